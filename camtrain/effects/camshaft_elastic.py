"""Elastic camshaft effect: the camshaft's bending and torsion under its lobe and drive loads.

The shaft of ``[camshaft.flexibility]`` (Teodorescu et al. 2005 §2.6; stations at the bearings,
lobes and drive, Euler-Bernoulli bending in two planes on bearing springs, torsion from the drive:
:mod:`camtrain.camshaft.flexible`) answers the lobe forces and torques of the camshaft effect and
the drive's hub load with its periodic response, order by order
(:mod:`camtrain.camshaft.flexible_response`). The bearing loads it gives replace the simply
supported bays of the bearings effect; the named splits ``determinate`` and ``equal_share`` are
its limits. The loads are those of the trains as the plan computed them (rigid-train or dynamic):
the shaft's deflection does not act back on the trains here.
"""
from __future__ import annotations

import math

#: a load order within this fraction of a natural frequency is reported as near resonance
_NEAR_RESONANCE = 0.1


def missing(deck) -> list[str]:
    cs = deck.camshaft
    if cs is None or cs.flexibility is None:
        return ["[camshaft.flexibility] section"]
    return [] if cs.bearings else ["[[camshaft.bearings]]"]


def reason(deck, planned) -> str:
    cs = deck.camshaft
    f = cs.flexibility
    support = ("rigid supports" if f.bearing_stiffness is None
               else f"bearing supports {f.bearing_stiffness * 1e-3:g} N/mm")
    drive = ("drive held at the mean speed" if f.drive_stiffness is None
             else f"drive spring {f.drive_stiffness:g} N·m/rad")
    return (f"[camshaft.flexibility] given: {f.split} bearing split, {f.response} shaft on "
            f"{len(cs.bearings)} bearings, {support}, {drive}, {f.nodes_per_span} extra stations "
            "per span")


def run(deck, inputs, res):
    import numpy as np

    from camtrain.camshaft import harmonic_orders, shaft_forces
    from camtrain.camshaft.flexible import ShaftSection, beam_shaft, stations, torsion_shaft
    from camtrain.camshaft.flexible_response import (
        bearing_split,
        bending_response,
        drive_acceleration,
        torsion_response,
    )
    from camtrain.camshaft.product import CamshaftLoads, ElasticCamshaft

    cs = deck.camshaft
    f = cs.flexibility
    loads = inputs[CamshaftLoads]
    omega = abs(loads.omega)
    theta = res["cam_angle"]
    drive = None
    if cs.drive is not None:
        drive = (cs.drive.position, cs.drive.radius, cs.drive.hub_load_angle, cs.drive.preload)
    else:
        res.warn("no [camshaft.drive]: the drive hub load is left out of the elastic shaft and "
                 "its torsion is driven at the first bearing")
    positions, fx, fy = shaft_forces(loads.lobe_positions, loads.lobe_forces, loads.torque, drive)
    drive_position = cs.drive.position if cs.drive is not None else cs.bearings[0].position
    bearing_positions = [b.position for b in cs.bearings]
    st = stations(bearing_positions, positions + [drive_position], f.nodes_per_span)
    n_lobes = len(loads.lobe_positions)
    lobe_nodes = st.force_nodes[:n_lobes]
    drive_node = int(st.force_nodes[-1])
    section = ShaftSection.hollow(f.diameter, f.bore, f.modulus, f.shear_modulus, f.density)
    masses = np.zeros(st.positions.size)
    np.add.at(masses, lobe_nodes, f.lobe_mass)
    stiffness = math.inf if f.bearing_stiffness is None else f.bearing_stiffness
    beam = beam_shaft(st, section, stiffness, f.bearing_damping, f.damping_ratio, masses)

    if f.split == "elastic":
        # the force stations of the shaft model include the drive station (no extra force)
        bend = bending_response(beam, np.vstack([fx, np.zeros_like(theta)]),
                                np.vstack([fy, np.zeros_like(theta)]), omega,
                                quasi_static=(f.response == "quasi_static"))
        dx, dy = bend.deflection_x[lobe_nodes], bend.deflection_y[lobe_nodes]
    else:
        bend = bearing_split(f.split, bearing_positions, positions, fx, fy, cs.overhang)
        # the limits are static splits; the deflection of the elastic shaft under the same loads
        shape = bending_response(beam, np.vstack([fx, np.zeros_like(theta)]),
                                 np.vstack([fy, np.zeros_like(theta)]), omega,
                                 quasi_static=(f.response == "quasi_static"))
        dx, dy = shape.deflection_x[lobe_nodes], shape.deflection_y[lobe_nodes]

    inertias = np.zeros(st.positions.size)
    np.add.at(inertias, lobe_nodes, f.lobe_inertia)
    inertias[drive_node] += f.drive_inertia
    drive_stiffness = math.inf if f.drive_stiffness is None else f.drive_stiffness
    torsion = torsion_shaft(st, section, drive_node, inertias, f.damping_ratio, drive_stiffness)
    torques = np.zeros((len(positions) + 1, theta.size))
    if loads.lobe_torques:  # a lobe's resisting torque loads the shaft against the rotation
        torques[:n_lobes] = -np.array(loads.lobe_torques)
    accel = None
    if f.speed_amplitude > 0:
        accel = drive_acceleration(theta - theta[0], omega, f.speed_amplitude, f.speed_order)
    twist_nodes = torsion_response(torsion, torques, omega, drive_accel=accel)
    twist = twist_nodes[lobe_nodes]

    _outputs(res, cs, theta, bend.bearing_x, bend.bearing_y, dx, dy, twist, harmonic_orders)
    _resonance(res, beam, torsion, omega, cs.orders)
    return ElasticCamshaft(bend.bearing_x, bend.bearing_y, dx, dy, twist, f.split)


