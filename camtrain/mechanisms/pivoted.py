"""End-pivoted (finger) and centrally pivoted (rocker) followers by Dyson's method.

Ball (1988) App A after Dyson (1980) and Lim et al. (1983), with the corrections of the reference
extraction: L^2 of eq. A.11 has the opposite overall sign (so that r_c = r_B on the base circle),
V_c of eq. A.15 carries the missing r_f, V_f of eq. A.17 is written for the corrected L^2, and the
first term of eq. A.21 has the exponent -1. phi' (Dyson's angle of OU) increases with time, i.e.
the cam turns clockwise; :func:`camtrain.mechanisms.base.analyse` handles anticlockwise cams.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from camtrain.errors import GeometryError
from camtrain.lift.base import LiftCurve
from camtrain.mechanisms._contact import contact_arms
from camtrain.mechanisms.base import Kinematics, analyse, check_speed, cross, wrap_angle
from camtrain.mechanisms.checks import angle_text, check_curved_follower, check_face
from camtrain.mechanisms.pivot_geometry import PivotGeometry


# ---------------------------------------------------------------- published formulas
def dyson_m2(A, D, lam, gamma, g1):
    """M^2 = A^2 (1+gamma')^2 - 2 A D (1+gamma') cos(lambda+gamma) + D^2 (Ball eq. A.9);
    M = |dQ/dphi'|, the speed of the pad centre in the cam frame per radian."""
    g = 1.0 + g1
    return A * A * g * g - 2.0 * A * D * g * np.cos(lam + gamma) + D * D


def dyson_l2(A, D, lam, gamma, g1, g2):
    """L^2 = D^2 - A D gamma'' sin(lambda+gamma) - A D g (g+1) cos(lambda+gamma) + A^2 g^3,
    g = 1 + gamma' (Ball eq. A.11 with the overall sign corrected): L^2 = dQ/dphi' x d2Q/dphi'2.
    Negative L^2 means a concave flank."""
    g = 1.0 + g1
    return (D * D - A * D * g2 * np.sin(lam + gamma) - A * D * g * (g + 1.0) * np.cos(lam + gamma)
            + A * A * g ** 3)


