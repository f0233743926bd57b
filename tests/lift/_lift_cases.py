"""Lift laws built from the published data sets, shared by the lift tests."""
from __future__ import annotations

import numpy as np

from camtrain.errors import InputError
from camtrain.lift import (
    DEG,
    MM,
    ElementaryHalf,
    ExpPolyLift,
    FourPowerLift,
    LowJerkHalf,
    MultipolLift,
    PolynomialLift,
    Ramps,
    SplineLift,
    WilliamsElementaryLift,
    WilliamsLowJerkLift,
)

ACC = MM / DEG**2            # 1 mm/deg^2 in m/rad^2
JERK = MM / DEG**3           # 1 mm/deg^3 in m/rad^3

# Williams (2013) App 1 low-jerk design (deg, fractions, mm)
APP1_T = [12.0, 16.0, 3.25, 1.0, 4.25, 0.125, 4.0, 6.5, 3.0, 2.0, 2.5, 50.0, 3.5]
APP1_EPS = [0.001, 0.4, 0.6, 1.0, 0.8, 0.25, 0.075]
APP1 = dict(lam=0.23, p=1.35, q=70.0, s1=0.24, L=9.25, F0=0.00445)


def app1_half(**changes) -> LowJerkHalf:
    T = changes.pop("T", APP1_T)
    eps = changes.pop("eps", APP1_EPS)
    kw = {**APP1, **changes}
    return LowJerkHalf([t * DEG for t in T], eps, kw["lam"], kw["p"], kw["q"], kw["s1"] * MM)


def app1_law(**kwargs) -> WilliamsLowJerkLift:
    return WilliamsLowJerkLift(app1_half(), APP1["L"] * MM, APP1["F0"] * ACC, **kwargs)


ELEMENTARY_T = [10.0, 8.0, 15.0, 12.0, 45.0]    # deg; an illustrative design, not published


def elementary_law() -> WilliamsElementaryLift:
    return WilliamsElementaryLift(ElementaryHalf([t * DEG for t in ELEMENTARY_T], 0.25 * MM),
                                  9.0 * MM)


def teodorescu_law() -> PolynomialLift:
    """Polydyne 2-8-14-20-26; x0 and duration are not published, 9 mm over +-60 deg is ours."""
    return PolynomialLift(60.0 * DEG, 9.0 * MM, [2, 8, 14, 20, 26])


def analytic_laws() -> dict[str, object]:
    """Every analytic law, with whether its lift is symmetric about the nose."""
    return {
        "four_power_harrison": (FourPowerLift.harrison(), True),
        "multipol_app_f": (MultipolLift.ball_desmo(), True),
        "exp_poly_rover": (ExpPolyLift.rover_2300(), False),
        "polydyne_teodorescu": (teodorescu_law(), True),
        "polynomial_with_ramps": (PolynomialLift(55.0 * DEG, 8.0 * MM, [2, 6, 10],
                                                 ramps=Ramps(0.3 * MM, 20.0 * DEG)), True),
        "williams_elementary": (elementary_law(), True),
        "williams_low_jerk": (app1_law(), True),
        "spline_bump": (spline_bump(), True),
        "williams_low_jerk_asym": (WilliamsLowJerkLift(
            app1_half(), 9.25 * MM, 0.00445 * ACC,
            closing=app1_half(s1=0.30, T=[12.0, 20.0] + APP1_T[2:])), False),
    }


def spline_bump() -> SplineLift:
    """A symmetric quintic B-spline over +-60 deg, 8 spans: lift, velocity, acceleration and
    jerk zero at both ends (four zero coefficients each side)."""
    inner = np.linspace(-60.0, 60.0, 9)
    knots = np.concatenate(([-60.0] * 5, inner, [60.0] * 5)) * DEG
    coefficients = np.array([0, 0, 0, 0, 1.0, 4.0, 8.0, 4.0, 1.0, 0, 0, 0, 0]) * MM
    return SplineLift(knots, coefficients, 5)


def problem(exc: InputError):
    """The single problem carried by an InputError."""
    assert len(exc.problems) == 1
    return exc.problems[0]


def away_from_joints(law, theta: np.ndarray, gap: float) -> np.ndarray:
    """Angles of ``theta`` farther than ``gap`` [rad] from every joint (and the event ends)."""
    marks = [a for a, _ in law.joints()] + [law.opening_angle, law.closing_angle]
    keep = np.ones(theta.shape, bool)
    for a in marks:
        d = np.abs(np.mod(theta - a + np.pi, 2 * np.pi) - np.pi)
        keep &= d > gap
    return theta[keep]
