"""Push-rod trains (Williams 2013 ch. 11): simple (tappet, push rod, rocker) and four-bar chain.

Rocker frame (origin at the rocker pivot K, x to the right, y up; Williams Figs 11.1, 11.6): the
valve arm D2 and the push-rod arm D1 form one rigid rocker. With phi - phi0 from the valve lift
(eq. 11.3) and eps = phi - phi0 - alpha0 - gamma (eq. 11.10), the push-rod end of the rocker is at
(-D1 cos eps, D1 sin eps) (eqs 11.57-11.58). The valve arm is perpendicular to the valve axis at
the valve lift lambda * L (L = maximum valve lift of the law).

* Simple train: the push rod (length D_PR) hangs from the rocker tip down to a translating tappet
  whose axis is parallel to y at x = -x_bar; the tappet then runs on the cam as a flat or domed
  translating follower (:mod:`camtrain.mechanisms.translating`).
* Four-bar chain: the push rod joins the rocker tip to a point at distance e from the pivot F of
  a finger follower, F = (-a, -b) in the rocker frame; the finger follower then runs on the cam as
  a pivoted follower (:mod:`camtrain.mechanisms.pivoted`), with cam centre at distance D from F.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.errors import GeometryError, field_error
from camtrain.lift.base import LiftCurve
from camtrain.mechanisms.base import Kinematics, analyse, check_speed
from camtrain.mechanisms.checks import (
    angle_text,
    check_curved_follower,
    check_face,
    check_flat_follower_convex,
)
from camtrain.mechanisms.pivot_geometry import base_circle_cosine
from camtrain.mechanisms.pivoted import pivoted_contact
from camtrain.mechanisms.translating import check_translating_inputs, translating_contact


# ---------------------------------------------------------------- published formulas
def rocker_angle(valve_lift, D2, perpendicular_lift):
    """phi - phi0 = asin[(s_V - lambda L) / D2] (Williams 2013 eq. 11.3)."""
    return np.arcsin((valve_lift - perpendicular_lift) / D2)


def rocker_angle_rates(d1, d2, D2, phi_rel):
    """phi' = s_V' / [D2 cos(phi-phi0)] (eq. 11.5) and phi'' = s_V''/(D2 c) +
    s_V'^2 sin(phi-phi0)/(D2^2 c^3), c = cos(phi-phi0) (eq. 11.7 in its consistent form)."""
    c = np.cos(phi_rel)
    return d1 / (D2 * c), d2 / (D2 * c) + d1 * d1 * np.sin(phi_rel) / (D2 * D2 * c ** 3)


def pushrod_angle(eps, D1, D_PR, x_bar):
    """psi = asin[(x_bar - D1 cos eps) / D_PR] (Williams 2013 eq. 11.17)."""
    return np.arcsin((x_bar - D1 * np.cos(eps)) / D_PR)


def pushrod_angle_rates(eps, psi, phi1, phi2, D1, D_PR):
    """psi' = D1 sin(eps) phi' / (D_PR cos psi) (eq. 11.19) and
    psi'' = [D_PR sin psi psi'^2 + D1 sin eps phi'' + D1 cos eps phi'^2] / (D_PR cos psi) (11.21)."""
    psi1 = D1 * np.sin(eps) * phi1 / (D_PR * np.cos(psi))
    psi2 = (D_PR * np.sin(psi) * psi1 ** 2 + D1 * np.sin(eps) * phi2
            + D1 * np.cos(eps) * phi1 ** 2) / (D_PR * np.cos(psi))
    return psi1, psi2


def tappet_lift(eps, psi, eps0, psi0, D1, D_PR):
    """s_F = D_PR (cos psi0 - cos psi) + D1 (sin eps - sin eps0) (Williams eq. 11.24, with
    cos beta0 = -sin eps0 from eqs 11.8-11.10)."""
    return D_PR * (np.cos(psi0) - np.cos(psi)) + D1 * (np.sin(eps) - np.sin(eps0))


def tappet_lift_rates(eps, psi, phi1, phi2, D1, D_PR):
    """s_F' = D1 [tan psi sin eps + cos eps] phi' (eq. 11.27) and
    s_F'' = D1 [(tan psi sin eps + cos eps) phi'' +
                (tan psi cos eps + D1 sin^2 eps / (D_PR cos^3 psi) - sin eps) phi'^2] (eq. 11.29)."""
    k1 = np.tan(psi) * np.sin(eps) + np.cos(eps)
    k2 = (np.tan(psi) * np.cos(eps) + D1 * np.sin(eps) ** 2 / (D_PR * np.cos(psi) ** 3)
          - np.sin(eps))
    return D1 * k1 * phi1, D1 * (k1 * phi2 + k2 * phi1 ** 2)