def dyson_cam_radius(m2, l2, follower_radius):
    """r_c = M^3/L^2 - r_f (Ball eq. A.13); infinite (flat spot) where L^2 = 0."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(l2 == 0.0, np.inf, m2 ** 1.5 / np.where(l2 == 0.0, 1.0, l2)) \
            - follower_radius


def dyson_equivalent_radius(m2, l2, follower_radius):
    """R = r_f - r_f^2 L^2 / M^3 (Ball eq. A.14), finite through a flat spot of the cam."""
    return follower_radius - follower_radius ** 2 * l2 / m2 ** 1.5


def dyson_surface_velocities(m2, l2, g1, follower_radius, omega):
    """V_c = omega (M - r_f L^2/M^2) (Ball eq. A.15, r_f restored) and
    V_f = omega r_f (1 + gamma' - L^2/M^2) (Ball eq. A.17 for the corrected L^2)."""
    ratio = l2 / m2
    return (omega * (np.sqrt(m2) - follower_radius * ratio),
            omega * follower_radius * (1.0 + g1 - ratio))


def follower_angle(valve_lift, B, kappa, gamma_b, user_theta=None):
    """gamma from l_v = B cos(gamma_B + kappa) - B cos(gamma + kappa) (Ball eq. A.19), on the
    branch of gamma_B. Raises GeometryError where the valve arm would pass the valve axis."""
    c = np.cos(gamma_b + kappa) - valve_lift / B
    bad = np.abs(c) >= 1.0
    if np.any(bad):
        i = int(np.argmax(bad))
        where = angle_text(user_theta[i]) if user_theta is not None else f"index {i}"
        raise GeometryError(
            f"mechanism.pivot_to_valve, mechanism.kappa: the valve lift {valve_lift[i] * 1e3:.3f}"
            f" mm at {where} cannot be produced by a valve arm of {B * 1e3:.3f} mm at this angle "
            "(the arm would have to pass through the valve axis)")
    side = 1.0 if np.sin(gamma_b + kappa) > 0.0 else -1.0
    gamma = side * np.arccos(c) - kappa
    return gamma_b + wrap_angle(gamma - gamma_b)


def follower_angle_rates(d1, d2, B, kappa, gamma):
    """gamma' = l_v' / [B sin(gamma+kappa)] (Ball eq. A.20) and
    gamma'' = l_v'' / [B sin] - l_v'^2 cos(gamma+kappa) / [B^2 sin^3] (eq. A.21, first-term
    exponent corrected)."""
    s = np.sin(gamma + kappa)
    g1 = d1 / (B * s)
    g2 = d2 / (B * s) - d1 * d1 * np.cos(gamma + kappa) / (B * B * s ** 3)
    return g1, g2


# ---------------------------------------------------------------- kernel
def pivoted_contact(theta, gamma, g1, g2, *, A, D, lam, follower_radius, base_radius, sign,
                    gamma_b, omega):
    """Contact fields of a pivoted follower with angle gamma(theta) (clockwise cam).

    ``sign`` orients the follower coordinate q = sign (gamma - gamma_B) so that q grows with lift.
    Returns a dict of Kinematics fields (without the valve-side arm and inertia terms).
    """
    rf = follower_radius
    m2 = dyson_m2(A, D, lam, gamma, g1)
    l2 = dyson_l2(A, D, lam, gamma, g1, g2)
    rc = dyson_cam_radius(m2, l2, rf)
    R = dyson_equivalent_radius(m2, l2, rf)
    vc, vf = dyson_surface_velocities(m2, l2, g1, rf, omega)

    # Vector form in the cam frame: U = D e(theta), Q = U + A e(theta + pi + lambda + gamma).
    g = 1.0 + g1
    c = theta + np.pi + lam + gamma
    ux, uy = D * np.cos(theta), D * np.sin(theta)
    qx, qy = ux + A * np.cos(c), uy + A * np.sin(c)
    dqx, dqy = -uy - A * g * np.sin(c), ux + A * g * np.cos(c)
    ddqx = -ux - A * g2 * np.sin(c) - A * g * g * np.cos(c)
    ddqy = -uy + A * g2 * np.cos(c) - A * g * g * np.sin(c)
    speed = np.sqrt(m2)
    nx, ny = dqy / speed, -dqx / speed          # outward normal of the pitch curve
    px, py = qx - rf * nx, qy - rf * ny

    # nu: angle from UQ to the normal; the pad position is measured from its base-circle contact
    aqx, aqy = qx - ux, qy - uy
    nu = np.arctan2(cross(aqx, aqy, nx, ny), aqx * nx + aqy * ny)
    cb = np.pi + lam + gamma_b
    qbx, qby = D + A * np.cos(cb), A * np.sin(cb)
    nu_b = np.arctan2(cross(A * np.cos(cb), A * np.sin(cb), qbx, qby),
                      A * np.cos(cb) * qbx + A * np.sin(cb) * qby)
    ecc = -rf * wrap_angle(nu - nu_b)

    rq = np.hypot(qx, qy)
    cam_d1 = (qx * dqx + qy * dqy) / rq
    cam_d2 = (m2 + qx * ddqx + qy * ddqy - cam_d1 ** 2) / rq

    dispx, dispy = -sign * (py - uy), sign * (px - ux)      # sign * z x (P - U)
    arms = contact_arms(px, py, nx, ny, dispx, dispy, -sign * aqy / A, sign * aqx / A, vc - vf)
    return dict(contact_x=px, contact_y=py, eccentricity=ecc, cam_radius=rc,
                follower_radius=np.full_like(theta, rf), equivalent_radius=R, radius_x=R,
                radius_y=np.full_like(theta, np.inf), v_cam=vc, v_follower=vf,
                cam_lift=rq - base_radius - rf, cam_d1=cam_d1, cam_d2=cam_d2,
                q=sign * (gamma - gamma_b), q_d1=sign * g1, q_d2=sign * g2,
                gamma=gamma, gamma_d1=g1, gamma_d2=g2, nu=nu, **arms)


def pivoted(lift: LiftCurve, geometry: PivotGeometry, *, omega: float,
            rotation: str | int = "clockwise", min_concave_radius: float | None = None,
            face_length: float | None = None, face_centre: float = 0.0) -> Kinematics:
    """Pivoted follower driven by the valve lift law ``lift`` (Dyson's method, Ball App A).

    ``arm_valve`` = |B sin(gamma+kappa)| (= dl_v/dq), ``arm_normal`` = A cos(pressure angle)
    (= A |sin nu|), ``inertia['follower_inertia']`` = q'' for the follower's moment of inertia
    about its pivot (Ball's M_f B^2). The face position (eccentricity) is measured along the pad
    from its base-circle contact point; face_length/face_centre locate the pad [m].
    Raises GeometryError for a cusp, a concave flank tighter than ``min_concave_radius`` (the
    grinding-wheel radius) or a contact off the pad.
    """
    g = geometry
    check_speed(omega)
    sign = g.lift_sign
    gamma_b = g.gamma_b

    def kernel(lc: LiftCurve, user_theta: np.ndarray) -> Kinematics:
        gamma = follower_angle(lc.lift, g.B, g.kappa, gamma_b, user_theta)
        g1, g2 = follower_angle_rates(lc.d1, lc.d2, g.B, g.kappa, gamma)
        fields = pivoted_contact(lc.theta, gamma, g1, g2, A=g.A, D=g.D, lam=g.lam,
                                 follower_radius=g.follower_radius, base_radius=g.base_radius,
                                 sign=sign, gamma_b=gamma_b, omega=omega)
        arm_valve = sign * g.B * np.sin(gamma + g.kappa)
        with np.errstate(divide="ignore"):
            ratio = arm_valve / fields["arm_normal"]
        return Kinematics(
            mechanism=f"{g.kind}-pivoted follower", rotation="clockwise", omega=float(omega),
            theta=lc.theta.copy(), valve_lift=lc.lift.copy(), valve_d1=lc.d1.copy(),
            valve_d2=lc.d2.copy(), valve_d3=lc.d3.copy(), rocker_ratio=ratio,
            arm_valve=arm_valve, inertia={"follower_inertia": fields["q_d2"].copy()}, **fields)

    k = analyse(lift, rotation, kernel)
    check_curved_follower(k, radius_field="mechanism.follower_radius",
                          min_concave_radius=min_concave_radius)
    check_face(k, face_length, face_centre)
    return k


def end_pivoted(lift: LiftCurve, geometry: PivotGeometry, **kwargs) -> Kinematics:
    """End-pivoted finger follower (Ball App A(a)); see :func:`pivoted`."""
    return pivoted(lift, _as_kind(geometry, "end"), **kwargs)


def centrally_pivoted(lift: LiftCurve, geometry: PivotGeometry, **kwargs) -> Kinematics:
    """Centrally pivoted rocker follower (Ball App A(b)); see :func:`pivoted`."""
    return pivoted(lift, _as_kind(geometry, "central"), **kwargs)


def _as_kind(geometry: PivotGeometry, kind: str) -> PivotGeometry:
    return geometry if geometry.kind == kind else replace(geometry, kind=kind)
