"""Analytic and published lift laws for the mechanism tests (SI units, cam angle from the nose)."""
from __future__ import annotations

import numpy as np
from numpy.polynomial import Polynomial
from scipy.interpolate import make_interp_spline

from camtrain.lift.base import LiftCurve

# (1 - u^2)^3 (1 + 3u^2): flat nose, lift/velocity/acceleration continuous at the event ends.
_SHAPE = Polynomial([1.0, 0.0, -1.0]) ** 3 * Polynomial([1.0, 0.0, 3.0])


def event_lift(theta: np.ndarray, height: float, half_width: float, skew: float = 0.0) -> LiftCurve:
    """Smooth test event: l = h c(u) (1 + skew u), u = theta / half_width, zero for |u| >= 1."""
    shape = _SHAPE * Polynomial([1.0, skew])
    u = theta / half_width
    inside = np.abs(u) < 1.0
    out = []
    for order in range(4):
        values = np.where(inside, shape.deriv(order)(u) if order else shape(u), 0.0)
        out.append(height * values / half_width ** order)
    return LiftCurve(theta, *out)


HARRISON_C = {2: -11.6918407e-3, 9: 2.8498942e-3, 78: -0.5894568e-3, 80: 0.5314033e-3}


def harrison_lift(theta: np.ndarray) -> LiftCurve:
    """Ball (1988) §3.2 four-power lift: l = Y_R + l_cmax + sum C_n (|phi|/phi_T)^n for
    |phi| <= 60 deg, then a constant-velocity ramp of 0.5 mm over 25 deg, then the base circle."""
    ramp_height, peak, phi_t, ramp = 0.5e-3, 8.9e-3, np.radians(60.0), np.radians(25.0)
    a, sg = np.abs(theta), np.sign(theta)
    u = a / phi_t
    main = a <= phi_t
    on_ramp = (a > phi_t) & (a <= phi_t + ramp)
    poly = Polynomial([ramp_height + peak] + [0.0] * 80)
    for n, c in HARRISON_C.items():
        poly.coef[n] = c
    out = [np.zeros_like(theta) for _ in range(4)]
    for order in range(4):
        values = poly.deriv(order)(u) if order else poly(u)
        out[order][main] = values[main] / phi_t ** order * (sg[main] if order % 2 else 1.0)
    out[0][on_ramp] = ramp_height * (phi_t + ramp - a[on_ramp]) / ramp
    out[1][on_ramp] = -sg[on_ramp] * ramp_height / ramp
    return LiftCurve(theta, *out)


ROVER_EXP = [2.317111, -0.8104e-3, -1.526837, -0.1552985, -1.789897, 0.1171634, -0.2422081]


def rover_lift(theta: np.ndarray) -> LiftCurve:
    """Lim et al. (1983) exponential fit of the Rover valve lift (Ball §2.1(d)), mm -> m."""
    p = Polynomial(ROVER_EXP)
    a, b, c = p.deriv(1)(theta), p.deriv(2)(theta), p.deriv(3)(theta)
    lift = np.exp(p(theta)) * 1e-3
    return LiftCurve(theta, lift, a * lift, (b + a * a) * lift, (c + 3 * a * b + a ** 3) * lift)


PINTO_APP_E = """
0.0000 0.0008 0.0038 0.0094 0.0174 0.0275 0.0386 0.0495 0.0604 0.0713 0.0822 0.0931 0.1040 0.1149
0.1258 0.1367 0.1476 0.1585 0.1694 0.1803 0.1912 0.2021 0.2129 0.2238 0.2347 0.2457 0.2569 0.2688
0.2825 0.2990 0.3208 0.3509 0.3922 0.4472 0.5176 0.6046 0.7085 0.8290 0.9653 1.1158 1.2788 1.4521
1.6332 1.8203 2.0116 2.2055 2.4005 2.5950 2.7877 2.9776 3.1637 3.3454 3.5221 3.6934 3.8590 4.0188
4.1727 4.3205 4.4624 4.5983 4.7282 4.8524 4.9709 5.0838 5.1913 5.2933 5.3901 5.4816 5.5681 5.6495
5.7259 5.7975 5.8643 5.9264 5.9838 6.0365 6.0848 6.1286 6.1679 6.2029 6.2336 6.2601 6.2823 6.3004
6.3144 6.3244 6.3303 6.3323 6.3303 6.3245 6.3148 6.3013 6.2840 6.2630 6.2383 6.2099 6.1779 6.1422
6.1030 6.0603 6.0140 5.9642 5.9109 5.8542 5.7940 5.7305 5.6635 5.5932 5.5196 5.4426 5.3623 5.2787
5.1919 5.1018 5.0084 4.9119 4.8121 4.7091 4.6029 4.4935 4.3810 4.2654 4.1468 4.0251 3.9005 3.7731
3.6430 3.5102 3.3750 3.2375 3.0979 2.9565 2.8134 2.6690 2.5236 2.3777 2.2316 2.0857 1.9408 1.7974
1.6562 1.5181 1.3837 1.2540 1.1296 1.0115 0.9007 0.7982 0.7050 0.6220 0.5499 0.4893 0.4402 0.4022
0.3742 0.3547 0.3414 0.3319 0.3238 0.3158 0.3079 0.2999 0.2920 0.2840 0.2761 0.2681 0.2601 0.2522
0.2442 0.2363 0.2283 0.2203 0.2124 0.2044 0.1964 0.1885 0.1805 0.1725 0.1645 0.1566 0.1486 0.1406
0.1326 0.1247 0.1167 0.1086 0.1015 0.0948 0.0882 0.0815 0.0748 0.0681 0.0614 0.0547 0.0480 0.0414
0.0347 0.0280 0.0213 0.0146 0.0081 0.0030 0.0004 0.0000
"""


