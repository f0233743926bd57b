"""The valve pad and the pivot of a pivoted follower (finger follower or rocker), on arrays.

Besides its cam contact, a finger follower (end pivot on a ball socket, the lash adjuster) or a
rocker (centre pivot on a shaft) has two more contacts: its valve pad, a pad of radius r_p
centred at Dyson's V (Ball 1988 App A) on the flat valve tip, and its pivot. Geometry in the
fixed frame of :mod:`camtrain.mechanisms.pivot_geometry` (cam centre O at the origin, pivot U at
(D, 0), counterclockwise angles), with the valve opening along d = (cos kappa, -sin kappa) and
t = z x d = (sin kappa, cos kappa) across the valve tip:

* pad contact point: C = V + r_p d (the pad touches the flat tip, normal to the valve axis);
* sliding speed of the arm over the valve tip, along t (the tip does not move across itself):
  v_pad = gamma_dot (r_p - B cos(gamma + kappa)) (:func:`pad_sliding_speed`; derivation in
  docs/mechanism_roller.md: the arm's material point at C moves with gamma_dot z x (C - U));
  no sliding where the contact point lies on the perpendicular from U to the valve axis;
* pad load: the valve force along d from the arm's moment balance about its pivot (the same
  virtual-work balance as the loads, :mod:`camtrain.mechanisms.base`), cam friction included,
  pad and pivot friction left out of it (first order: their moments are small against the
  load's; stated where used);
* pivot reaction: the force balance of the arm, R = -(W n - F_pad d), the arm's own linear
  inertia force and the cam-contact friction force neglected (a roller's traction is small);
* pivot friction torque: mu_p r_p' |R| (ball socket of radius r_p' or rocker shaft of radius
  r_p': a Coulomb coefficient times the reaction times the radius, as a plain pivot), its power
  that torque times |gamma_dot|.

Signs: ``gamma`` and ``q`` are even in the cam angle, ``gamma_d1`` and ``q_d1`` odd, and every
Kinematics of camtrain has d/dt = omega d/dtheta in the user's cam angle (the rotation rule of
:func:`camtrain.mechanisms.base.analyse`), so these speeds hold for both cam rotations.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.mechanisms.base import ANTICLOCKWISE, Kinematics
from camtrain.mechanisms.pivot_geometry import PivotGeometry


@dataclass(frozen=True)
class ArmContacts:
    """Valve pad and pivot of a pivoted follower over the cycle (the arm_contacts effect's
    product; arrays on the cam-angle grid, SI units).

    pad_sliding_speed: the arm's speed over the valve tip at the pad contact, along t [m/s]
    pad_travel: pad contact position across the valve tip from its base-circle position [m]
    pad_load: normal load at the valve pad [N]
    pad_max_pressure: Hertz maximum pressure at the pad [Pa]
    pad_half_width: Hertz half-width (cylindrical pad) or semi-minor axis (spherical) [m]
    pad_friction_power: mu_pad x pad load x |pad sliding speed| [W]
    pivot_reaction: magnitude of the pivot's force on the arm [N]
    pivot_friction_torque: mu_pivot x pivot radius x reaction [N m]
    pivot_friction_power: torque x |follower angular speed| [W]
    """

    pad_sliding_speed: np.ndarray
    pad_travel: np.ndarray
    pad_load: np.ndarray
    pad_max_pressure: np.ndarray
    pad_half_width: np.ndarray
    pad_friction_power: np.ndarray
    pivot_reaction: np.ndarray
    pivot_friction_torque: np.ndarray
    pivot_friction_power: np.ndarray


# ---------------------------------------------------------------- geometry
def arm_points(k: Kinematics, g: PivotGeometry) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Pivot U, roller (face) centre Q and pad centre V in the fixed frame at every angle of
    ``k`` (Ball 1988 App A: Q = U + A e(pi + lambda + gamma), V = U + B e(pi + gamma))."""
    gamma = k.gamma
    ones = np.ones_like(gamma)
    cq, cv = np.pi + g.lam + gamma, np.pi + gamma
    return {"U": (g.D * ones, 0.0 * ones),
            "Q": (g.D + g.A * np.cos(cq), g.A * np.sin(cq)),
            "V": (g.D + g.B * np.cos(cv), g.B * np.sin(cv))}


