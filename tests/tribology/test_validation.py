"""Cycle-mean friction power of the shipped decks against the published values.

Sources: Ball (1988) Fig 5.9 (Rover, 58.78 W), Fig 5.15 (Pinto, 166.14 W), Fig 5.22 (Pinto
improved, 160.89 W), all at 2500 rpm; Yang (1992) §4.3 (Zeta intake, 39.68 W per cam, 1500 rpm).
Tolerance 15 % for Ball: the reference extraction (§4.5) shows his printed numbers depend on
unstated choices (entrainment convention, base-circle contact, follower inertia) by 2-15 %, and
camtrain uses the mean entrainment and the 0.4 mm template clearance throughout. Zeta 2 %: Yang
states all his inputs and camtrain follows his model. Each test also pins camtrain's own value
(1 %) so that a model change shows up; docs/tribology.md explains every residual.
"""
from __future__ import annotations

import pytest

from camtrain import api
from tests.tribology.conftest import DECKS

CASES = {   # deck: (published W, camtrain W at the time of writing, tolerance vs published)
    "rover_2300_rocker": (58.78, 57.98, 0.15),
    "pinto_finger": (166.14, 153.25, 0.15),
    "pinto_finger_improved": (160.89, 140.68, 0.15),
    "zeta_intake": (39.68, 39.62, 0.02),
}


@pytest.fixture(scope="module")
def runs():
    return {name: api.run(str(DECKS / f"{name}.toml")) for name in CASES}


@pytest.mark.parametrize("name", list(CASES))
def test_power_loss_against_source(runs, name):
    published, ours, tol = CASES[name]
    p = runs[name].metrics["power_loss_mean"].value
    assert p == pytest.approx(published, rel=tol)
    assert p == pytest.approx(ours, rel=0.01)


def test_improved_pinto_loses_less(runs):
    """Ball §5.5: the improved design gives a 'small decrease' (166.14 -> 160.89 W, -3.2 %);
    camtrain: -8.2 %, the same direction."""
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
