"""The spline lift form: a B-spline of the deck's knots and coefficients."""
from __future__ import annotations

import numpy as np
import pytest
from _lift_cases import problem, spline_bump
from scipy.interpolate import BSpline

from camtrain.errors import InputError
from camtrain.lift import DEG, MM, SplineLift


def test_values_are_the_b_spline_and_zero_outside():
    law = spline_bump()
    theta = np.linspace(-59.0, 59.0, 237) * DEG
    ref = BSpline(law.knots, law.coefficients, 5)
    c = law.evaluate(theta)
    for k, name in enumerate(("lift", "d1", "d2", "d3")):
        assert np.allclose(getattr(c, name), ref(theta, nu=k), rtol=1e-12, atol=1e-15)
    out = law.evaluate(np.array([-90.0, 61.0, 170.0]) * DEG)
    assert not np.any(out.lift) and not np.any(out.d3)


@pytest.mark.derived
def test_quintic_spline_is_c4_across_its_knots():
    """de Boor (2001): degree 5 on simple knots is four times continuously differentiable; the
    one-sided jerk limits at each knot agree to round-off (jump / step -> the fourth
    derivative, bounded)."""
    law = spline_bump()
    for angle, _ in law.joints():
        for eps in (1e-6, 1e-8):
            left = law.evaluate(np.array([angle - eps * DEG]))
            right = law.evaluate(np.array([angle + eps * DEG]))
            assert abs(right.d3[0] - left.d3[0]) < 1e-3 * eps * MM / DEG ** 3


def test_deck_units_round_trip():
    law = spline_bump()
    deck = law.in_deck_units()
    again = SplineLift(np.array(deck["knots"]) * DEG, np.array(deck["coefficients"]) * MM,
                       deck["degree"])
    theta = np.linspace(-np.pi, np.pi, 361)
    assert np.allclose(again.evaluate(theta).lift, law.evaluate(theta).lift, atol=1e-15)


@pytest.mark.parametrize("knots, coefficients, field", [
    ([-1, -1, -1, -1, -1, -1, 0, 1, 1, 1, 1, 1, 1], [0, 1, 2, 2, 1, 0], "knots"),
    ([-1, -1, -1, -1, -1, -1, 1, 1, 1, 1, 1, 1], [0, 1, 2, 1, 1, 1], "coefficients"),
    ([-1, -1, -1, -1, -1, 0.5, 0, 1, 1, 1, 1, 1, 1], [0, 1, 2, 3, 2, 1, 0], "knots"),
    ([1, 1, 1, 1, 1, 1, 2, 3, 3, 3, 3, 3, 3], [0, 1, 2, 3, 2, 1, 0], "knots"),
    ([-1, -1, -1, -1, -1, -1, 0, 1, 1, 1, 1, 1, 1], [0, -1, -2, -3, -2, -1, 0],
     "coefficients"),
])
def test_bad_spline_names_its_field(knots, coefficients, field):
    with pytest.raises(InputError) as exc:
        SplineLift(np.array(knots) * 20 * DEG, np.array(coefficients) * MM, 5)
    assert problem(exc.value).path == f"lift.spline.{field}"
