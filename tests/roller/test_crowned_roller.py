"""A crowned turning roller (mechanism.roller.crown_radius with [roller]): the cam-roller contact
is the Hertz ellipse, with the point-contact film, the Barus shear over the ellipse and the
rolling resistance on its slices (camtrain.roller.traction)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain import api
from camtrain.formulas import ball_1988_shear_force, hertz_line, hertz_point, yang_1992_shear_force
from camtrain.roller.traction import goksem_hargreaves_ellipse_rolling, goksem_hargreaves_rolling
from tests.roller.conftest import DECKS

FINGER = DECKS / "roller_finger.toml"
QUASI = ("roller.solver=quasi_static",)


@pytest.fixture(scope="module")
def runs():
    straight = api.run(api.load(FINGER, QUASI))
    crowned = api.run(api.load(FINGER, QUASI + ("mechanism.roller.crown_radius=500",)))
    flat = api.run(api.load(FINGER, QUASI + ("mechanism.roller.crown_radius=5000",)))
    return straight, crowned, flat


def test_a_crowned_roller_turns_on_an_elliptical_contact(runs):
    """The crowned finger roller runs with [roller]: the Hertz ellipse carries the load at a
    higher pressure than the straight roller's line, the roller still turns (its largest slip
    finite and below the straight roller's, whose traction is lower), and a 500 mm crown keeps
    the ellipse on the 9 mm contact width (no edge warning)."""
    straight, crowned, _ = runs
    assert crowned.metrics["hertz_max"].value > 1.5 * straight.metrics["hertz_max"].value
    assert "radius_y" in crowned.columns and "radius_y" not in straight.columns
    for name in ("roller_power_pin", "roller_power_rolling", "roller_power_sliding"):
        assert np.isfinite(crowned.metrics[name].value) and crowned.metrics[name].value >= 0.0
    assert 0.0 <= crowned.metrics["roller_slip_max"].value < \
        straight.metrics["roller_slip_max"].value
    assert not any("crowned roller" in w for w in crowned.warnings)


def test_a_crown_too_flat_for_the_load_is_reported(runs):
    """With a 5 m crown the ellipse grows longer than cam.width at the nose: a warning names the
    ellipse's length, the width and the field to change."""
    warning = next(w for w in runs[2].warnings if "crowned roller" in w)
    assert "cam.width (9 mm)" in warning and "mechanism.roller.crown_radius" in warning


@pytest.mark.derived
@pytest.mark.parametrize("crown", [1.0, 10.0, 1.0e3])
def test_crown_to_infinity_tends_to_the_line_contact_of_the_same_length(crown):
    """Crown radius -> infinity at a fixed load: the ellipse becomes slender (a_y/a_x 21, 77,
    950 here) and each of its sections across the rolling direction a line contact, but it does
    NOT become the line contact of its own length 2 a_y: it carries its load along its length as
    the parabola (3 W / 4 a_y)(1 - y^2/a_y^2), 3/2 of the mean at its centre, where the line
    contact carries W / 2 a_y uniformly. So the limits are, exactly: central pressure and
    half-width sqrt(3/2) = 1.2247 times the line contact's (reached as the complete elliptic
    integral E(e) -> 1: 1.2268, 1.2250, 1.22475 at these crowns); Newtonian shear area
    pi sqrt(3/2)/4 = 0.9619 of the line's; rolling resistance (3/2)^0.0126 B(1/2, 1.0126)/2 =
    0.99744 of the line's at any crown (its load exponent 0.0126 makes it nearly indifferent to
    how the load is spread)."""
    W, Rx, E, u, eta, alpha = 1000.0, 0.008, 2.27e11, 5.0, 0.05, 22e-9
    p = hertz_point(W, Rx, crown, E)
    length = 2.0 * p.a_y
    line = hertz_line(W, Rx, E, L=length)
    limit = math.sqrt(1.5)
    tol = {1.0: 3e-3, 10.0: 2e-4, 1.0e3: 3e-6}[crown]
    assert p.max_pressure / line.max_pressure == pytest.approx(limit, rel=tol)
    assert p.a_x / line.half_width == pytest.approx(limit, rel=tol)
    shear = (yang_1992_shear_force(1.0, 1.0, eta, 0.0, p.max_pressure, p.a_x, p.a_y)
             / ball_1988_shear_force(1.0, 1.0, eta, 0.0, line.max_pressure, line.half_width,
                                     length))
    assert shear == pytest.approx(math.pi * limit / 4.0, rel=tol)
    rolling = (goksem_hargreaves_ellipse_rolling(u, eta, alpha, E, Rx, p.a_y, W)
               / goksem_hargreaves_rolling(u, eta, alpha, E, Rx, length, W))
    slices = math.sqrt(math.pi) * math.gamma(1.0126) / math.gamma(1.5126)
    assert rolling == pytest.approx(1.5 ** 0.0126 * slices / 2.0, rel=1e-12)


def test_the_compiled_balance_takes_the_ellipse(monkeypatch):
    """Harrison's roller crowned (300 mm) on its needle pin, in a full film: the compiled
    quasi-static balance solves every loaded angle with the ellipse's area and film, and gives
    the array solve's speeds."""
    from camtrain.roller import solve

    deck = api.load(DECKS / "harrison_roller_needle.toml",
                    QUASI + ("mechanism.follower=roller", "mechanism.roller.crown_radius=300"))
    taken = []
    records = solve._compiled_records
    monkeypatch.setattr(solve, "_compiled_records",
                        lambda *a: taken.append(records(*a)) or taken[-1])
    compiled = np.asarray(api.run(deck).columns["roller_speed"].values)
    assert taken[-1] is not None and np.count_nonzero(taken[-1][0]) > 500
    monkeypatch.setattr(solve, "_compiled_records", lambda *a: None)
    array = np.asarray(api.run(deck).columns["roller_speed"].values)
    np.testing.assert_allclose(compiled, array, rtol=1e-12, atol=0.0)