def four_bar_quadratic(x1, y1, a, b, c, d, e):
    """Coefficients of A y2^2 + B y2 + C = 0 for the push-rod/follower joint (Williams 2013
    eqs 11.68-11.76 as corrected in the reference extraction), u = x1 + a, v = y1 + b,
    F = a^2 + b^2 - c^2 + d^2 - e^2; then x2 = -[F + 2 y2 v] / (2 u) (eq. 11.70)."""
    u, v = x1 + a, y1 + b
    F = a * a + b * b - c * c + d * d - e * e
    return 4.0 * (u * u + v * v), 4.0 * v * (F - 2.0 * a * u) + 8.0 * b * u * u, \
        (F - 2.0 * a * u) ** 2 + 4.0 * u * u * (b * b - e * e)


def solve_joint_rates(jx, jy, fx, fy, tx, ty, rhs_x, rhs_y):
    """Solve (J - F).J' = rhs_x and (T - J).J' = rhs_y for J' (the form of Williams eqs
    11.83/11.85 for velocities and 11.87/11.89 for accelerations)."""
    a11, a12 = jx - fx, jy - fy
    a21, a22 = tx - jx, ty - jy
    det = a11 * a22 - a12 * a21
    return (rhs_x * a22 - a12 * rhs_y) / det, (a11 * rhs_y - a21 * rhs_x) / det


# ---------------------------------------------------------------- geometry containers
@dataclass(frozen=True)
class RockerGeometry:
    """Rocker and push rod shared by both trains (SI, radians; deck fields in brackets).

    D1: rocker arm on the push-rod side [m] (mechanism.rocker_pushrod_arm)
    D2: rocker arm on the valve side [m] (mechanism.rocker_valve_arm)
    alpha0: angle between the rocker arms, Williams' alpha_0 [rad] (mechanism.rocker_arm_angle)
    valve_angle: angle between the y axis and the valve axis, Williams' gamma [rad]
        (mechanism.valve_axis_angle)
    perpendicular_fraction: lambda, fraction of the maximum valve lift at which the valve arm is
        perpendicular to the valve axis (mechanism.perpendicular_lift_fraction)
    pushrod_length: D_PR [m] (mechanism.pushrod_length)
    pushrod_cg_fraction: D_PR1 / D_PR, distance of the push rod's centre of mass from its lower
        (tappet or follower) end as a fraction of its length (mechanism.pushrod_cg_fraction)
    """

    D1: float
    D2: float
    alpha0: float
    valve_angle: float
    perpendicular_fraction: float
    pushrod_length: float
    pushrod_cg_fraction: float = 0.5

    def __post_init__(self) -> None:
        for attr, path in (("D1", "rocker_pushrod_arm"), ("D2", "rocker_valve_arm"),
                           ("pushrod_length", "pushrod_length")):
            if not getattr(self, attr) > 0.0:
                raise field_error(f"mechanism.{path}", "must be positive", getattr(self, attr),
                                  "> 0 m")
        if not 0.0 <= self.pushrod_cg_fraction <= 1.0:
            raise field_error("mechanism.pushrod_cg_fraction", "must lie in [0, 1]",
                              self.pushrod_cg_fraction)

    def rocker(self, lift: LiftCurve, max_lift: float, user_theta: np.ndarray):
        """eps, eps', eps'' and the rocker angle from the valve lift (eqs 11.3-11.10)."""
        arg = (lift.lift - self.perpendicular_fraction * max_lift) / self.D2
        if np.any(np.abs(arg) >= 1.0):
            i = int(np.argmax(np.abs(arg)))
            raise GeometryError(f"mechanism.rocker_valve_arm: a valve arm of {self.D2 * 1e3:.3f}"
                                f" mm cannot give the valve lift at {angle_text(user_theta[i])}")
        phi_rel = rocker_angle(lift.lift, self.D2, self.perpendicular_fraction * max_lift)
        phi1, phi2 = rocker_angle_rates(lift.d1, lift.d2, self.D2, phi_rel)
        return phi_rel - self.alpha0 - self.valve_angle, phi1, phi2, phi_rel

    def base_eps(self, max_lift: float) -> float:
        return float(rocker_angle(0.0, self.D2, self.perpendicular_fraction * max_lift)
                     - self.alpha0 - self.valve_angle)


