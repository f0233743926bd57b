"""Camshaft torque effect: the deck's valve train copied to every lobe of ``[camshaft]``.

Each lobe drives a copy of the deck's valve train, so its torque is the deck's cam torque curve
delayed by the lobe's angle of maximum lift (Williams 2013 App 7 steps 1-3; Yang 1992 App C.5
"angle to maximum lift"). The sum is the camshaft torque; its FFT gives the orders (Williams
§9.2); a second bank is the first advanced by half the V angle (Williams App 7 step 4); pendulum
dampers are sized with Williams ch 10 (eqs 10.57, 10.59, 10.64, 10.65).

Lobe forces for the bearings (Ball 1988 §6.3; Yang 1992 §3.3.1): the contact load ``load`` acts
on the lobe along the follower axis, the friction ``friction_force`` across it, opposing the
shaft rotation. For a pivoted follower the contact normal turns a little over the cycle; using
the fixed follower axis is the sources' simplification.
"""
from __future__ import annotations

import math

#: a pendulum swing above this [rad] leaves the small-angle theory of Williams ch 10
_LARGE_SWING = 0.5


def missing(deck) -> list[str]:
    return [] if deck.camshaft is not None else ["[camshaft] section (lobes)"]


def reason(deck, planned) -> str:
    torque = "W e + F r" if "CamTorque" in planned else "W e only (no friction)"
    return f"{len(deck.camshaft.lobes)} lobes given; lobe torque {torque}"


def lobe_torque(kin, load, cam_torque_product):
    """The single-lobe torque [N m] on the run grid: the power effect's W e + F r when planned,
    else the normal-load torque W e."""
    import numpy as np

    from camtrain.formulas import cam_torque

    if cam_torque_product is not None:
        return cam_torque_product.cam_torque
    return np.asarray(cam_torque(np.maximum(load, 0.0), kin.torque_arm_normal, 0.0, 0.0),
                      dtype=float)


def order_phases(harm, theta0: float):
    """Phases of T = sum A_n cos(n theta + phase_n) on a grid starting at theta0 (not 0)."""
    import numpy as np

    ph = harm.phase - harm.order * theta0
    return np.angle(np.exp(1j * ph))


def add_orders(res, torque, theta0: float, highest: int, prefix: str,
               what: str):
    """Order metrics ``<prefix>_n`` [N m] (angle = first maximum) and ``<prefix>_n_phase``."""
    import numpy as np

    from camtrain.camshaft import harmonic_orders

    harm = harmonic_orders(torque)
    phase = order_phases(harm, theta0)
    res.add_metric(f"{prefix}_0", harm.mean, "N*m", f"{what}: order 0, the mean torque")
    tiny = 1e-9 * max(float(np.max(harm.amplitude)), 1e-300)
    for n in range(1, min(highest, harm.order.size - 1) + 1):
        peak = -phase[n] / n  # cos(n theta + phase) is largest here
        where = math.remainder(peak, 2.0 * math.pi / n) if harm.amplitude[n] > tiny else None
        res.add_metric(f"{prefix}_{n}", harm.amplitude[n], "N*m",
                       f"{what}: order {n} amplitude (peak); angle = its first maximum", where)
        res.add_metric(f"{prefix}_{n}_phase", phase[n], "rad",
                       f"{what}: order {n} phase in A cos(n theta + phase)")
    return harm


