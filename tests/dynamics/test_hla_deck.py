"""The [dynamics.lash_adjuster] deck section: a run of the shipped adjuster deck, the adjuster
at the pivot of an end-pivoted finger follower, deck checks and the leak-down command."""
from __future__ import annotations

import json
import tomllib

import pytest

from tests.conftest import DECKS

ADJUSTER = {"plunger_diameter": 11.0, "radial_clearance": 4.0, "leak_length": 6.0,
            "chamber_volume": 150.0, "stroke": 2.5, "rest_extension": 0.6,
            "plunger_mass": 0.008, "supply_pressure": 2.5}


def _finger_with_adjuster(location="pivot"):
    raw = tomllib.loads((DECKS / "pinto_finger.toml").read_text(encoding="utf-8"))
    raw["clearance"] = {"lash_adjuster": True}
    raw["dynamics"] = {"follower_mass": 0.03, "contact_stiffness": 2.0e5,
                       "rocker_stiffness": 2.0e4, "seat_stiffness": 2.0e5,
                       "lash_adjuster": dict(ADJUSTER, location=location)}
    return raw


def test_adjuster_at_the_pivot_of_a_finger_follower_is_referred_by_the_lever_ratio():
    """Pivot at 0, cam contact at a, valve at l: the plunger moves 1/(R - 1) times the valve
    (R = l/a the load ratio on the base circle); the run writes the adjuster's outputs."""
    import numpy as np

    from camtrain import api
    from camtrain.assemble.dynamics import setup
    from camtrain.deck.load import validate
    from tests.dynamics.conftest import kinematics_of

    deck = validate(_finger_with_adjuster(), "finger_hla", DECKS)
    kin = kinematics_of(deck)
    model = setup(deck, kin).model
    ratio = float(np.asarray(kin.rocker_ratio)[int(np.argmin(kin.valve_lift))])
    assert model.series.ratio == pytest.approx(1.0 / (ratio - 1.0), rel=1e-12)
    assert model.mass[model.series.node] == pytest.approx(0.008 * model.series.ratio ** 2, rel=1e-12)
    result = api.run(deck)
    assert "hla_pressure" in result.columns and "valve_lift_loss" in result.columns
    assert result.metrics["hla_pressure_max"].value > 2.5e5


def test_deck_checks_name_the_fields():
    from camtrain.deck.load import validate
    from camtrain.errors import CamtrainError

    raw = _finger_with_adjuster()
    raw["clearance"] = {"lash_adjuster": False, "valve_clearance": 0.4}
    raw["dynamics"]["integrator"] = "central_difference"
    with pytest.raises(CamtrainError) as info:
        validate(raw, "bad", DECKS)
    for field in ("clearance.lash_adjuster", "dynamics.integrator"):
        assert field in str(info.value)
    raw = _finger_with_adjuster()
    raw["dynamics"]["lash_adjuster"]["rest_extension"] = 3.0
    with pytest.raises(CamtrainError, match="dynamics.lash_adjuster.rest_extension"):
        validate(raw, "bad", DECKS)
    raw = _finger_with_adjuster(location="pivot")
    raw["mechanism"] = dict(raw["mechanism"], type="rocker")
    with pytest.raises(CamtrainError, match="dynamics.lash_adjuster.location"):
        validate(raw, "bad", DECKS)


def test_leakdown_command(tmp_path):
    from click.testing import CliRunner

    from camtrain.cli import main

    out = CliRunner().invoke(main, ["leakdown", str(DECKS / "zeta_intake_hla.toml"), "--json"])
    assert out.exit_code == 0, out.output
    report = json.loads(out.output)
    assert report["time"] == pytest.approx(report["time_closed_form"], rel=1e-3)
    bad = CliRunner().invoke(main, ["leakdown", str(DECKS / "zeta_intake_dynamics.toml")])
    assert bad.exit_code == 2
    assert "dynamics.lash_adjuster" in bad.output and "Traceback" not in bad.output


