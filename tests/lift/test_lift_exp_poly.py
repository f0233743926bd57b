"""Exponential-polynomial fit of Lim et al. (1983), Rover 2300 cam (Ball 1988 §5.3)."""
from __future__ import annotations

import numpy as np
import pytest
from _lift_cases import problem

from camtrain.errors import InputError
from camtrain.lift import DEG, MM, ExpPolyLift
from camtrain.lift.exp_poly import ROVER_2300, exp_poly_lift

# (deg, mm): derived from the printed coefficients; the nose value
# matches Ball's printed "Maximum Valve Lift 10.15"
PUBLISHED = [(0.0, 10.1463), (30.0, 5.7024), (-30.0, 5.9127), (45.0, 1.8158), (-45.0, 1.9704)]


@pytest.mark.parametrize("deg, mm", PUBLISHED)
def test_rover_fit_values(deg, mm):
    """The fitted function at 0, +-30, +-45 deg; the values are printed to 4 decimals, so the
    tolerance is half a unit of the last digit."""
    assert exp_poly_lift(np.array(deg * DEG), ROVER_2300) / MM == pytest.approx(mm, abs=5e-5)


def test_law_keeps_the_nose_and_stays_within_the_cutoff_of_the_fit():
    """Shift blend: the nose lift is exactly the fit's, and elsewhere the law is below the fit by
    at most the cut-off (1e-4 mm), which bounds its difference from the published values."""
    law = ExpPolyLift.rover_2300()
    theta = np.array([d for d, _ in PUBLISHED]) * DEG
    lift = law.evaluate(theta).lift / MM
    fit = exp_poly_lift(theta, ROVER_2300) / MM
    assert lift[0] == pytest.approx(10.1463, abs=5e-5)
    assert lift[0] == pytest.approx(fit[0], abs=1e-12)
    assert np.all((fit - lift >= 0.0) & (fit - lift <= 1e-4))
    assert law.max_lift / MM == pytest.approx(10.1463, abs=5e-5)


def test_cutoff_angles_and_small_derivative_steps():
    """The event ends where the fit falls to the cut-off (the fit is < 0.01 mm by about
    70 deg, 1e-4 mm near 80 deg). The shift blend leaves a continuous lift and velocity and
    acceleration steps of < 1e-4 mm/deg and < 1e-4 mm/deg^2, four orders below the peaks."""
    law = ExpPolyLift.rover_2300()
    for angle in (law.opening_angle, law.closing_angle):
        assert exp_poly_lift(angle, ROVER_2300) / MM == pytest.approx(1e-4, rel=1e-9)
        assert 75.0 < abs(angle) / DEG < 85.0
    for j in law.joint_jumps():
        e = j.in_mm_deg()
        assert abs(e["lift_mm"]) < 1e-9
        assert 0.0 < abs(e["d1_mm_per_deg"]) < 1e-4
        assert abs(e["d2_mm_per_deg2"]) < 1e-4


def test_hard_blend_reproduces_the_fit_with_a_lift_step():
    law = ExpPolyLift.rover_2300(blend="hard")
    theta = np.array([30.0, -45.0]) * DEG
    np.testing.assert_allclose(law.evaluate(theta).lift, exp_poly_lift(theta, ROVER_2300),
                               rtol=1e-14)
    steps = [j.lift / MM for j in law.joint_jumps()]
    np.testing.assert_allclose(np.abs(steps), 1e-4, rtol=1e-3)


def test_rover_is_asymmetric_and_derivatives_at_nose():
    """Odd coefficients make the curve asymmetric; at the nose d1 = f(0) a1 and
    d2 = f(0)(2 a2 + a1^2) (analytic derivatives of exp; hard blend, so no cut-off scaling;
    checked to round-off)."""
    law = ExpPolyLift.rover_2300(blend="hard")
    c = law.evaluate(np.array([0.0]))
    f0, a1, a2 = c.lift[0], ROVER_2300[1], ROVER_2300[2]
    assert c.d1[0] == pytest.approx(f0 * a1, rel=1e-12)
    assert c.d2[0] == pytest.approx(f0 * (2 * a2 + a1 * a1), rel=1e-12)


@pytest.mark.parametrize("kwargs, path", [
    ({"cutoff": 20 * MM}, "lift.exp_poly.cutoff"),
    ({"cutoff": -1.0}, "lift.exp_poly.cutoff"),
    ({"blend": "soft"}, "lift.exp_poly.blend"),
    ({"coefficients": [2.3, 0.0, -1.5, 0.0, 0.3]}, "lift.exp_poly.coefficients"),
    ({"coefficients": [2.3, 0.0, -0.01]}, "lift.exp_poly.coefficients"),
    ({"coefficients": [2.3, float("nan"), -1.5]}, "lift.exp_poly.coefficients[1]"),
])
def test_bad_input_names_the_field(kwargs, path):
    kwargs.setdefault("coefficients", ROVER_2300)
    with pytest.raises(InputError) as err:
        ExpPolyLift(**kwargs)
    assert problem(err.value).path == path
