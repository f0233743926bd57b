"""The transient film's resolution knobs in `camtrain accuracy` (docs/transient_film.md)."""
from __future__ import annotations

import tomllib

import pytest

from camtrain.errors import InputError
from camtrain.study import accuracy as acc
from tests.conftest import DECKS
from tests.report.declarations import StoredPlan

#: the plan of a lubricated valve train (the knobs' tests on deck options narrow it)
CHAIN = StoredPlan("valve_train", ["kinematics", "loads", "hertz", "film", "friction", "power"])


def test_film_knobs_follow_the_film_model():
    flat = {"mechanism": {"type": "flat"}, "lift": {"form": "four_power"}}
    squeeze = dict(flat, tribology={"film_model": "squeeze"})
    level2 = dict(flat, tribology={"film_model": "averaged_reynolds"})
    assert acc.relevant_knobs(squeeze, CHAIN) == ["angle_points", "film_angle_step"]
    assert acc.relevant_knobs(level2, CHAIN) == ["angle_points", "film_angle_step", "film_nodes",
                                          "film_zone_width", "film_tolerance"]
    with pytest.raises(InputError, match="--knob"):
        acc.check_knobs(squeeze, ["film_nodes"], CHAIN)


def test_film_nodes_ladder_reports_error_against_cost():
    """A short film_nodes ladder on a coarse Göçmen deck: every rung runs, the film metrics are
    studied, and the error of the nose film falls as the nodes grow."""
    raw = tomllib.loads((DECKS / "gocmen_table31.toml").read_text())
    raw["solver"] = {"angle_points": 90}
    rep = acc.study_knob(raw, "film_nodes", 1e-3, ladder=(21, 41, 81))
    assert all(r["status"] == "ok" and r["wall_time"] > 0.0 for r in rep["rungs"])
    assert {"film_max", "film_at_zero_entrainment_1"} <= set(rep["metrics"])
    errors = rep["metrics"]["film_max"]["errors"]
    assert errors[0] > errors[1]
