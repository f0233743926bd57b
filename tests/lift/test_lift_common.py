"""Properties every lift law must have: periodicity, symmetry, derivatives that are derivatives.

These are self-consistency checks, not published numbers; tolerances follow from the numerics
stated in each docstring.
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest
from _lift_cases import analytic_laws, away_from_joints, problem
from hypothesis import given, settings
from hypothesis import strategies as st

from camtrain.errors import InputError
from camtrain.lift import (
    DEG,
    MM,
    REGISTRY,
    LiftCurve,
    LiftLaw,
    PolynomialLift,
    TableLift,
    angle_grid,
    evaluate_on_grid,
)

LAWS = analytic_laws()
NAMES = sorted(LAWS)


def test_registry_names_the_eight_forms():
    assert set(REGISTRY) == {"four_power", "multipol", "table", "exp_poly", "polynomial",
                             "williams_elementary", "williams_low_jerk", "spline"}
    for form, cls in REGISTRY.items():
        assert issubclass(cls, LiftLaw) and cls.form == form


@pytest.mark.parametrize("name", NAMES)
def test_grid_evaluation_shape_and_base_circle(name):
    """evaluate_on_grid returns a LiftCurve on angle_grid; base circle is exactly zero."""
    law, _ = LAWS[name]
    curve = evaluate_on_grid(law, 720)
    assert isinstance(curve, LiftCurve)
    np.testing.assert_array_equal(curve.theta, angle_grid(720))
    off = (curve.theta < law.opening_angle - 1e-9) | (curve.theta > law.closing_angle + 1e-9)
    assert off.any()
    for arr in (curve.lift, curve.d1, curve.d2, curve.d3):
        assert np.all(np.isfinite(arr))
        assert np.all(arr[off] == 0.0)
    assert law.event_angle < 2 * np.pi
    assert curve.max_lift == pytest.approx(law.max_lift, rel=1e-4)


@pytest.mark.parametrize("name", NAMES)
def test_periodic_over_one_revolution(name):
    """theta and theta + 2 pi k give the same values (to 1e-9 of each peak: the angle shift
    moves theta by ~1e-15 rad). The grid is offset so no angle sits exactly on a joint, where
    the two one-sided values may legitimately differ."""
    law, _ = LAWS[name]
    theta = np.linspace(-np.pi, np.pi, 1001) + 1.234e-3
    a, b, c = law.evaluate(theta), law.evaluate(theta + 2 * np.pi), law.evaluate(theta - 4 * np.pi)
    for k in ("lift", "d1", "d2", "d3"):
        scale = np.max(np.abs(getattr(a, k))) + 1e-30
        np.testing.assert_allclose(getattr(b, k), getattr(a, k), atol=1e-9 * scale)
        np.testing.assert_allclose(getattr(c, k), getattr(a, k), atol=1e-9 * scale)


@pytest.mark.parametrize("name", [n for n in NAMES if LAWS[n][1]])
def test_symmetric_laws_give_even_lift_and_odd_velocity(name):
    """Symmetric laws: lift and d2 even, d1 and d3 odd in theta (to 1e-9 of each peak). The
    nose itself is left out: there a law's one-sided values differ by its (tiny) nose jump."""
    law, _ = LAWS[name]
    theta = np.linspace(1e-3, np.pi, 777)
    p, m = law.evaluate(theta), law.evaluate(-theta)
    for k, sign in (("lift", 1), ("d1", -1), ("d2", 1), ("d3", -1)):
        scale = np.max(np.abs(getattr(p, k)))
        np.testing.assert_allclose(getattr(m, k), sign * getattr(p, k), atol=1e-9 * scale)


@pytest.mark.parametrize("name", [n for n in NAMES if not LAWS[n][1]])
def test_asymmetric_laws_are_asymmetric(name):
    law, _ = LAWS[name]
    theta = np.linspace(0.1, 1.2, 50)
    assert np.max(np.abs(law.evaluate(theta).lift - law.evaluate(-theta).lift)) > 1e-6


def _derivative_check(law, gap=2e-4, h=1e-5, rtol=2e-5):
    """Each analytic derivative matches a central difference of the one below it.

    The difference error is h^2/6 times the next derivative; with h = 1e-5 rad it is below
    1e-8 of the peak for every law here. Points closer than ``gap`` to a joint are skipped,
    because a difference across a joint measures the jump, not the derivative; the App 1
    polynomial's jerk varies like t^0.35 near its start, which the 2e-5 relative bound covers.
    """
    theta = away_from_joints(law, np.linspace(law.opening_angle, law.closing_angle, 3001), gap)
    c, plus, minus = law.evaluate(theta), law.evaluate(theta + h), law.evaluate(theta - h)
    for low, high in (("lift", "d1"), ("d1", "d2"), ("d2", "d3")):
        fd = (getattr(plus, low) - getattr(minus, low)) / (2 * h)
        exact = getattr(c, high)
        np.testing.assert_allclose(fd, exact, atol=rtol * np.max(np.abs(exact)),
                                   err_msg=f"{high} vs difference of {low}")


@pytest.mark.parametrize("name", NAMES)
def test_analytic_derivatives_match_finite_differences(name):
    law, _ = LAWS[name]
    _derivative_check(law)


def test_table_spline_derivatives_are_consistent():
    """The spline's derivatives are derivatives of its lift (same check, data-table law)."""
    _derivative_check(TableLift.dataset("pinto_inlet_cam"), gap=2e-4, rtol=2e-4)


def test_valid_input_raises_no_floating_point_warning():
    """Every law (tables too) evaluates a grid and its joint report with numpy raising on every
    floating-point event; the laws silence only the underflow of x^80 near the nose, locally,
    where zero is the true value."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with np.errstate(all="raise"):
            tables = [TableLift.dataset(n, method=m) for n in ("pinto_inlet_cam", "zeta_intake")
                      for m in ("spline", "central")]
            for law in [law for law, _ in LAWS.values()] + tables:
                law.evaluate(angle_grid(1440))
                law.joint_jumps()


@settings(max_examples=30, deadline=None)
@given(st.lists(st.integers(min_value=2, max_value=40), min_size=2, max_size=6, unique=True))
def test_polydyne_meets_the_base_circle_smoothly(exps):
    """Any distinct integer exponent set >= 2 that builds gives a polydyne that starts and ends
    at zero lift with zero velocity, acceleration (k >= 3) and jerk (k >= 4) at the event ends
    (Teodorescu et al. 2005 eq. 18: k-1 derivatives vanish). Tolerance 1e-9 of the peak."""
    try:
        law = PolynomialLift(50 * DEG, 5 * MM, exps)
    except InputError as exc:                    # some sets overshoot: they must say so clearly
        assert problem(exc).path == "lift.polynomial.exponents"
        return
    end = law.evaluate(np.array([50 * DEG - 1e-12]))
    assert abs(end.lift[0]) < 1e-9 * law.max_lift
    scales = [np.max(np.abs(getattr(law.evaluate(angle_grid(2000)), k))) for k in ("d1", "d2",
                                                                                      "d3")]
    for order in range(1, min(len(exps), 4)):
        value = getattr(end, f"d{order}")[0]
        assert abs(value) < 1e-6 * scales[order - 1]
