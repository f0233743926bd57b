"""Spring, valve-side and cam contact forces of a rigid valve train (D'Alembert balance).

All functions are vectorised over the cam-angle grid of a :class:`~camtrain.mechanisms.Kinematics`
and use SI units. The load balance is the generalised virtual-work form documented in
``camtrain.mechanisms.base``::

    W (arm_normal + mu arm_friction) = F_valve arm_valve + omega^2 sum_b J_b inertia[b]

which reduces to Ball (1988) eq. B.4 for the flat follower (W = k(l_v + delta) + M omega^2 l_v''),
to eq. B.3 for the domed follower and to eqs. C.9 / C.18 for pivoted followers (signs as in
the sign-safe form of the reference extraction, §2.3).
"""
from __future__ import annotations

from collections.abc import Mapping

import numpy as np

__all__ = ["spring_force", "valve_force", "load_parts", "contact_load", "contact_mask"]


def spring_force(valve_lift, rate: float, preload_compression: float,
                 progressive: tuple[float, ...] = ()):
    """Valve spring force [N] at valve lift ``valve_lift`` [m].

    Linear spring (Ball 1988 eq. C.7, S = k (l_v + delta)) plus the optional progressive terms
    c2 x^2 + c3 x^3 with x = l_v + delta the total compression (``progressive`` = (c2[, c3]) in
    N/m^2 and N/m^3).
    """
    x = np.asarray(valve_lift, dtype=float) + preload_compression
    force = rate * x
    for power, c in enumerate(progressive, start=2):
        if c:   # a linear spring's zero terms add nothing
            force = force + c * x ** power
    return force


def valve_force(valve_lift, valve_d2, omega: float, *, rate: float, preload_compression: float,
                valve_mass: float, progressive: tuple[float, ...] = ()):
    """Valve-side force F_valve = S + M omega^2 l_v'' [N] along the valve axis.

    M is the equivalent reciprocating mass at the valve (valve, retainer, collets, a third of the
    spring; Ball 1988 Table 3.1 and eq. C.8); gravity and guide friction are neglected.
    """
    return (spring_force(valve_lift, rate, preload_compression, progressive)
            + valve_mass * omega ** 2 * np.asarray(valve_d2, dtype=float))


def load_parts(kin, *, rate: float, preload_compression: float, valve_mass: float,
               body_inertia: Mapping[str, float] | None = None,
               progressive: tuple[float, ...] = ()):
    """Split the generalised driving force into the speed-independent and omega^2 parts.

    Returns (G0, G2) [N or N m, per the generalised coordinate] such that the right-hand side of
    the load balance is G0 + omega^2 G2: G0 = S arm_valve, G2 = (M l_v'' arm_valve +
    sum_b J_b inertia[b]). Keys of ``kin.inertia`` missing from ``body_inertia`` count as J = 0.
    """
    body_inertia = dict(body_inertia or {})
    g0 = spring_force(kin.valve_lift, rate, preload_compression, progressive) * kin.arm_valve
    g2 = valve_mass * kin.valve_d2 * kin.arm_valve
    for name, coeff in kin.inertia.items():
        j = float(body_inertia.get(name, 0.0))
        if j:
            g2 = g2 + j * coeff
    return g0, g2


#: Lift below which the follower counts as on the base circle [m]: 0.05 µm, half the finest
#: printed digit of the sources' lift tables (0.1 µm). A smoothed lift table is not exactly zero
#: on the base circle; ripples below this are data noise, not lift.
BASE_CIRCLE_TOLERANCE = 5e-8


def contact_mask(valve_lift, clearance: float = 0.0):
    """True where the cam drives the valve: valve lift above the valve clearance.

    With a clearance c (lash) the cam first takes up c; until then the valve sits on its seat and
    the cam/follower load is zero (Ball 1988 §8.3.1.2, "clearance on the base circle"; the
    reference extraction §4.5 shows Ball's printed power losses need this). With c = 0 the base
    circle (l_v within BASE_CIRCLE_TOLERANCE of 0) is still unloaded: the seat carries the
    spring preload.
    """
    return np.asarray(valve_lift, dtype=float) > max(float(clearance), BASE_CIRCLE_TOLERANCE)


def contact_load(kin, mu=0.0, *, rate: float, preload_compression: float, valve_mass: float,
                 body_inertia: Mapping[str, float] | None = None,
                 progressive: tuple[float, ...] = (), clearance: float = 0.0,
                 base_load: float = 0.0, omega: float | None = None, parts=None):
    """Normal cam/follower load W [N] at every cam angle (rigid train, no loss of contact).

    Args:
        kin: Kinematics of the mechanism.
        mu: friction coefficient (scalar or per angle) used in the friction arm (pivoted
            followers; flat followers have arm_friction = 0).
        rate, preload_compression, valve_mass, progressive: spring and mass data (SI).
        body_inertia: J_b for the keys of ``kin.inertia`` (kg or kg m^2).
        clearance: valve clearance [m]; W = ``base_load`` where l_v <= clearance.
        base_load: load while the valve is seated (a hydraulic lash adjuster's load) [N].
        omega: camshaft speed [rad/s]; default ``kin.omega``.
        parts: (G0, G2) of :func:`load_parts` for these data when already formed (the load
            iteration forms them once for all its passes).

    Returns W, which may be negative where the spring cannot hold the train on the cam (loss of
    contact; see :mod:`camtrain.loads.bounce`). Ball (1988) eqs. B.1-B.4, C.9, C.18.
    """
    w = kin.omega if omega is None else float(omega)
    g0, g2 = parts if parts is not None else load_parts(
        kin, rate=rate, preload_compression=preload_compression, valve_mass=valve_mass,
        body_inertia=body_inertia, progressive=progressive)
    denom = kin.arm_normal + np.asarray(mu, dtype=float) * kin.arm_friction
    inside = contact_mask(kin.valve_lift, clearance)
    safe = np.where(inside & (denom != 0.0), denom, 1.0)
    load = np.where(inside, (g0 + w * w * g2) / safe, base_load)
    return load
