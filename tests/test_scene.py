"""Scene plan: effects run only when the deck calls for them, each with its reason."""
from __future__ import annotations

import tomllib

import pytest

from camtrain.deck.load import load_deck_text, validate
from camtrain.errors import InputError
from camtrain.scene import resolve
from tests.conftest import DECKS, MINIMAL_DECK


def _plan(raw):
    return {s.effect: s for s in resolve(validate(raw)).steps}


def test_no_load_data_gives_kinematics_and_blok_film_only():
    """Ball (1988) §4.2.3: without load data, kinematics and the load-free Blok film only."""
    raw = tomllib.loads(MINIMAL_DECK)
    raw["lubricant"] = {"viscosity": 0.05, "pressure_viscosity": 22}
    steps = _plan(raw)
    assert steps["kinematics"].chosen
    assert not steps["loads"].chosen and "spring" in steps["loads"].reason
    assert steps["film"].chosen and "Blok" in steps["film"].reason
    for name in ("hertz", "friction", "power"):
        assert not steps[name].chosen and "needs" in steps[name].reason


def test_full_deck_plans_everything():
    deck = load_deck_text((DECKS / "harrison_flat.toml").read_text()).model
    plan = resolve(deck)
    assert plan.chosen == ["kinematics", "loads", "hertz", "film", "friction", "power"]


def test_missing_width_stops_hertz_and_friction():
    raw = tomllib.loads((DECKS / "harrison_flat.toml").read_text())
    del raw["cam"]["width"]
    steps = _plan(raw)
    assert steps["loads"].chosen
    assert not steps["hertz"].chosen and "cam.width" in steps["hertz"].reason
    assert not steps["friction"].chosen


def test_explicit_list_pulls_in_prerequisites():
    raw = tomllib.loads((DECKS / "harrison_flat.toml").read_text())
    raw["effects"] = ["hertz"]
    steps = _plan(raw)
    assert steps["hertz"].chosen and steps["hertz"].reason.startswith("requested in the deck")
    assert steps["loads"].chosen and steps["loads"].reason.startswith("needed by hertz")
    assert steps["kinematics"].chosen
    assert not steps["film"].chosen and steps["film"].reason == "not requested"


def test_explicit_effect_missing_data_names_fields():
    raw = tomllib.loads(MINIMAL_DECK)
    raw["effects"] = ["film"]
    with pytest.raises(InputError) as info:
        resolve(validate(raw))
    assert "effect 'film' is requested" in str(info.value)
    assert "lubricant" in str(info.value)


def test_plan_is_resolved_without_computation():
    """Resolving a plan touches no physics: in a fresh process, loading a deck and resolving
    its plan imports no lift, mechanism, formula, contact or load module (and not numpy); the
    effect modules it asks for their data checks import none either."""
    import subprocess
    import sys

    code = ("import sys; from camtrain.deck.load import load_deck; from camtrain.scene import "
            f"resolve; resolve(load_deck({str(DECKS / 'harrison_flat.toml')!r}).model); "
            "print(','.join(m for m in sys.modules if m.startswith(('camtrain.lift', "
            "'camtrain.mechanisms', 'camtrain.formulas', 'camtrain.contact', 'camtrain.loads', "
            "'camtrain.camshaft', 'camtrain.bearings', 'numpy'))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == ""