def _tip(D1, eps, e1, e2):
    """Rocker tip position, velocity and acceleration (Williams eqs 11.57-11.58, 11.81-11.91 as
    corrected: y1' = c cos(eps) eps', x1'' = c (sin eps eps'' + cos eps eps'^2), ...)."""
    s, c = np.sin(eps), np.cos(eps)
    return (-D1 * c, D1 * s, D1 * s * e1, D1 * c * e1,
            D1 * (s * e2 + c * e1 ** 2), D1 * (c * e2 - s * e1 ** 2))


def _kinematics(name, lc, omega, q_fields, contact, arm_valve, inertia) -> Kinematics:
    with np.errstate(divide="ignore"):
        ratio = arm_valve / contact["arm_normal"]
    return Kinematics(mechanism=name, rotation="clockwise", omega=float(omega),
                      theta=lc.theta.copy(), valve_lift=lc.lift.copy(), valve_d1=lc.d1.copy(),
                      valve_d2=lc.d2.copy(), valve_d3=lc.d3.copy(), rocker_ratio=ratio,
                      arm_valve=arm_valve, inertia=inertia, **q_fields, **contact)


# ---------------------------------------------------------------- simple push-rod train
def pushrod_simple(lift: LiftCurve, rocker: RockerGeometry, *, tappet_axis_distance: float,
                   base_radius: float, omega: float, tappet_radius: float = np.inf,
                   tappet_offset: float = 0.0, rotation: str | int = "clockwise",
                   min_concave_radius: float | None = None,
                   face_length: float | None = None, tappet_shape: str = "spherical") -> Kinematics:
    """Valve lift law -> rocker -> push rod -> translating tappet on the cam (Williams §11.2-11.5).

    tappet_axis_distance: x_bar, rocker pivot to tappet axis [m] (mechanism.tappet_axis_distance);
    tappet_radius: inf for a flat tappet, else the dome radius (mechanism.follower_radius);
    tappet_offset: tappet axis offset from the cam centre (mechanism.offset);
    tappet_shape: 'spherical' dome or 'cylindrical' face (a roller lifter, line contact).
    q is the tappet lift; inertia keys: tappet_mass, rocker_inertia (about its pivot),
    pushrod_mass, pushrod_inertia (about its centre of mass).
    """
    check_translating_inputs(base_radius, tappet_radius, tappet_offset, omega, tappet_shape)
    r, xb = rocker, float(tappet_axis_distance)
    max_lift = lift.max_lift
    f = r.pushrod_cg_fraction

    def kernel(lc: LiftCurve, user_theta: np.ndarray) -> Kinematics:
        eps, e1, e2, phi_rel = r.rocker(lc, max_lift, user_theta)
        arg = (xb - r.D1 * np.cos(eps)) / r.pushrod_length
        if np.any(np.abs(arg) >= 1.0):
            i = int(np.argmax(np.abs(arg)))
            raise GeometryError("mechanism.pushrod_length, mechanism.tappet_axis_distance: the "
                                f"push rod cannot reach the tappet axis at {angle_text(user_theta[i])}")
        psi = pushrod_angle(eps, r.D1, r.pushrod_length, xb)
        eps0 = r.base_eps(max_lift)
        psi0 = float(pushrod_angle(eps0, r.D1, r.pushrod_length, xb))
        s = tappet_lift(eps, psi, eps0, psi0, r.D1, r.pushrod_length)
        s1, s2 = tappet_lift_rates(eps, psi, e1, e2, r.D1, r.pushrod_length)
        ks, _ = tappet_lift_rates(eps, psi, 1.0, 0.0, r.D1, r.pushrod_length)    # ds_F/d eps
        if np.any(ks <= 0.0):
            i = int(np.argmin(ks))
            raise GeometryError("mechanism.rocker_arm_angle, mechanism.tappet_axis_distance: the "
                                f"tappet would move down as the valve opens at "
                                f"{angle_text(user_theta[i])}")
        psi1, psi2 = pushrod_angle_rates(eps, psi, e1, e2, r.D1, r.pushrod_length)
        dpsi, _ = pushrod_angle_rates(eps, psi, 1.0, 0.0, r.D1, r.pushrod_length)
        _, _, tx1, ty1, tx2, ty2 = _tip(r.D1, eps, e1, e2)
        _, _, gx, gy, _, _ = _tip(r.D1, eps, 1.0, 0.0)
        ax, ay = f * tx2, f * ty2 + (1.0 - f) * s2          # push-rod centre of mass, per omega^2
        gx, gy = f * gx, f * gy + (1.0 - f) * ks            # d(centre of mass)/d eps
        contact = translating_contact(lc.theta, s, s1, s2, base_radius=base_radius,
                                      follower_radius=tappet_radius, offset=tappet_offset,
                                      omega=omega, shape=tappet_shape)
        inertia = {"tappet_mass": s2, "rocker_inertia": e2 / ks,
                   "pushrod_mass": (ax * gx + ay * gy) / ks, "pushrod_inertia": psi2 * dpsi / ks}
        q_fields = dict(cam_lift=s, cam_d1=s1, cam_d2=s2, q=s.copy(), q_d1=s1.copy(),
                        q_d2=s2.copy())
        return _kinematics("simple push rod", lc, omega, q_fields, contact,
                           r.D2 * np.cos(phi_rel) / ks, inertia)

    k = analyse(lift, rotation, kernel)
    if np.isinf(tappet_radius):
        check_flat_follower_convex(k, base_radius)
    else:
        check_curved_follower(k, radius_field="mechanism.follower_radius",
                              min_concave_radius=min_concave_radius)
    check_face(k, face_length)
    return k