def run(deck, inputs, res):
    import numpy as np

    from camtrain.camshaft import drive_power, lobe_force, second_bank, shift_curve
    from camtrain.camshaft.product import CamshaftLoads
    from camtrain.contact.products import CamTorque, ContactFriction
    from camtrain.formulas import cycle_mean
    from camtrain.loads import ContactLoad
    from camtrain.mechanisms import TrainKinematics

    cs = deck.camshaft
    kin = inputs[TrainKinematics].main
    contact = inputs[ContactLoad]
    theta = res["cam_angle"]
    omega = abs(deck.speed.omega)
    torque = inputs.get(CamTorque)
    single = lobe_torque(kin, contact.load, torque)
    if torque is None:
        res.warn("camshaft torque without friction (W e only): the power effect did not run")
    bank1 = [lobe for lobe in cs.lobes if lobe.bank == 1]
    curves = [shift_curve(single, lobe.max_lift_angle) for lobe in bank1]
    total = np.sum(curves, axis=0) if curves else np.zeros_like(theta)
    res.add_column("shaft_angle", theta, "rad",
                   "camshaft angle, the abscissa of the camshaft's columns from here on (torque, "
                   "drive power, bearings, shaft, lobes), on which each lobe's nose sits at its "
                   "camshaft.lobes max_lift_angle; the columns before it (lift to the guide "
                   "powers) are the train's, at its own lobe's cam_angle (nose at 0)")
    res.add_column("camshaft_torque", total, "N*m",
                   f"summed torque of the {len(bank1)} lobes on this shaft, at shaft_angle")
    power, mean_power = drive_power(total, omega)
    res.add_column("drive_power", power, "W", "camshaft drive power T omega")
    res.add_metric("drive_power_mean", mean_power, "W", "cycle-mean camshaft drive power")
    i = int(np.argmax(total))
    res.add_metric("camshaft_torque_peak", total[i], "N*m", "largest camshaft torque", theta[i])
    i = int(np.argmin(total))
    res.add_metric("camshaft_torque_min", total[i], "N*m", "smallest camshaft torque", theta[i])
    harm = add_orders(res, total, float(theta[0]), cs.orders, "order", "camshaft torque")

    if cs.v_angle is not None:
        bank2_lobes = [lobe for lobe in cs.lobes if lobe.bank == 2]
        if bank2_lobes:
            bank2 = np.sum([shift_curve(single, lobe.max_lift_angle - 0.5 * cs.v_angle)
                            for lobe in bank2_lobes], axis=0)
        else:  # the other bank is a copy of this one (Williams App 7 step 4)
            bank2 = second_bank(total, cs.v_angle)
        both = total + bank2
        res.add_column("camshaft_torque_bank_2", bank2, "N*m", "torque of the second bank")
        res.add_column("camshaft_torque_both", both, "N*m", "torque of both banks")
        res.add_metric("drive_power_both_mean", cycle_mean(both) * omega, "W",
                       "cycle-mean drive power of both banks")
        add_orders(res, both, float(theta[0]), cs.orders, "both_order", "both banks")

    if cs.damper is not None:
        _dampers(deck, res, total, harm, omega)

    # lobe forces on the shaft for the bearings effect (this shaft's lobes only)
    load = np.maximum(contact.load, 0.0)
    friction = inputs.get(ContactFriction)
    friction = np.zeros_like(load) if friction is None else friction.main.force
    turn = 1.0 if cs.rotation == "anticlockwise" else -1.0
    # friction torque on the shaft opposes its rotation; positive tangential is z x axis
    signed = -turn * friction * np.sign(np.where(kin.friction_arm == 0, 1.0, kin.friction_arm))
    forces = [lobe_force(shift_curve(load, lobe.max_lift_angle),
                         shift_curve(signed, lobe.max_lift_angle), lobe.follower_axis_angle)
              for lobe in bank1]
    return CamshaftLoads(torque=total, lobe_positions=tuple(lobe.position for lobe in bank1),
                         lobe_forces=tuple(forces), omega=turn * omega,
                         lobe_torques=tuple(curves))


def _dampers(deck, res, total, harm, omega) -> None:
    import numpy as np

    from camtrain.camshaft import damper_motion, optimum_damper, pendulum_effective_inertia

    d = deck.camshaft.damper
    orders = [int(n) for n in d.orders]
    top = harm.order.size - 1
    bad = [n for n in orders if n >= top]
    if bad:
        res.warn(f"damper orders {bad} are beyond the grid's resolution (< {top}); skipped")
        orders = [n for n in orders if n < top]
    if not orders:
        return
    big = []
    for n in orders:
        R = d.pivot_radius
        r = R / (n * n * (1.0 + d.tuning_margin))  # R/r a little above n^2 (eq. 10.59)
        lam, beta = damper_motion(harm.amplitude[n], d.count, n, omega, d.mass, R, r)
        ie = pendulum_effective_inertia(d.mass, R, r, n)
        res.add_metric(f"damper_order_{n}_length", r, "m",
                       f"effective pendulum length r for order {n} (Williams eq. 10.59)")
        res.add_metric(f"damper_order_{n}_inertia", ie, "kg*m^2",
                       f"effective inertia of one pendulum at order {n} (eq. 10.57)")
        res.add_metric(f"damper_order_{n}_shaft_amplitude", lam, "rad",
                       f"shaft angle fluctuation with the order-{n} dampers (eq. 10.64)")
        res.add_metric(f"damper_order_{n}_swing", beta, "rad",
                       f"pendulum swing at order {n} (eq. 10.65)")
        if beta > _LARGE_SWING:
            big.append(n)
    if big:
        res.warn(f"pendulum swing above {_LARGE_SWING} rad at orders {big}: small-angle damper "
                 "theory doubtful; add mass or pendulums")
    damper, damped = optimum_damper(total, orders)
    res.add_column("camshaft_torque_damped", damped, "N*m",
                   f"camshaft torque with orders {orders} removed by the dampers")
    res.add_metric("camshaft_torque_range", float(np.ptp(total)), "N*m",
                   "peak-to-peak camshaft torque without dampers")
    res.add_metric("camshaft_torque_damped_range", float(np.ptp(damped)), "N*m",
                   "peak-to-peak camshaft torque with the dampers (Williams Tables 9.9, 9.10)")
