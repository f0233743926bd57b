"""General polynomial / polydyne law (Teodorescu et al. 2005 eqs. 18-19, minus-sign reading)."""
from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from _lift_cases import problem, teodorescu_law

from camtrain.errors import InputError
from camtrain.lift import DEG, MM, PolynomialLift, Ramps, polydyne_coefficients

EXPONENTS = [2, 8, 14, 20, 26]


def test_teodorescu_coefficients_are_the_exact_fractions():
    """C = [455, -455, 390, -182, 35] / 243 (derived exactly from eq. 18); the float
    formula must agree to round-off (1e-13)."""
    exact = [Fraction(455, 243), Fraction(-455, 243), Fraction(130, 81), Fraction(-182, 243),
             Fraction(35, 243)]
    np.testing.assert_allclose(polydyne_coefficients(EXPONENTS), [float(f) for f in exact],
                               rtol=1e-13)
    assert float(sum(exact)) == 1.0


def test_teodorescu_derived_kinematics():
    """Per unit x0 and per unit alpha (derived from eqs. 18-19, 5-6 significant figures):
    x''(0) = -3.74486; peak x'' = +8.38656 at |alpha| = 0.80883; x'' = 0 and peak |x'| =
    1.86007 at |alpha| = 0.58481. Tolerances are half a unit of the last printed digit."""
    law = teodorescu_law()
    tp, x0 = law.half_period, law.rise
    alpha = np.linspace(0.0, 1.0, 200001)
    c = law.evaluate(alpha * tp)
    xpp, xp = c.d2 * tp**2 / x0, c.d1 * tp / x0
    assert xpp[0] == pytest.approx(-3.74486, abs=5e-6)
    i = np.argmax(xpp)
    assert xpp[i] == pytest.approx(8.38656, abs=5e-6)
    assert alpha[i] == pytest.approx(0.80883, abs=1e-5)
    k = np.argmax(np.abs(xp))
    assert abs(xp[k]) == pytest.approx(1.86007, abs=5e-6)
    assert alpha[k] == pytest.approx(0.58481, abs=1e-5)


def test_polydyne_is_smooth_against_the_base_circle():
    """The k = 5 polydyne has its first four derivatives zero at |alpha| = 1 (the minus-sign
    form; the printed plus sign would give 2 x0 there). Lift, d1, d2, d3 at the event end are
    zero to round-off of sums of O(1) terms (1e-12 of the peaks)."""
    law = teodorescu_law()
    c = law.evaluate(np.array([60 * DEG - 1e-14, -60 * DEG + 1e-14, 0.0]))
    assert c.lift[2] == pytest.approx(9 * MM)
    peaks = [np.max(np.abs(getattr(law.evaluate(np.linspace(-1.1, 1.1, 2001)), k)))
             for k in ("lift", "d1", "d2", "d3")]
    for k, name in enumerate(("lift", "d1", "d2", "d3")):
        assert np.all(np.abs(getattr(c, name)[:2]) < 1e-10 * peaks[k])


def test_explicit_coefficients_and_ramps():
    """Giving the polydyne coefficients explicitly reproduces the default; ramps add their
    height below the polynomial (peak = ramp + rise)."""
    a = PolynomialLift(60 * DEG, 9 * MM, EXPONENTS, polydyne_coefficients(EXPONENTS))
    theta = np.linspace(-1.2, 1.2, 101)
    np.testing.assert_allclose(a.evaluate(theta).lift, teodorescu_law().evaluate(theta).lift,
                               atol=1e-15)
    r = PolynomialLift(60 * DEG, 9 * MM, EXPONENTS, ramps=Ramps(0.3 * MM, 20 * DEG))
    assert r.max_lift / MM == pytest.approx(9.3)
    assert r.closing_angle / DEG == pytest.approx(80.0)


@pytest.mark.parametrize("kwargs, path", [
    ({"exponents": [2, 8, 8]}, "lift.polynomial.exponents"),
    ({"exponents": [1, 8, 14]}, "lift.polynomial.exponents[0]"),
    ({"exponents": [2, 2.5, 14]}, "lift.polynomial.exponents[1]"),
    ({"exponents": [2, 8], "coefficients": [1.0, 0.5]}, "lift.polynomial.coefficients"),
    ({"exponents": [2, 8], "coefficients": [1.0]}, "lift.polynomial.coefficients"),
    ({"exponents": [2, 4], "coefficients": [-1.0, 2.0]}, "lift.polynomial.exponents"),
    ({"half_period": 0.0}, "lift.polynomial.half_period"),
    ({"half_period": 190 * DEG}, "lift.polynomial.half_period"),
    ({"ramps": Ramps(0.3 * MM, 20 * DEG, 0.4 * MM)}, "lift.ramps.closing_height"),
])
def test_bad_input_names_the_field(kwargs, path):
    args = {"half_period": 60 * DEG, "rise": 9 * MM, "exponents": EXPONENTS, **kwargs}
    with pytest.raises(InputError) as err:
        PolynomialLift(**args)
    assert problem(err.value).path == path