def _outputs(res, cs, theta, bx, by, dx, dy, twist, harmonic_orders) -> None:
    import numpy as np

    for i in range(bx.shape[0]):
        comp, what = f"bearing_{i + 1}", f"bearing {i + 1}"
        res.add_column("reaction_x", bx[i], "N", f"{what}: load from the shaft, x",
                       component=comp)
        res.add_column("reaction_y", by[i], "N", f"{what}: load from the shaft, y",
                       component=comp)
        mag = np.hypot(bx[i], by[i])
        j = int(np.argmax(mag))
        res.add_metric("reaction_max", mag[j], "N", f"{what}: largest load from the shaft",
                       theta[j], component=comp)
        hx, hy = harmonic_orders(bx[i]), harmonic_orders(by[i])
        amplitude = np.hypot(hx.amplitude, hy.amplitude)
        for n in range(1, min(cs.orders, amplitude.size - 1) + 1):
            res.add_metric(f"reaction_order_{n}", amplitude[n], "N",
                           f"{what}: order {n} amplitude of the load vector", component=comp)
    for i in range(dx.shape[0]):
        comp, what = f"lobe_{i + 1}", f"lobe {i + 1}"
        res.add_column("deflection_x", dx[i], "m", f"{what}: shaft deflection, x",
                       component=comp)
        res.add_column("deflection_y", dy[i], "m", f"{what}: shaft deflection, y",
                       component=comp)
        res.add_column("twist", twist[i], "rad",
                       f"{what}: twist against the drive (positive with the rotation)",
                       component=comp)
    defl = np.hypot(dx, dy)
    i, j = np.unravel_index(int(np.argmax(defl)), defl.shape)
    res.add_metric("shaft_deflection_max", defl[i, j], "m",
                   f"largest shaft deflection at a lobe (lobe {i + 1})", theta[j])
    i, j = np.unravel_index(int(np.argmax(np.abs(twist))), twist.shape)
    res.add_metric("shaft_twist_max", abs(twist[i, j]), "rad",
                   f"largest twist of a lobe against the drive (lobe {i + 1})", theta[j])


def _resonance(res, beam, torsion, omega, orders) -> None:
    """First natural frequencies as metrics; a warning when a load order sits near one."""
    bending = float(beam.natural_frequencies(1)[0])
    twisting = float(torsion.natural_frequencies()[0])
    res.add_metric("shaft_bending_frequency_1", bending / (2.0 * math.pi), "Hz",
                   "first bending natural frequency of the camshaft")
    res.add_metric("shaft_torsion_frequency_1", twisting / (2.0 * math.pi), "Hz",
                   "first torsional natural frequency of the camshaft")
    for name, w in (("bending", bending), ("torsional", twisting)):
        near = [k for k in range(1, orders + 1)
                if omega > 0 and abs(k * omega - w) < _NEAR_RESONANCE * w]
        if near:
            res.warn(f"camshaft: load order(s) {near} within {_NEAR_RESONANCE:.0%} of the first "
                     f"{name} natural frequency ({w / (2 * math.pi):.0f} Hz): resonant shaft")
