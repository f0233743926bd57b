"""Cycle-mean friction power of the shipped decks against the published values.

Sources: Ball (1988) Fig 5.9 (Rover, 58.78 W), Fig 5.15 (Pinto, 166.14 W), Fig 5.22 (Pinto
improved, 160.89 W), all at 2500 rpm; Yang (1992) §4.3 (Zeta intake, 39.68 W per cam, 1500 rpm).
Ball's decks follow his stated definitions: the "entraining velocity" is the sum V_c + V_f; the
valve clearance, which he does not state for these trains, is his template's 0.4 mm.
Tolerance 15 % for Ball: the (docs/references/ball1988.md §4.5) shows his printed numbers depend on
unstated choices (base-circle contact, follower inertia) by 2-15 %. The Pinto trains are the
most sensitive to the unstated clearance (App E's ramps lift the valve only about 0.45 mm), so
for them the test is that Ball's value lies between camtrain's results at 0.4 mm and at zero
clearance. Zeta 2 %: Yang states all his inputs and camtrain follows his model. camtrain's own
values are not pinned here: the golden files (tests/golden, with the zero-clearance variants)
hold them; docs/examples.md tabulates every Ball target under both entrainment conventions and
both clearances, docs/references/ the published values.
"""
from __future__ import annotations

import tomllib

import pytest
import tomli_w

from camtrain import api
from tests.tribology.conftest import DECKS

CASES = {   # deck: (published W, tolerance vs published)
    "rover_2300_rocker": (58.78, 0.15),      # Ball (1988) Fig 5.9
    "pinto_finger": (166.14, 0.15),          # Ball (1988) Fig 5.15
    "zeta_intake": (39.68, 0.02),            # Yang (1992) §4.3
}
#: deck: published W (Ball 1988 Figs 5.15, 5.22)
CLEARANCE_BRACKETS = {
    "pinto_finger": 166.14,
    "pinto_finger_improved": 160.89,
}


@pytest.fixture(scope="module")
def runs():
    names = list(CASES) + [n for n in CLEARANCE_BRACKETS if n not in CASES]
    return {name: api.run(str(DECKS / f"{name}.toml")) for name in names}


@pytest.mark.parametrize("name", list(CASES))
def test_power_loss_against_source(runs, name):
    published, tol = CASES[name]
    p = runs[name].metrics["power_loss_mean"].value
    assert p == pytest.approx(published, rel=tol)


@pytest.mark.parametrize("name", list(CLEARANCE_BRACKETS))
def test_pinto_power_between_the_clearance_limits(runs, name):
    """Ball's Pinto losses lie between camtrain's at his template clearance (0.4 mm, the deck)
    and at zero clearance. The improved design is -17.8 % at 0.4 mm, outside the 15 % of the
    other decks: its unstated clearance and follower inertia are as uncertain as the datum's."""
    published = CLEARANCE_BRACKETS[name]
    p = runs[name].metrics["power_loss_mean"].value
    raw = tomllib.loads((DECKS / f"{name}.toml").read_text(encoding="utf-8"))
    raw["clearance"]["valve_clearance"] = 0.0
    zero = api.run(api.loads(tomli_w.dumps(raw), name)).metrics["power_loss_mean"].value
    assert p < published < zero


def test_improved_pinto_loses_less(runs):
    """Ball §5.5: the improved design gives a 'small decrease' (166.14 -> 160.89 W, -3.2 %);
    camtrain: -9.3 %, the same direction."""
    datum = runs["pinto_finger"].metrics["power_loss_mean"].value
    improved = runs["pinto_finger_improved"].metrics["power_loss_mean"].value
    assert improved < datum
    assert 1.0 - improved / datum < 0.15


@pytest.mark.parametrize("name", ["rover_2300_rocker", "pinto_finger", "pinto_finger_improved"])
def test_ball_decks_use_the_template_clearance(runs, name):
    """0.4 mm (Ball's template default, as the Harrison deck): the base circle is unloaded."""
    res = runs[name]
    seated = res["valve_lift"] <= 0.4e-3
    assert seated.any() and (res["load"][seated] == 0.0).all()
    assert (res["power_loss"][seated] == 0.0).all()


BALL_DECKS = ("harrison_flat", "rover_2300_rocker", "pinto_finger", "pinto_finger_improved",
              "desmo_rig", "pinto_camshaft")


@pytest.mark.parametrize("name", BALL_DECKS)
def test_ball_decks_follow_balls_entrainment_definition(name):
    """Ball (1988) Ch 3/5: the 'entraining velocity' is the sum V_c + V_f; his decks use it."""
    assert api.load(DECKS / f"{name}.toml").model.tribology.entrainment == "sum"


def test_new_decks_default_to_the_mean_entrainment():
    """The physically standard mean (V_c + V_f)/2 stays camtrain's default."""
    from tests.conftest import MINIMAL_DECK

    assert api.loads(MINIMAL_DECK).model.tribology.entrainment == "mean"
