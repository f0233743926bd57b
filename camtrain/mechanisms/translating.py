"""Translating followers: flat-faced (bucket), domed radial or offset, and the tapered cam.

Geometry (fixed frame): cam centre O at the origin, follower axis parallel to +y at x = e (the
offset, positive towards the side the top of a clockwise cam moves to). For a domed face the
centre of curvature Q sits on the axis at height d + l, d = sqrt((r_B + r_f)^2 - e^2).
``lift`` is the follower (valve) lift for direct-acting trains and the tappet lift when a push-rod
train drives the valve.
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.errors import field_error
from camtrain.identity_cache import by_identity
from camtrain.lift.base import LiftCurve
from camtrain.mechanisms._contact import contact_arms
from camtrain.mechanisms.base import Kinematics, analyse, check_speed, equivalent_radius, kept
from camtrain.mechanisms.checks import check_curved_follower, check_face, check_flat_follower_convex

FOLLOWER_SHAPES = ("spherical", "cylindrical")


# ---------------------------------------------------------------- published formulas
def flat_cam_radius(lift, d2, base_radius):
    """Cam radius of curvature under a flat follower, r_c = l'' + l + r_B (Ball 1988 eq. 3.6,
    Williams 2013 eq. 4.14)."""
    return d2 + lift + base_radius


def flat_surface_velocities(lift, d2, base_radius, omega):
    """V_c = omega (l'' + l + r_B), V_f = omega l'' (Ball 1988 eqs 3.4, 3.5)."""
    return omega * (d2 + lift + base_radius), omega * d2


def dyson_naylor_domed(Z, Z1, Z2, follower_radius, omega):
    """Radial domed follower in terms of Z = l + r_B + r_f (Ball 1988 eqs 3.1-3.3 as corrected
    in the reference extraction; Yang 1992 eqs 3.1-3.3; after Dyson & Naylor 1960).

    Returns r_c, R, V_c, V_f. R uses the form r_f - r_f^2 (Z^2+2Z'^2-ZZ'')/(Z^2+Z'^2)^(3/2), which
    stays finite on a flat spot of the cam where r_c is infinite.
    """
    rf = follower_radius
    s2 = Z * Z + Z1 * Z1
    k2 = Z * Z + 2.0 * Z1 * Z1 - Z * Z2
    with np.errstate(divide="ignore", invalid="ignore"):
        rc = np.where(k2 == 0.0, np.inf, s2 ** 1.5 / np.where(k2 == 0.0, 1.0, k2)) - rf
    R = rf - rf * rf * k2 / s2 ** 1.5
    vc = omega * (np.sqrt(s2) - rf * k2 / s2)
    vf = omega * rf * (Z * Z2 - Z1 * Z1) / s2
    return rc, R, vc, vf


def offset_base_height(base_radius, follower_radius, offset):
    """Height of the follower's centre of curvature on the base circle,
    d = sqrt((r_B + r_f)^2 - e^2) (Williams 2013 eq. 6.1; minus sign as corrected)."""
    return np.sqrt((base_radius + follower_radius) ** 2 - offset ** 2)


def offset_pressure_angle(s, s1, d, offset):
    """tan(beta) = (s' + e) / (s + d) (Williams 2013 eq. 6.9; eq. 5.4 for e = 0)."""
    return np.arctan2(s1 + offset, s + d)


def offset_pressure_angle_rate(s, s1, s2, d, offset):
    """dbeta/dtheta = [(d+s) s'' - (s'+e) s'] / [(d+s)^2 sec^2 beta] (Williams 2013 eq. 6.12)."""
    return ((d + s) * s2 - (s1 + offset) * s1) / ((d + s) ** 2 + (s1 + offset) ** 2)


def offset_cam_radius(s, beta, beta1, d, follower_radius):
    """rho = (d + s) / [cos(beta) (1 - beta')] - r_f: closed form of Williams 2013 eqs 6.17/6.18
    (0/0-free; infinite on a flat spot where beta' = 1)."""
    den = np.cos(beta) * (1.0 - beta1)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(den == 0.0, np.inf, (d + s) / np.where(den == 0.0, 1.0, den)) \
            - follower_radius


def offset_surface_velocities(s, beta, beta1, d, follower_radius, omega):
    """V_c = omega rho (1 - beta'), V_f = omega r_f beta' (Williams 2013 eqs 6.19-6.22 with the
    sign of V_c corrected; the printed forms return -V_s as the "entrainment")."""
    vc = omega * ((d + s) / np.cos(beta) - follower_radius * (1.0 - beta1))
    return vc, omega * follower_radius * beta1


def yang_principal_radii(cam_radius, follower_radius):
    """Tapered cam on a spherical follower: R_x from 1/R_x = 1/r_c + 1/r_f along the rolling
    direction, R_y = r_f across it (the taper is straight) (Yang 1992 eq. 3.16 and §3.2.3)."""
    return equivalent_radius(cam_radius, follower_radius), np.full_like(cam_radius,
                                                                          follower_radius)


def yang_load_factor(beta, taper_angle):
    """F_v / W = [1 + tan^2(psi_c - theta_c) + tan^2(gamma)]^(-1/2) (Yang 1992 eqs 3.9-3.11)."""
    return 1.0 / np.sqrt(1.0 + np.tan(beta) ** 2 + np.tan(taper_angle) ** 2)


@by_identity
def _cached_unit_circle(theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    c, s = np.cos(theta), np.sin(theta)
    c.flags.writeable = s.flags.writeable = False
    return c, s


def unit_circle(theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """cos(theta), sin(theta); formed once per read-only grid (the run's cached angle grid)."""
    if isinstance(theta, np.ndarray) and not theta.flags.writeable:
        return _cached_unit_circle(theta)
    return np.cos(theta), np.sin(theta)


def _infinite(follower_radius) -> bool:
    """A flat face: an infinite follower radius (one radius, or one per sweep case)."""
    if type(follower_radius) is float:
        return math.isinf(follower_radius)
    return bool(np.all(np.isinf(follower_radius)))


# ---------------------------------------------------------------- kernel shared with push rods
def translating_contact(theta, s, s1, s2, *, base_radius, follower_radius, offset, omega,
                        shape="spherical", taper_angle=None):
    """Contact fields of a translating follower driven with lift s(theta) (clockwise cam).

    ``follower_radius`` = inf selects the flat face; ``taper_angle`` (rad, or None) selects Yang's
    tapered-cam model for a radial spherical follower. Returns a dict of Kinematics fields.
    """
    c, sn = unit_circle(theta)
    ax, ay, bx, by = -sn, c, c, sn       # follower axis and offset directions in the cam frame
    rb, e = base_radius, offset
    if _infinite(follower_radius):
        rc = flat_cam_radius(s, s2, rb)
        vc, vf = flat_surface_velocities(s, s2, rb, omega)
        h = rb + s
        px, py = h * ax - s1 * bx, h * ay - s1 * by
        nx, ny = ax, ay
        ecc = s1 + e
        R = rc.copy()
        # the flat face's radius and the transverse radius: one read-only array of inf serves
        # both (the Kinematics freezes its fields)
        ry = np.empty_like(s)
        ry.fill(np.inf)
        rx, rf_arr = R, ry
        load_factor = None   # the whole normal load acts in the plane
    else:
        rf = follower_radius
        d = offset_base_height(rb, rf, e)
        if taper_angle is not None:
            beta = np.arctan2(s1, d + s)       # Yang's tan(psi_c - theta_c) = Z'/Z
            rc, R, vc, vf = dyson_naylor_domed(d + s, s1, s2, rf, omega)
            rx, ry = yang_principal_radii(rc, rf)
            R = rx
            load_factor = yang_load_factor(beta, taper_angle) / np.cos(beta)
        else:
            beta = offset_pressure_angle(s, s1, d, e)
            beta1 = offset_pressure_angle_rate(s, s1, s2, d, e)
            rc = offset_cam_radius(s, beta, beta1, d, rf)
            vc, vf = offset_surface_velocities(s, beta, beta1, d, rf, omega)
            R = rf - rf * rf * np.cos(beta) * (1.0 - beta1) / (d + s)   # Ball eq. 3.3 form
            rx = R
            # np.full, not full_like: a follower radius per sweep case broadcasts to (cases, angles)
            ry = np.full(np.shape(R), rf if shape == "spherical" else np.inf)
            load_factor = None
        cb, sb = np.cos(beta), np.sin(beta)
        nx, ny = cb * ax + sb * bx, cb * ay + sb * by
        qx, qy = e * bx + (d + s) * ax, e * by + (d + s) * ay
        px, py = qx - rf * nx, qy - rf * ny
        ecc = rf * beta
        rf_arr = np.full(np.shape(R), rf)
    arms = contact_arms(px, py, nx, ny, ax, ay, ax, ay, vc - vf)
    if load_factor is not None:
        # A taper tilts the normal out of the plane: only the in-plane share loads the follower
        # axis and the camshaft (Yang eq. 3.11); friction stays in the plane.
        arms["arm_normal"] = arms["arm_normal"] * load_factor
        arms["torque_arm_normal"] = arms["torque_arm_normal"] * load_factor
    return dict(contact_x=px, contact_y=py, eccentricity=ecc, cam_radius=rc,
                follower_radius=rf_arr, equivalent_radius=R, radius_x=rx, radius_y=ry,
                v_cam=vc, v_follower=vf, **arms)


def check_translating_inputs(base_radius, follower_radius, offset, omega, shape="spherical"):
    """Validate the inputs of a translating follower or tappet (InputError naming the field)."""
    if not base_radius > 0.0:
        raise field_error("cam.base_radius", "must be positive", base_radius, "> 0 m")
    if not follower_radius > 0.0:
        raise field_error("mechanism.follower_radius", "must be positive (inf for a flat face)",
                          follower_radius, "> 0 m")
    check_speed(omega)
    if shape not in FOLLOWER_SHAPES:
        raise field_error("mechanism.follower_shape", "unknown follower face shape", shape,
                          " or ".join(FOLLOWER_SHAPES))
    if not _infinite(follower_radius) and abs(offset) >= base_radius + follower_radius:
        raise field_error("mechanism.offset", "offset reaches beyond the follower's centre of "
                          "curvature on the base circle", offset,
                          f"|offset| < base radius + follower radius = "
                          f"{base_radius + follower_radius}")


def _ones(like: np.ndarray) -> np.ndarray:
    """np.ones_like without its Python-level wrapper."""
    ones = np.empty_like(like)
    ones.fill(1.0)
    return ones


def translating_kinematics(lc: LiftCurve, name: str, *, base_radius, follower_radius, offset,
                           omega, shape="spherical", taper_angle=None,
                           cases: int = 0) -> Kinematics:
    """Clockwise kinematics of a translating follower on the lift curve ``lc`` (the contact
    kernel :func:`translating_contact`, no checks). With ``cases`` > 0 a scalar may be one value
    per sweep case, a (cases, 1) column, and every field is a (cases, angles) array."""
    fields = translating_contact(lc.theta, lc.lift, lc.d1, lc.d2, base_radius=base_radius,
                                 follower_radius=follower_radius, offset=offset,
                                 omega=omega, shape=shape, taper_angle=taper_angle)
    arm = fields["arm_normal"]
    if np.count_nonzero(arm) == arm.size:   # the usual case: no errstate context needed
        ratio = 1.0 / arm
    else:
        with np.errstate(divide="ignore"):
            ratio = 1.0 / arm
    # the valve, cam and follower coordinates of a direct-acting follower are one lift
    lift, d1, d2 = kept(lc.lift), kept(lc.d1), kept(lc.d2)
    arrays = dict(theta=kept(lc.theta), valve_lift=lift, valve_d1=d1, valve_d2=d2,
                  valve_d3=kept(lc.d3), cam_lift=lift, cam_d1=d1, cam_d2=d2, rocker_ratio=ratio,
                  arm_valve=_ones(lc.lift), q=lift, q_d1=d1, q_d2=d2, **fields)
    if cases:   # a batch of sweep cases: every field spans (cases, angles)
        grid = (cases, lc.theta.size)
        arrays = {k: np.broadcast_to(v, grid) for k, v in arrays.items()}
        omega = np.broadcast_to(omega, grid) if isinstance(omega, np.ndarray) else omega
    else:
        omega = float(omega)
    return Kinematics(mechanism=name, rotation="clockwise", omega=omega,
                      inertia={"follower_mass": arrays["q_d2"]}, **arrays)


def _translating(lift: LiftCurve, name: str, *, base_radius, follower_radius, offset, omega,
                 rotation, shape="spherical", taper_angle=None) -> Kinematics:
    check_translating_inputs(base_radius, follower_radius, offset, omega, shape)

    def kernel(lc: LiftCurve, user_theta: np.ndarray) -> Kinematics:
        return translating_kinematics(lc, name, base_radius=base_radius,
                                      follower_radius=follower_radius, offset=offset,
                                      omega=omega, shape=shape, taper_angle=taper_angle)

    return analyse(lift, rotation, kernel)


def flat_faced(lift: LiftCurve, *, base_radius: float, omega: float,
               rotation: str | int = "clockwise", offset: float = 0.0,
               face_length: float | None = None) -> Kinematics:
    """Flat-faced translating follower (direct-acting bucket tappet), Ball 1988 eqs 3.4-3.6.

    base_radius [m] (``cam.base_radius``); offset [m] of the follower axis from the cam centre
    (``mechanism.offset``; it moves the contact on the face, not the cam); face_length [m]: usable
    face diameter (``mechanism.face_length``). ``inertia['follower_mass']`` is l'': lump the bucket
    mass into the valve-side equivalent mass or use this term, not both.
    Raises GeometryError if the cam would be concave or the face is too small.
    """
    k = _translating(lift, "flat-faced translating", base_radius=base_radius,
                     follower_radius=np.inf, offset=offset, omega=omega, rotation=rotation)
    check_flat_follower_convex(k, base_radius)
    check_face(k, face_length)
    return k


def domed(lift: LiftCurve, *, base_radius: float, follower_radius: float, omega: float,
          rotation: str | int = "clockwise", offset: float = 0.0, shape: str = "spherical",
          min_concave_radius: float | None = None, face_length: float | None = None) -> Kinematics:
    """Curved (domed) translating follower, radial (offset 0) or offset (Williams 2013 ch. 5-6,
    V_c sign corrected; reduces to Ball 1988 eqs 3.1-3.3 for offset 0).

    shape: 'spherical' dome (elliptical contact, R_y = r_f, Ball §3.3.2.1) or 'cylindrical' pad or
    roller without rotation (line contact). face_length: arc length of the face, centred on the
    follower axis. The pressure angle is exact (tan beta = (l'+e)/(d+l)); Ball's load eq. B.3
    approximates it by l'/r_f.
    """
    k = _translating(lift, "domed translating" if offset == 0.0 else "offset domed translating",
                     base_radius=base_radius, follower_radius=follower_radius, offset=offset,
                     omega=omega, rotation=rotation, shape=shape)
    check_curved_follower(k, radius_field="mechanism.follower_radius",
                          min_concave_radius=min_concave_radius)
    check_face(k, face_length)
    return k


def tapered_domed(lift: LiftCurve, *, base_radius: float, follower_radius: float,
                  taper_angle: float, omega: float, rotation: str | int = "clockwise",
                  min_concave_radius: float | None = None,
                  face_length: float | None = None) -> Kinematics:
    """Tapered cam on a non-rotating spherical domed follower (Yang 1992 §3.2.1-3.2.3).

    In-plane kinematics of Yang eqs 3.1-3.5; principal radii R_x (rolling direction, 1/R_x =
    1/r_c + 1/r_f) and R_y = r_f; the taper angle [rad] (``mechanism.taper_angle``) adds the
    out-of-plane load component of Yang eq. 3.11 to ``arm_normal`` and ``torque_arm_normal``.
    The small axial contact offset the taper causes (r_f sin(taper)) is not modelled.
    """
    if not 0.0 <= taper_angle < 0.5 * np.pi:
        raise field_error("mechanism.taper_angle", "taper angle out of range", taper_angle,
                          "0 <= angle < pi/2 rad")
    k = _translating(lift, "tapered cam, domed follower", base_radius=base_radius,
                     follower_radius=follower_radius, offset=0.0, omega=omega,
                     rotation=rotation, taper_angle=float(taper_angle))
    check_curved_follower(k, radius_field="mechanism.follower_radius",
                          min_concave_radius=min_concave_radius)
    check_face(k, face_length)
    return k