def pinto_cam_lift(theta: np.ndarray) -> LiftCurve:
    """Ball (1988) App E: Pinto inlet cam lift on a 44 mm roller, 1 deg steps from -87 to +116
    deg, zero elsewhere; periodic cubic interpolating spline."""
    values = np.array(PINTO_APP_E.split(), dtype=float)
    assert values.size == 204
    deg = np.arange(-180, 180)
    lift = np.zeros(deg.size)
    lift[(deg >= -87) & (deg <= 116)] = values
    spline = make_interp_spline(np.radians(np.append(deg, 180)), np.append(lift, 0.0) * 1e-3,
                                k=3, bc_type="periodic")
    t = -np.pi + np.mod(theta + np.pi, 2 * np.pi)
    return LiftCurve(theta, spline(t), spline(t, 1), spline(t, 2), spline(t, 3))


def negated(lift: LiftCurve) -> LiftCurve:
    return LiftCurve(lift.theta, -lift.lift, -lift.d1, -lift.d2, -lift.d3)


# Ball (1988) App F.1.1 desmodromic valve lift: ramp end -> nose segments (theta_T deg, C1..C5 mm),
# segment 3 C4 taken as -0.08113 (the printed +0.08113 breaks velocity continuity).
APP_F_SEGMENTS = [(3.0, [.03700, 0.0, .04894, -.01224, 0.0]),
                  (8.0, [.35969, .52204, 0.0, 0.0, 0.0]),
                  (5.0, [.87736, .20392, 0.0, -.08113, .02828]),
                  (5.0, [1.10212, 0.0, -.04167, .02153, -.00490]),
                  (34.0, [7.06324, -2.07447, -1.44115, .34428, .00640])]
APP_F_RAMP_HEIGHT = 0.3333            # mm
APP_F_RAMP_SLOPE = .03700 / 3.0       # mm/deg, the velocity at the start of segment 1


def desmo_lift(theta: np.ndarray) -> LiftCurve:
    """Symmetric multipol of App F with constant-velocity ramps, mm/deg -> m/rad."""
    x = np.degrees(np.abs(theta))
    sg = np.sign(theta)
    span = sum(t for t, _ in APP_F_SEGMENTS)
    z = span - x                               # degrees from the end of the ramp
    out = [np.zeros_like(x) for _ in range(4)]
    start, level = 0.0, APP_F_RAMP_HEIGHT
    for length, coef in APP_F_SEGMENTS:
        poly = Polynomial([level] + coef)
        inside = (z >= start) & (z <= start + length)
        u = (z[inside] - start) / length
        for order in range(4):
            out[order][inside] = poly.deriv(order)(u) / length ** order if order else poly(u)
        level, start = poly(1.0), start + length
    ramp = (z < 0) & (z > -APP_F_RAMP_HEIGHT / APP_F_RAMP_SLOPE)
    out[0][ramp] = APP_F_RAMP_HEIGHT + APP_F_RAMP_SLOPE * z[ramp]
    out[1][ramp] = APP_F_RAMP_SLOPE
    k = 180.0 / np.pi
    # d/dz -> d/dtheta: z = span - |theta|, so odd derivatives take the factor -sign(theta)
    return LiftCurve(theta, out[0] * 1e-3, -sg * out[1] * k * 1e-3, out[2] * k ** 2 * 1e-3,
                     -sg * out[3] * k ** 3 * 1e-3)


def pinto_nose_reference() -> dict[str, tuple[float, float]]:
    """Pinto nose r_c, R, V_c/omega, V_f/omega [mm] derived from the App E data alone.

    l'' at the nose comes from least-squares polynomial fits of the 4-decimal App E cam lift
    (1 deg steps, symmetric to 0.0002 mm) over windows of +-3 to +-5 deg and degrees 4 to 6;
    fits with fewer than two spare data points (interpolation in disguise) are left out. The
    reference is the widest, lowest-degree fit (+-5 deg, degree 4: l'' = -12.89 mm/rad^2), the
    tolerance the largest departure of any other fit of the family from it.

    With the inspection roller radius equal to r_f the pad centre Q runs on the roller's pitch
    curve, so the nose follows from plane geometry without the follower kinematics: the pitch
    radius at the apex is rho = r^2 / (r - l''), r = r_B + r_i + l_max; r_c = rho - r_f;
    1/R = 1/r_c + 1/r_f. At maximum valve lift gamma' = 0, so |dQ/dphi'| = |OQ| = r and Dyson's
    (Ball App A.12, A.15, A.17) V_c/omega = r r_c / rho, V_f/omega = r_f (1 - r / rho).

    Returns {name: (reference, tolerance)} in mm.
    """
    lift = np.array(PINTO_APP_E.split(), dtype=float)
    deg = np.arange(-87.0, 117.0)
    r_b, r_f = 15.0, 44.0

    def nose(window: int, degree: int) -> np.ndarray:
        inside = np.abs(deg) <= window
        c = np.polynomial.polynomial.polyfit(np.radians(deg[inside]), lift[inside], degree)
        r = r_b + r_f + c[0]
        rho = r * r / (r - 2.0 * c[2])
        r_c = rho - r_f
        return np.array([r_c, r_c * r_f / (r_c + r_f), r * r_c / rho, r_f * (1.0 - r / rho)])

    ref = nose(5, 4)
    family = [nose(w, d) for w in (3, 4, 5) for d in (4, 5, 6) if 2 * w + 1 >= d + 3]
    tol = np.max(np.abs(np.array(family) - ref), axis=0)
    names = ("cam_radius", "equivalent_radius", "v_cam", "v_follower")
    return {n: (float(v), float(t)) for n, v, t in zip(names, ref, tol, strict=True)}