# ---------------------------------------------------------------- four-bar chain
@dataclass(frozen=True)
class FourBarGeometry:
    """Follower side of the four-bar chain (SI; deck fields in brackets).

    a, b: rocker pivot offset; the follower pivot F is at (-a, -b) from the rocker pivot [m]
        (mechanism.rocker_pivot_x, mechanism.rocker_pivot_y)
    e: follower pivot to push-rod joint [m] (mechanism.follower_pushrod_arm)
    A: follower pivot to pad centre of curvature, Williams' D_F [m]
        (mechanism.pivot_to_cam_contact_centre)
    D: cam centre to follower pivot [m] (mechanism.cam_to_pivot)
    follower_radius, base_radius [m]; branch: +1/-1 side of the cam-side cosine rule (with a
        clockwise cam +1 is an "away" cam, -1 a "towards" cam) (mechanism.branch);
    closure: +1/-1, side of the line F -> rocker tip on which the joint lies (mechanism.closure)
    """

    a: float
    b: float
    e: float
    A: float
    D: float
    follower_radius: float
    base_radius: float
    branch: int = 1
    closure: int = -1

    def __post_init__(self) -> None:
        for attr, path in (("e", "follower_pushrod_arm"), ("A", "pivot_to_cam_contact_centre"),
                           ("D", "cam_to_pivot"), ("follower_radius", "follower_radius")):
            if not getattr(self, attr) > 0.0:
                raise field_error(f"mechanism.{path}", "must be positive", getattr(self, attr),
                                  "> 0 m")
        if not self.base_radius > 0.0:
            raise field_error("cam.base_radius", "must be positive", self.base_radius, "> 0 m")
        for attr in ("branch", "closure"):
            if getattr(self, attr) not in (1, -1):
                raise field_error(f"mechanism.{attr}", "must be +1 or -1", getattr(self, attr))


def _joint(fx, fy, e, tx, ty, d, closure, user_theta):
    """Intersection of the circles |J - F| = e and |J - T| = d (Williams eqs 11.62-11.63)."""
    dx, dy = tx - fx, ty - fy
    dist = np.hypot(dx, dy)
    bad = (dist > d + e) | (dist < abs(d - e))
    if np.any(bad):
        i = int(np.argmax(bad))
        raise GeometryError(
            "mechanism.pushrod_length, mechanism.follower_pushrod_arm, mechanism.rocker_pivot_x, "
            f"mechanism.rocker_pivot_y: the four-bar chain cannot assemble at "
            f"{angle_text(user_theta[i])} (pivot-to-rocker-tip distance {dist[i] * 1e3:.3f} mm, "
            f"push rod {d * 1e3:.3f} mm, follower arm {e * 1e3:.3f} mm)")
    along = (e * e - d * d + dist * dist) / (2.0 * dist)
    h = np.sqrt(np.maximum(e * e - along * along, 0.0))
    ux, uy = dx / dist, dy / dist
    return fx + along * ux - closure * h * uy, fy + along * uy + closure * h * ux


