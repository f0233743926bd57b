"""Loss of contact (valve bounce / follower jump) of a rigid valve train.

With friction coefficients held fixed, the contact load of a rigid train is, at every cam angle,
W(omega) = a + omega^2 b with a = G0/D and b = G2/D (see :func:`camtrain.loads.forces.load_parts`,
D = arm_normal + mu arm_friction). The cam holds the train while W > 0 (Ball 1988 §4.2.3.2:
W <= 0 means the cam no longer controls the valve). Where a > 0 and b < 0 contact is lost above
omega* = sqrt(-a/b); the bounce speed is the smallest omega* over the angles in contact.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.loads.forces import contact_mask, load_parts

__all__ = ["Bounce", "loss_of_contact", "bounce_speed", "bounce_speeds"]


@dataclass(frozen=True)
class Bounce:
    """Camshaft speed [rad/s] at which contact is first lost and the angle [rad] where."""

    omega: float        # inf when the spring always holds the train
    angle: float | None


def loss_of_contact(load, in_contact) -> np.ndarray:
    """Boolean per angle: the cam should drive the valve but the load is W <= 0."""
    return np.asarray(in_contact, dtype=bool) & (np.asarray(load, dtype=float) <= 0.0)


def bounce_speeds(kin, mu=0.0, *, rate, preload_compression, valve_mass, body_inertia=None,
                  progressive: tuple[float, ...] = (), clearance: float = 0.0,
                  parts=None) -> np.ndarray:
    """Per angle, the camshaft speed [rad/s] above which the load there is W <= 0, sqrt(-a/b);
    inf where the spring holds the train at any speed. Shape-agnostic: the spring and mass data
    may be arrays that broadcast against the kinematics (a batch of sweep cases). ``parts``:
    (G0, G2) of :func:`~camtrain.loads.forces.load_parts` when already formed."""
    g0, g2 = parts if parts is not None else load_parts(
        kin, rate=rate, preload_compression=preload_compression, valve_mass=valve_mass,
        body_inertia=body_inertia, progressive=progressive)
    denom = kin.arm_normal + np.asarray(mu, dtype=float) * kin.arm_friction
    ok = contact_mask(kin.valve_lift, clearance) & (denom > 0.0)
    safe = np.where(ok, denom, 1.0)
    a, b = g0 / safe, g2 / safe
    limited = ok & (a > 0.0) & (b < 0.0)
    shape = limited.shape
    if a.shape != shape or b.shape != shape:   # a batch's parameters: (cases, angles)
        shape = np.broadcast_shapes(a.shape, b.shape, shape)
        a, b = np.broadcast_to(a, shape), np.broadcast_to(b, shape)
        limited = np.broadcast_to(limited, shape)
    speeds = np.empty(shape)
    speeds.fill(np.inf)
    speeds[limited] = np.sqrt(a[limited] / -b[limited])
    return speeds


def bounce_speed(kin, mu=0.0, *, rate: float, preload_compression: float, valve_mass: float,
                 body_inertia=None, progressive: tuple[float, ...] = (),
                 clearance: float = 0.0, parts=None) -> Bounce:
    """Closed-form lowest camshaft speed of loss of contact, min over angles of sqrt(-a/b).

    Angles already without load at zero speed (a <= 0) are excluded; they are a spring problem,
    not a speed limit. ``mu`` (fixed) enters the denominator only for followers with a friction arm.
    ``parts``: (G0, G2) of :func:`~camtrain.loads.forces.load_parts` when already formed.
    """
    speeds = bounce_speeds(kin, mu, rate=rate, preload_compression=preload_compression,
                           valve_mass=valve_mass, body_inertia=body_inertia,
                           progressive=progressive, clearance=clearance, parts=parts)
    i = int(np.argmin(speeds))
    if not np.isfinite(speeds.flat[i]):
        return Bounce(np.inf, None)
    return Bounce(float(speeds.flat[i]), float(kin.theta[i]))