def cam_to_fixed(k: Kinematics, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A point of the cam frame in the fixed frame: turned by -theta for a clockwise cam (the
    kernel's cam frame has U at D e(theta)), +theta for an anticlockwise one (its analysis is
    the clockwise one at -theta)."""
    a = k.theta if k.rotation == ANTICLOCKWISE else -k.theta
    c, s = np.cos(a), np.sin(a)
    return c * x - s * y, s * x + c * y


def fixed_to_cam(k: Kinematics, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Inverse of :func:`cam_to_fixed`."""
    a = -k.theta if k.rotation == ANTICLOCKWISE else k.theta
    c, s = np.cos(a), np.sin(a)
    return c * x - s * y, s * x + c * y


def valve_directions(g: PivotGeometry) -> tuple[np.ndarray, np.ndarray]:
    """d, the valve's opening direction, and t = z x d, across the valve tip (fixed frame)."""
    return (np.array([np.cos(g.kappa), -np.sin(g.kappa)]),
            np.array([np.sin(g.kappa), np.cos(g.kappa)]))


def pad_sliding_speed(gamma_rate, gamma, B, kappa, pad_radius):
    """v_pad = gamma_dot (r_p - B cos(gamma + kappa)) [m/s]: the arm's material point at the pad
    contact C = V + r_p d moves with gamma_dot z x (C - U); its component along t is
    gamma_dot ((z x (V - U)).t + r_p (z x d).t) = gamma_dot (-B cos(gamma + kappa) + r_p)."""
    return gamma_rate * (pad_radius - B * np.cos(gamma + kappa))


def pad_travel(gamma, gamma_b, B, kappa):
    """Position of the pad contact across the valve tip, along t, from its base-circle
    position [m]: C.t = V.t = D sin(kappa) - B sin(gamma + kappa), so
    (C - C_B).t = -B (sin(gamma + kappa) - sin(gamma_B + kappa))."""
    return -B * (np.sin(gamma + kappa) - np.sin(gamma_b + kappa))


# ---------------------------------------------------------------- forces
def pad_load(k: Kinematics, load, mu, follower_inertia: float):
    """Valve force at the pad [N] from the arm's moment balance about its pivot (the virtual
    work of :mod:`camtrain.mechanisms.base`): F_pad arm_valve = W (arm_normal + mu
    arm_friction) - omega^2 J q'' with J the arm's moment of inertia about the pivot."""
    mu = 0.0 if mu is None else mu
    moment = load * (k.arm_normal + mu * k.arm_friction) \
        - k.omega ** 2 * follower_inertia * k.q_d2
    return moment / k.arm_valve


def pivot_reaction(k: Kinematics, g: PivotGeometry, load, pad_force):
    """|R| of the pivot on the arm [N], R = -(W n - F_pad d): n the cam contact normal into the
    follower (from the contact point to the roller centre), d the valve's opening direction."""
    pts = arm_points(k, g)
    qx, qy = pts["Q"]
    px, py = cam_to_fixed(k, k.contact_x, k.contact_y)
    nx, ny = (qx - px) / g.follower_radius, (qy - py) / g.follower_radius
    d, _ = valve_directions(g)
    rx = -(load * nx - pad_force * d[0])
    ry = -(load * ny - pad_force * d[1])
    return np.hypot(rx, ry)


def pad_hertz(pad_force, pad_radius, reduced_modulus, *, shape: str, width: float | None):
    """Hertz maximum pressure and half-width of the pad on the flat valve tip: a cylindrical
    pad of ``width`` (line contact) or a spherical pad (circular point contact); no load, no
    pressure (Johnson 1985 §4.2-4.3 through camtrain.formulas.hertz)."""
    from camtrain.formulas.hertz import hertz_line, hertz_point

    w = np.maximum(pad_force, 0.0)
    if shape == "cylindrical":
        h = hertz_line(w, pad_radius, reduced_modulus, width)
        return np.asarray(h.max_pressure, float), np.asarray(h.half_width, float)
    h = hertz_point(w, pad_radius, pad_radius, reduced_modulus)
    return np.asarray(h.max_pressure, float), np.asarray(h.a_x, float)


def arm_contacts(k: Kinematics, g: PivotGeometry, load, *, mu=None, follower_inertia=0.0,
                 pad_radius: float, pad_shape: str = "cylindrical",
                 pad_width: float | None = None, pad_friction: float = 0.0,
                 pivot_radius: float = 0.0, pivot_friction: float = 0.0,
                 reduced_modulus: float, pivot_bearing=None,
                 pivot_film: str = "short") -> ArmContacts:
    """Valve pad and pivot of pivoted follower ``k`` (geometry ``g``) under cam load ``load``
    [N] (friction coefficient ``mu`` of the cam contact as the load was solved, or None).
    ``pivot_bearing`` (a :class:`camtrain.bearings.JournalBearing`): the rocker shaft as a
    plain journal bearing instead of the Coulomb pivot (:func:`journal_pivot_torque`)."""
    rate = k.omega * k.gamma_d1
    slide = pad_sliding_speed(rate, k.gamma, g.B, g.kappa, pad_radius)
    # the pad only pushes: a negative balance means the arm would leave the valve tip there
    force = np.where(load > 0.0, np.maximum(pad_load(k, load, mu, follower_inertia), 0.0), 0.0)
    p_max, half = pad_hertz(force, pad_radius, reduced_modulus, shape=pad_shape, width=pad_width)
    reaction = np.where(load > 0.0, pivot_reaction(k, g, np.maximum(load, 0.0), force), 0.0)
    if pivot_bearing is None:
        torque = pivot_friction * pivot_radius * reaction
    else:
        torque = journal_pivot_torque(pivot_bearing, rate, reaction, pivot_film)
    return ArmContacts(
        pad_sliding_speed=slide, pad_travel=pad_travel(k.gamma, g.gamma_b, g.B, g.kappa),
        pad_load=force, pad_max_pressure=p_max, pad_half_width=half,
        pad_friction_power=pad_friction * force * np.abs(slide), pivot_reaction=reaction,
        pivot_friction_torque=torque, pivot_friction_power=torque * np.abs(rate))


def journal_pivot_torque(bearing, rate, reaction, film: str = "short") -> np.ndarray:
    """Friction torque [N m] (>= 0) of a rocker shaft as a plain journal bearing: the bore
    turns at the arm's angular speed ``rate`` [rad/s] about the fixed shaft under the pivot
    reaction [N]; the steady eccentricity of the Ocvirk short bearing (``film = "short"``) or
    of the finite-length Reynolds film (``"finite"``) at the mean speed rate/2, and the
    Couette shear power over the complete film (Martin 1985, Yang 1992 eq. 1.22), torque =
    power / rate (the plain bushing of :func:`camtrain.roller.pin.bushing_torque`, the roller's
    pin). Quasi-steady: the shaft's squeeze film as the arm reverses is not modelled, so where
    the arm stands (rate 0) the torque is 0."""
    from camtrain.roller.pin import bushing_torque

    return np.abs(bushing_torque(bearing, np.asarray(rate, dtype=float),
                                 np.maximum(np.asarray(reaction, dtype=float), 0.0), film))