def pushrod_four_bar(lift: LiftCurve, rocker: RockerGeometry, follower: FourBarGeometry, *,
                     omega: float, rotation: str | int = "clockwise",
                     min_concave_radius: float | None = None, face_length: float | None = None,
                     face_centre: float = 0.0) -> Kinematics:
    """Valve lift law -> rocker -> push rod -> finger follower on the cam (Williams §11.6-11.10).

    q is the finger follower's angular lift [rad]; inertia keys: follower_inertia and
    rocker_inertia (about their pivots), pushrod_mass, pushrod_inertia. gamma/nu follow Dyson's
    convention with lambda = 0 (gamma = angle from the pivot-to-cam line to the pad arm).
    """
    check_speed(omega)
    r, fb = rocker, follower
    c = base_circle_cosine(fb.A, fb.D, fb.follower_radius, fb.base_radius)
    if abs(c) >= 1.0:
        raise GeometryError("mechanism.pivot_to_cam_contact_centre, mechanism.cam_to_pivot: the "
                            "finger follower cannot touch the base circle")
    gamma_b = fb.branch * float(np.arccos(c))
    max_lift = lift.max_lift
    d, e, f = r.pushrod_length, fb.e, r.pushrod_cg_fraction
    fx, fy = -fb.a, -fb.b

    def chain(eps, e1, e2, user_theta):
        x1, y1, x1p, y1p, x1pp, y1pp = _tip(r.D1, eps, e1, e2)
        jx, jy = _joint(fx, fy, e, x1, y1, d, fb.closure, user_theta)
        rhs = (x1 - jx) * x1p + (y1 - jy) * y1p
        jxp, jyp = solve_joint_rates(jx, jy, fx, fy, x1, y1, 0.0, rhs)
        rhs_a = -(jxp ** 2 + jyp ** 2)
        rhs_b = (x1 - jx) * x1pp + (y1 - jy) * y1pp + (x1p - jxp) ** 2 + (y1p - jyp) ** 2
        jxpp, jypp = solve_joint_rates(jx, jy, fx, fy, x1, y1, rhs_a, rhs_b)
        chi = np.arctan2(jy - fy, jx - fx)
        chi1 = ((jx - fx) * jyp - (jy - fy) * jxp) / (e * e)
        chi2 = ((jx - fx) * jypp - (jy - fy) * jxpp) / (e * e)
        return dict(x1=x1, y1=y1, x1p=x1p, y1p=y1p, x1pp=x1pp, y1pp=y1pp, jx=jx, jy=jy, jxp=jxp,
                    jyp=jyp, jxpp=jxpp, jypp=jypp, chi=chi, chi1=chi1, chi2=chi2)

    base = chain(np.array([r.base_eps(max_lift)]), 1.0, 0.0, np.zeros(1))
    turn = 1.0 if base["chi1"][0] > 0.0 else -1.0       # follower turns this way as the valve opens

    def kernel(lc: LiftCurve, user_theta: np.ndarray) -> Kinematics:
        eps, e1, e2, phi_rel = r.rocker(lc, max_lift, user_theta)
        ch = chain(eps, e1, e2, user_theta)
        unit = chain(eps, np.ones_like(eps), np.zeros_like(eps), user_theta)   # d/d eps
        dq = turn * unit["chi1"]
        if np.any(dq <= 0.0):
            i = int(np.argmin(dq))
            raise GeometryError("mechanism.closure: the finger follower reverses its motion at "
                                f"{angle_text(user_theta[i])} (chain at a toggle position)")
        q = turn * (ch["chi"] - base["chi"][0])
        q = np.mod(q + np.pi, 2.0 * np.pi) - np.pi
        q1, q2 = turn * ch["chi1"], turn * ch["chi2"]
        gamma = gamma_b + fb.branch * q
        contact = pivoted_contact(lc.theta, gamma, fb.branch * q1, fb.branch * q2, A=fb.A,
                                  D=fb.D, lam=0.0, follower_radius=fb.follower_radius,
                                  base_radius=fb.base_radius, sign=fb.branch, gamma_b=gamma_b,
                                  omega=omega)
        # push rod: angle psi of T - J from the y axis (Williams eqs 11.92-11.101, combined form)
        px, py = ch["x1"] - ch["jx"], ch["y1"] - ch["jy"]
        psi2 = (py * (ch["x1pp"] - ch["jxpp"]) - px * (ch["y1pp"] - ch["jypp"])) / (d * d)
        ux = unit["x1p"] - unit["jxp"]
        uy = unit["y1p"] - unit["jyp"]
        dpsi = (py * ux - px * uy) / (d * d)
        gx = unit["jxp"] + f * ux
        gy = unit["jyp"] + f * uy
        ax = ch["jxpp"] + f * (ch["x1pp"] - ch["jxpp"])
        ay = ch["jypp"] + f * (ch["y1pp"] - ch["jypp"])
        inertia = {"follower_inertia": q2.copy(), "rocker_inertia": e2 / dq,
                   "pushrod_mass": (ax * gx + ay * gy) / dq, "pushrod_inertia": psi2 * dpsi / dq}
        return _kinematics("four-bar push rod", lc, omega, {}, contact,
                           r.D2 * np.cos(phi_rel) / dq, inertia)

    k = analyse(lift, rotation, kernel)
    check_curved_follower(k, radius_field="mechanism.follower_radius",
                          min_concave_radius=min_concave_radius)
    check_face(k, face_length, face_centre)
    return k
