"""Guide friction of the Zeta valve train against Yang (1992) §4.3 (Fig 4.7), 1500 rpm camshaft.

Yang prints the totals for 8 valve trains to two figures: 8 followers/guides 4.9 W, 8 valves/
guides 2.0 W, i.e. +-0.05 W, about 1 % and 2.5 %. camtrain uses Yang's own full-film Couette
model (eq. 3.29) with his C.3/C.4 data, so the only differences are the lift-table derivative
and rounding; tolerances: 2 % (followers) and 3 % (valves), just above the print resolution.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from camtrain.deck.load import load_deck
from camtrain.deck.schema import Guides
from camtrain.formulas import couette_guide_power, cycle_mean
from camtrain.runner import run_plan
from tests.tribology.conftest import DECKS

VALVES = 8


@pytest.fixture(scope="module")
def intake():
    return run_plan(load_deck(str(DECKS / "zeta_intake.toml")).model)


def test_yang_totals(intake):
    m = intake.metrics
    assert VALVES * m["follower_guide_power_mean"].value == pytest.approx(4.9, rel=0.02)
    assert VALVES * m["valve_guide_power_mean"].value == pytest.approx(2.0, rel=0.03)
    assert m["guide_power_mean"].value == pytest.approx(
        m["follower_guide_power_mean"].value + m["valve_guide_power_mean"].value)
    # guide losses are reported apart from the cam/follower contact
    assert m["power_loss_mean"].value == pytest.approx(39.62, rel=0.01)


def test_couette_closed_form(intake):
    """Mean of (eta pi d L / c) V^2 with V = omega dl/dtheta, recomputed from the columns."""
    w = 1500 * 2 * np.pi / 60
    v = intake["valve_velocity"] * w          # the column is dl_v/dtheta [m/rad]
    p = couette_guide_power(v, 0.009865, 6.043e-3, 36e-3, 0.02e-3)
    assert cycle_mean(p) == pytest.approx(intake.metrics["valve_guide_power_mean"].value,
                                          rel=1e-6)


def test_pivoted_follower_has_no_follower_guide():
    deck = load_deck(str(DECKS / "rover_2300_rocker.toml")).model
    g = Guides(follower_diameter=28.4e-3, follower_guide_length=22e-3,
               follower_guide_clearance=24e-6, valve_stem_diameter=6e-3,
               valve_guide_length=36e-3, valve_guide_clearance=20e-6)
    res = run_plan(replace(deck, guides=g))
    assert "valve_guide_power_mean" in res.metrics
    assert "follower_guide_power_mean" not in res.metrics
    assert any("pivoted follower has no guide" in w for w in res.warnings)