def test_adjuster_in_a_push_rod_lifter_moves_with_the_push_rod():
    """In the lifter the plunger moves with the tappet and push rod: D1/D2 of the valve."""
    from camtrain.assemble.dynamics import pushrod_ratio, setup
    from camtrain.deck.load import validate
    from tests.dynamics.conftest import kinematics_of

    raw = tomllib.loads((DECKS / "pushrod_dynamics.toml").read_text(encoding="utf-8"))
    raw["clearance"] = {"lash_adjuster": True}
    raw["dynamics"]["lash_adjuster"] = dict(ADJUSTER, location="auto")
    deck = validate(raw, "pushrod_hla", DECKS)
    model = setup(deck, kinematics_of(deck)).model
    assert model.series.ratio == pytest.approx(1.0 / pushrod_ratio(deck), rel=1e-12)
    assert model.series.ratio < 1.0


def test_roller_finger_deck_with_its_adjuster_at_the_pivot_collapses_and_loses_lift():
    """decks/roller_finger_hla.toml: a roller finger follower laid out by [mechanism.layout],
    its adjuster under the ball pivot. The plunger is referred by the lever ratio of the
    layout's kinematics on the base circle, and the run reports the plunger's collapse per event
    and the valve lift lost to it."""
    import numpy as np

    from camtrain import api
    from camtrain.assemble.dynamics import setup
    from tests.dynamics.conftest import kinematics_of

    loaded = api.load(str(DECKS / "roller_finger_hla.toml"))
    deck = loaded.model
    assert deck.mechanism.follower == "roller" and deck.mechanism.layout is not None
    kin = kinematics_of(deck)
    model = setup(deck, kin).model
    ratio = float(np.asarray(kin.rocker_ratio)[int(np.argmin(kin.valve_lift))])
    assert ratio > 1.0
    assert model.series.ratio == pytest.approx(1.0 / (ratio - 1.0), rel=1e-12)
    result = api.run(loaded)
    metrics = result.metrics
    assert {"hla_pressure", "hla_extension", "valve_lift_loss"} <= set(result.columns)
    # the chamber carries the pivot's share of the valve load, at least the spring's installed
    # 224 N times (R - 1), over the 12 mm plunger
    assert metrics["hla_pressure_max"].value > 224.0 * (ratio - 1.0) / (np.pi / 4 * 0.012 ** 2)
    collapse = metrics["hla_collapse"].value
    assert 0.0 < collapse < 3.0e-3   # m: some collapse, less than the 3 mm stroke
    assert metrics["valve_lift_loss_max"].value > 0.0
    assert np.all(np.isfinite(result.columns["valve_lift_loss"].values))


def test_deck_with_the_ball_check_valve_writes_its_lift_and_cracking_pressure():
    """check_valve = "ball" on the shipped Zeta adjuster deck: the run writes the ball's lift
    column, its cracking pressure (preload over seat area: 6.3 mN on a 2 mm bore, 2.005 kPa),
    its natural frequency sqrt(k/m)/(2 pi) (0.1 N/mm on 0.064 g: 198.9 Hz) and a refill; a
    massless ball is refused with the field named."""
    import math

    import numpy as np

    from camtrain import api
    from camtrain.deck.load import validate
    from camtrain.errors import CamtrainError

    raw = tomllib.loads((DECKS / "zeta_intake_hla.toml").read_text(encoding="utf-8"))
    raw["dynamics"]["lash_adjuster"]["check_valve"] = "ball"
    result = api.run(validate(raw, "zeta_ball", DECKS))
    lift = result.columns["hla_check_lift"].values
    assert 0.0 < np.max(lift) <= 0.3e-3 and np.min(lift) == 0.0
    metrics = result.metrics
    assert metrics["hla_check_cracking_pressure"].value == pytest.approx(
        6.3e-3 / (math.pi / 4 * 2e-3 ** 2), rel=1e-12)
    assert metrics["hla_check_frequency"].value == pytest.approx(
        math.sqrt(100.0 / 6.4e-5) / (2 * math.pi), rel=1e-12)
    assert metrics["hla_refill"].value > 1e-6
    raw["dynamics"]["lash_adjuster"]["ball_mass"] = 0.0
    with pytest.raises(CamtrainError, match="dynamics.lash_adjuster.ball_mass"):
        validate(raw, "bad", DECKS)
