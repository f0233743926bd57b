"""The effect registry: an alternative product offered from a module of its own, the plan's
choice and reason, products checked by the runner, topological order, deck kinds."""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from camtrain.catalogue import KINDS, VALVE_TRAIN, EffectSpec, kind_of
from camtrain.contact.model import contact_friction, contact_hertz
from camtrain.deck.load import load_deck
from camtrain.formulas import cycle_mean, friction_torque
from camtrain.runner import run_plan
from camtrain.scene import order, resolve
from tests.conftest import DECKS

from . import toy_loads

# the toy alternative beside the rigid loads only (the shipped dynamic loads are a rival too)
CATALOGUE = tuple(s for s in VALVE_TRAIN if s.name != "dynamics") + (toy_loads.SPEC,)


def toy_deck(scale):
    deck = load_deck(str(DECKS / "harrison_flat.toml")).model
    values = {f.name: getattr(deck, f.name) for f in dataclasses.fields(deck)}
    return toy_loads.ToyDeck(**values, toy_scale=scale)


def steps(plan):
    return {s.effect: s for s in plan.steps}


def test_plan_chooses_the_alternative_when_its_data_are_present():
    plan = resolve(toy_deck(1.5), CATALOGUE)
    s = steps(plan)
    assert s["toy_loads"].chosen and "toy_scale = 1.5 given" in s["toy_loads"].reason
    assert "chosen over loads for ContactLoad" in s["toy_loads"].reason
    assert not s["loads"].chosen
    assert s["loads"].reason.startswith("ContactLoad comes from toy_loads instead")
    assert plan.chosen == ["kinematics", "toy_loads", "hertz", "film", "friction", "power"]


def test_plan_keeps_the_rigid_train_without_the_data():
    s = steps(resolve(toy_deck(None), CATALOGUE))
    assert s["loads"].chosen
    assert not s["toy_loads"].chosen and s["toy_loads"].reason == "no data: toy_scale"


def test_downstream_effects_run_unchanged_on_the_alternative():
    deck = toy_deck(1.5)
    result = run_plan(deck, resolve(deck, CATALOGUE))
    rigid = run_plan(toy_deck(None), resolve(toy_deck(None), CATALOGUE))
    load = result["load"]
    assert result.columns["load"].description == "toy contact load"
    assert not np.allclose(load, rigid["load"])
    kin = _kinematics(deck)
    w = np.maximum(load, 0.0)
    np.testing.assert_array_equal(result["hertz_pmax"], contact_hertz(deck, kin, w).pmax)
    force = contact_friction(deck, kin, w).force
    np.testing.assert_array_equal(result["friction_force"], force)
    power = friction_torque(force, kin.friction_arm) * abs(kin.omega)
    assert result.metrics["power_loss_mean"].value == pytest.approx(cycle_mean(power), rel=1e-12)


def _kinematics(deck):
    from camtrain.effects import kinematics
    from camtrain.result import Result
    from camtrain.runner import Inputs

    return kinematics.run(deck, Inputs(VALVE_TRAIN[0], {}), Result()).main


def test_runner_checks_what_an_effect_returns():
    wrong = EffectSpec("kinematics", "camtrain.effects.kinematics", "declares the wrong product",
                       produces=("ContactLoad",))
    deck = toy_deck(None)
    with pytest.raises(TypeError, match="returned a TrainKinematics"):
        run_plan(deck, resolve(deck, (wrong,)))


def test_runner_refuses_an_undeclared_read():
    from camtrain.loads import ContactLoad
    from camtrain.runner import Inputs

    spec = EffectSpec("x", "camtrain.effects.hertz", "", needs=("TrainKinematics",))
    with pytest.raises(TypeError, match="does not declare"):
        Inputs(spec, {})[ContactLoad]


def test_order_is_a_topological_sort_over_products():
    names = [s.name for s in order(tuple(reversed(VALVE_TRAIN)))]
    for spec in VALVE_TRAIN:
        for product in spec.needs + spec.uses:
            producers = [s.name for s in VALVE_TRAIN if product in s.produces]
            assert all(names.index(p) < names.index(spec.name) for p in producers)
    a = EffectSpec("a", "m", "", needs=("B",), produces=("A",))
    b = EffectSpec("b", "m", "", needs=("A",), produces=("B",))
    with pytest.raises(ValueError, match="cycle"):
        order((a, b))


def test_every_deck_kind_resolves_its_own_plan():
    bearing = load_deck(str(DECKS / "bearing_ocvirk_check.toml")).model
    assert kind_of(bearing) is KINDS["journal_bearing"]
    assert resolve(bearing).chosen == ["journal_bearing"]
    assert kind_of(toy_deck(None)) is KINDS["valve_train"]


def test_a_new_chain_effect_joins_the_sweep_batch_by_declaring_a_run_over_cases(monkeypatch):
    """The batch names no effect: an effect without ``run_cases`` sends the sweep case by case
    (the reason names it); with one (and no refusal) the plan runs over a case axis."""
    from camtrain.runner import cases_refusal

    deck = toy_deck(1.5)
    plan = resolve(deck, CATALOGUE)
    why = cases_refusal(deck, plan, ("speed.camshaft",))
    assert why == "the toy_loads effect runs case by case (it has no run over a case axis)"
    monkeypatch.setattr(toy_loads, "run_cases", lambda deck, inputs, cases: None, raising=False)
    assert cases_refusal(deck, plan, ("speed.camshaft",)) == ""
    monkeypatch.setattr(toy_loads, "cases_refused", lambda deck, swept: "toy: not over cases",
                        raising=False)
    assert cases_refusal(deck, plan, ("speed.camshaft",)) == "toy: not over cases"
