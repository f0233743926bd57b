"""Cam lift measured on an inspection follower -> valve lift of a pivoted follower.

Ball (1988) §4.2.1 lets the lift of a pivoted train be given "at the cam", as read by a radial
translating roller (inspection follower) of radius r_i, and converts it to valve lift before the
kinematics; the method is not printed. Here (reference extraction §4.6): the inspection reading
l_c(s) at inspection angle s places the roller centre on the pitch curve
C(s) = (r_B + r_i + l_c(s)) e(alpha + s); offsetting it by r_f - r_i along its normal gives the
locus of the pad centre Q of the real follower. At each cam angle theta, Q is where that locus
meets the circle of radius A about the pivot; its direction from the pivot gives gamma, and
eq. A.19 gives the valve lift. The inspection axis alpha is taken through the base-circle pad
centre; the result is re-centred so that maximum valve lift falls at theta = 0.

Derivatives of the converted lift come from a periodic quintic interpolating spline on the input
grid (Ball used central differences on data); the grid must be uniform over one revolution.
"""
from __future__ import annotations

import numpy as np

from camtrain.errors import ConvergenceError, field_error
from camtrain.lift.base import LiftCurve
from camtrain.mechanisms.base import CLOCKWISE, normalise_rotation, reverse_lift, wrap_angle
from camtrain.mechanisms.pivot_geometry import PivotGeometry

_TOL = 1e-13          # rad, Newton step on the inspection angle
_MAX_ITER = 60


def _periodic_grid_step(theta: np.ndarray) -> float:
    step = np.diff(theta)
    h = 2.0 * np.pi / theta.size
    if theta.size < 8 or np.any(np.abs(step - h) > 1e-9 * h):
        raise field_error("lift", "cam-lift conversion needs a uniform grid over one revolution",
                          theta.size, "theta = theta_0 + 2 pi k / n, k = 0..n-1")
    return h


def _inspection_interpolant(cam: LiftCurve):
    """C2 piecewise quintic through l_c, l_c', l_c'', repeated over three revolutions."""
    x = np.concatenate([cam.theta - 2 * np.pi, cam.theta, cam.theta + 2 * np.pi,
                        cam.theta[:1] + 4 * np.pi])
    y = np.stack([cam.lift, cam.d1, cam.d2], axis=1)
    from scipy.interpolate import BPoly

    return BPoly.from_derivatives(x, np.concatenate([y, y, y, y[:1]]))


def _pad_centre_locus(poly, s, alpha, base_radius, inspection_radius, follower_radius):
    """Points of the pad-centre locus and their derivative with respect to s."""
    rho = base_radius + inspection_radius + poly(s)
    r1, r2 = poly.derivative(1)(s), poly.derivative(2)(s)
    ang = alpha + s
    e = np.array([np.cos(ang), np.sin(ang)])
    ep = np.array([-np.sin(ang), np.cos(ang)])
    c1 = r1 * e + rho * ep                           # dC/ds
    c2 = (r2 - rho) * e + 2.0 * r1 * ep              # d2C/ds2
    speed = np.hypot(c1[0], c1[1])
    normal = np.array([c1[1], -c1[0]]) / speed       # outward normal of C
    offset = follower_radius - inspection_radius
    curvature = (c1[0] * c2[1] - c1[1] * c2[0]) / speed ** 3
    return rho * e + offset * normal, c1 * (1.0 + offset * curvature)


def _convert_clockwise(cam: LiftCurve, g: PivotGeometry, inspection_radius: float) -> np.ndarray:
    poly = _inspection_interpolant(cam)
    q_b = g.points()["Q"]
    alpha = float(np.arctan2(q_b[1], q_b[0]))
    theta = cam.theta
    ux, uy = g.D * np.cos(theta), g.D * np.sin(theta)
    s = theta.copy()
    for _ in range(_MAX_ITER):
        p, dp = _pad_centre_locus(poly, s, alpha, g.base_radius, inspection_radius,
                                  g.follower_radius)
        rx, ry = p[0] - ux, p[1] - uy
        f = rx * rx + ry * ry - g.A * g.A
        df = 2.0 * (rx * dp[0] + ry * dp[1])
        step = np.clip(f / df, -0.05, 0.05)
        s -= step
        if np.max(np.abs(step)) < _TOL:
            break
    else:
        raise ConvergenceError(f"cam-lift conversion: Newton iteration on the inspection angle did "
                               f"not reach {_TOL:g} rad in {_MAX_ITER} steps "
                               f"(last step {np.max(np.abs(step)):.3g} rad)")
    p, _ = _pad_centre_locus(poly, s, alpha, g.base_radius, inspection_radius, g.follower_radius)
    arm = np.arctan2(p[1] - uy, p[0] - ux)
    gamma = g.gamma_b + wrap_angle(arm - theta - np.pi - g.lam - g.gamma_b)
    return g.B * np.cos(g.gamma_b + g.kappa) - g.B * np.cos(gamma + g.kappa)


def valve_lift_from_cam_lift(cam_lift: LiftCurve, geometry: PivotGeometry,
                             inspection_radius: float, *, rotation: str | int = "clockwise",
                             recentre: bool = True) -> LiftCurve:
    """Valve lift of a pivoted follower from cam lift read by an inspection roller.

    cam_lift: inspection reading on a uniform grid over one revolution [m, rad];
    inspection_radius: roller radius r_i [m] (``lift.inspection_radius``); rotation: as for the
    kinematics (the conversion depends on it, see Ball §4.2.1). With ``recentre`` the returned
    curve has its maximum at theta = 0, on the same grid.
    """
    if not inspection_radius > 0.0:
        raise field_error("lift.inspection_radius", "must be positive", inspection_radius, "> 0 m")
    theta = np.asarray(cam_lift.theta, dtype=float)
    h = _periodic_grid_step(theta)
    direction = normalise_rotation(rotation)
    if direction == CLOCKWISE:
        valve = _convert_clockwise(cam_lift, geometry, inspection_radius)
    else:
        valve = _convert_clockwise(reverse_lift(cam_lift), geometry, inspection_radius)[::-1]
    x = np.append(theta, theta[0] + 2.0 * np.pi)
    from scipy.interpolate import make_interp_spline
    from scipy.optimize import minimize_scalar

    spline = make_interp_spline(x, np.append(valve, valve[0]), k=5, bc_type="periodic")
    shift = 0.0
    if recentre:
        i = int(np.argmax(valve))
        best = minimize_scalar(lambda t: -spline(t), bounds=(theta[i] - h, theta[i] + h),
                               method="bounded", options={"xatol": 1e-12})
        shift = float(best.x)
    t = theta[0] + np.mod(theta + shift - theta[0], 2.0 * np.pi)
    return LiftCurve(theta=theta.copy(), lift=spline(t), d1=spline(t, 1), d2=spline(t, 2),
                     d3=spline(t, 3))
