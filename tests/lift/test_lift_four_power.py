"""Ball's four-power polynomial on Harrison's data (Ball 1988 §5.2, template Fig 4.5f)."""
from __future__ import annotations

import numpy as np
import pytest
from _lift_cases import problem

from camtrain.errors import InputError
from camtrain.lift import DEG, MM, FourPowerLift, Ramps
from camtrain.lift.four_power import HARRISON

TEMPLATE_C = [-11.692 * MM, 2.8499 * MM, -0.58946 * MM, 0.53140 * MM]   # rounded, Fig 4.5f


def test_harrison_coefficients_sum_to_minus_lcmax():
    """Sum C = -8.9000000 mm (Ball §5.2 coefficients, 7 decimals: exact to 1e-7 mm)."""
    assert sum(HARRISON["coefficients"]) / MM == pytest.approx(-8.9, abs=1e-7)


def test_harrison_end_of_event_meets_the_ramp():
    """At phi_T the lift is the ramp height 0.5 mm, the velocity the ramp slope 0.5 mm / 25 deg
    = 0.02 mm/deg, the acceleration ~0 (Ball §5.2; derived from the coefficients: sum
    n C_n = -1.2 mm, sum n(n-1) C_n = 1.6e-5 mm). Tolerances: 1e-7 mm and 1e-8 mm/deg are the
    round-off of the 7-decimal coefficients; 2e-5 mm/rad^2 covers the printed 1.6e-5 mm
    residual divided by phi_T^2 = 1.097."""
    law = FourPowerLift.harrison()
    end = law.end_conditions()
    assert end["lift"] / MM == pytest.approx(0.5, abs=1e-7)
    assert end["d1"] / MM * DEG == pytest.approx(-0.02, abs=1e-8)
    assert abs(end["d2"] / MM) < 2e-5
    # the law itself, on both flanks, just inside and on the ramp
    c = law.evaluate(np.array([-60 * DEG, 60 * DEG, -70 * DEG, 70 * DEG, -84.9 * DEG]))
    np.testing.assert_allclose(c.lift[:2] / MM, 0.5, atol=1e-7)
    np.testing.assert_allclose(c.d1 / MM * DEG, [0.02, -0.02, 0.02, -0.02, 0.02], atol=1e-8)
    np.testing.assert_allclose(c.lift[2:] / MM, [0.3, 0.3, 0.002], atol=1e-9)


def test_harrison_peak_and_nose_curvature():
    """Peak 9.40 mm (Fig 5.1 "Maximum Valve Lift (mm) = 9.40"); l''(0) = 2 C_p / phi_T^2 =
    -21.3234 mm/rad^2 (derived). Both exact up to printed digits."""
    law = FourPowerLift.harrison()
    c = law.evaluate(np.array([0.0]))
    assert law.max_lift / MM == pytest.approx(9.40, abs=1e-12)
    assert c.lift[0] / MM == pytest.approx(9.40, abs=1e-12)
    assert c.d2[0] / MM == pytest.approx(-21.3234, abs=5e-5)
    assert law.opening_angle / DEG == pytest.approx(-85.0)
    assert law.closing_angle / DEG == pytest.approx(85.0)


def test_template_rounded_coefficients_are_accepted():
    """The template prints 5 significant figures; their sum misses -8.9 mm by 0.16 um, inside
    the 1 um default tolerance, and the peak moves by nothing (it is Y_R + l_cmax)."""
    law = FourPowerLift.harrison(coefficients=TEMPLATE_C)
    assert law.max_lift / MM == pytest.approx(9.40)
    lift_step = [j for j in law.joint_jumps() if j.label == "polynomial / closing ramp"][0].lift
    assert abs(lift_step) / MM < 2e-4


def test_harrison_joint_report():
    """Velocity is continuous at the polynomial ends (Harrison's design) but jerk is not:
    sum n(n-1)(n-2) C_n = -5664 mm gives a jerk step of 5664 / 60^3 = 0.0262 mm/deg^3 (derived)."""
    jumps = {j.label: j.in_mm_deg() for j in FourPowerLift.harrison().joint_jumps()}
    assert jumps["opening ramp start"]["d1_mm_per_deg"] == pytest.approx(0.02, rel=1e-6)
    end = jumps["polynomial / closing ramp"]
    assert abs(end["d1_mm_per_deg"]) < 1e-9
    assert end["d3_mm_per_deg3"] == pytest.approx(5664.0 / 60.0**3, rel=1e-3)


@pytest.mark.parametrize("change, path, words", [
    ({"coefficients": [c * 1.01 for c in HARRISON["coefficients"]]},
     "lift.four_power.coefficients", "mm"),
    ({"ramps": Ramps(0.5 * MM, 25 * DEG, 0.6 * MM, 25 * DEG)}, "lift.ramps.closing_height", "mm"),
    ({"ramps": Ramps(0.5 * MM, 0.0)}, "lift.ramps.opening_length", "deg"),
    ({"ramps": Ramps(0.5 * MM, -5 * DEG)}, "lift.ramps.opening_length", "deg"),
    ({"exponents": (2.0, 9.0, 78.0, 78.0)}, "lift.four_power.exponents", "distinct"),
    ({"exponents": (1.5, 9.0, 78.0, 80.0)}, "lift.four_power.exponents[0]", "2 or"),
    ({"exponents": (2.0, 9.0, 78.0)}, "lift.four_power.exponents", "4 values"),
    ({"half_period": 170 * DEG}, "lift.four_power.half_period", "360 deg"),
    ({"half_period": float("nan")}, "lift.four_power.half_period", "finite"),
    ({"rise": -1.0}, "lift.four_power.max_lift", "mm"),
])
def test_bad_input_names_the_field(change, path, words):
    with pytest.raises(InputError) as err:
        FourPowerLift.harrison(**change)
    p = problem(err.value)
    assert p.path == path
    assert words in err.value.render()


def test_path_prefix_is_used():
    with pytest.raises(InputError) as err:
        FourPowerLift.harrison(rise=0.0, path="valves.inlet.lift")
    assert problem(err.value).path == "valves.inlet.lift.four_power.max_lift"
