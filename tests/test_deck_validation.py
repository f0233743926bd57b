"""Every validation rule of the deck and its message: field path, value, expectation, hint."""
from __future__ import annotations

import math
import tomllib

import pytest
import tomli_w

from camtrain.deck.load import load_deck_text, validate
from camtrain.errors import InputError
from tests.conftest import MINIMAL_DECK


def _raw():
    return tomllib.loads(MINIMAL_DECK)


def _problems(raw) -> list[str]:
    with pytest.raises(InputError) as info:
        validate(raw, "deck.toml")
    return [p.render() for p in info.value.problems]


def test_minimal_deck_is_valid_and_in_si():
    deck = load_deck_text(MINIMAL_DECK).model
    assert deck.cam.base_radius == pytest.approx(0.018)
    assert deck.speed.omega == pytest.approx(1500 * 2 * math.pi / 60)
    assert deck.lift.four_power.half_period == pytest.approx(math.pi / 3)
    assert deck.lift.ramps.opening_height == pytest.approx(0.5e-3)
    assert deck.materials.cam_modulus == pytest.approx(207e9)  # default, GPa -> Pa


def test_model_is_immutable():
    deck = load_deck_text(MINIMAL_DECK).model
    with pytest.raises(AttributeError):
        deck.cam.base_radius = 1.0  # type: ignore[misc]


def test_engine_speed_is_twice_camshaft_speed():
    raw = _raw()
    raw["speed"] = {"engine": 3000}
    deck = validate(raw)
    assert deck.speed.omega == pytest.approx(1500 * 2 * math.pi / 60)


def test_both_speeds_rejected():
    raw = _raw()
    raw["speed"]["engine"] = 3000
    msgs = _problems(raw)
    assert any("exactly one of speed.camshaft or speed.engine" in m for m in msgs)


@pytest.mark.parametrize("path,value,fragment", [
    (("cam", "base_radius"), -1.0, "cam.base_radius: is out of range (got -1.0); expected a "
                                    "number > 0 in mm"),
    (("cam", "base_radius"), 0, "cam.base_radius: is out of range"),
    (("cam", "base_radius"), "18", "cam.base_radius: must be a number, not a string"),
    (("cam", "base_radius"), True, "cam.base_radius: must be a number, not a boolean"),
    (("cam", "base_radius"), math.nan, "cam.base_radius: must be finite"),
    (("cam", "base_radius"), math.inf, "cam.base_radius: must be finite"),
    (("materials", "cam_poisson"), 0.5, "materials.cam_poisson: is out of range (got 0.5); "
                                        "expected a number > 0 and < 0.5"),
    (("materials", "cam_poisson"), 0.0, "materials.cam_poisson: is out of range"),
    (("masses", "valve_side"), -0.1, "masses.valve_side: is out of range"),
    (("mechanism", "type"), "flatt", "mechanism.type: is not an allowed choice (got 'flatt'); "
                                     "expected one of 'flat'"),
    (("solver", "angle_points"), 100.5, "solver.angle_points: must be a whole number"),
    (("lift", "four_power", "exponents"), [2, 9, 78], "lift.four_power.exponents: has 3 "
                                                       "entries; expected at least 4 and at most 4"),
])
def test_field_rules(path, value, fragment):
    raw = _raw()
    node = raw
    for key in path[:-1]:
        node = node.setdefault(key, {})
    if path[-1] == "valve_side":
        node["valve_side"] = value
        raw["spring"] = {"rate": 38.0, "preload_compression": 6.4}
    else:
        node[path[-1]] = value
    msgs = _problems(raw)
    assert any(fragment in m for m in msgs), msgs


def test_flatt_hint_suggests_flat():
    raw = _raw()
    raw["mechanism"]["type"] = "flatt"
    assert any("did you mean 'flat'?" in m for m in _problems(raw))


def test_unknown_key_hint_in_same_section():
    raw = _raw()
    raw["cam"]["base_raduis"] = 18
    assert any("cam.base_raduis: is not a known key. did you mean `cam.base_radius`?" in m
               for m in _problems(raw))


def test_unknown_key_hint_from_other_section():
    raw = _raw()
    raw["masses"] = {"valve_side": 0.1, "rate": 38}
    assert any("masses.rate: is not a known key. did you mean `spring.rate`?" in m
               for m in _problems(raw))


def test_unknown_section():
    raw = _raw()
    raw["sping"] = {"rate": 1}
    assert any("sping: is not a known key. did you mean `spring`?" in m for m in _problems(raw))


def test_all_problems_reported_at_once():
    raw = _raw()
    raw["cam"]["base_radius"] = -1
    raw["speed"]["camshaft"] = "fast"
    raw["mechanism"]["type"] = "bucket"
    msgs = _problems(raw)
    assert len(msgs) >= 3


def test_missing_required_section_and_field():
    raw = _raw()
    del raw["cam"]
    del raw["lift"]["four_power"]["max_lift"]
    msgs = _problems(raw)
    assert any(m.startswith("cam: required section is missing") for m in msgs)
    assert any(m.startswith("lift.four_power.max_lift: required field is missing") for m in msgs)


def test_domed_follower_needs_radius():
    raw = _raw()
    raw["mechanism"]["type"] = "domed"
    assert any("mechanism.follower_radius: is required for a domed follower" in m
               for m in _problems(raw))


def test_flat_follower_rejects_radius():
    raw = _raw()
    raw["mechanism"]["follower_radius"] = 40
    assert any("mechanism.follower_radius: does not apply to a flat follower" in m
               for m in _problems(raw))


def test_pivoted_follower_needs_pivot_geometry():
    raw = _raw()
    raw["mechanism"].update(type="finger", follower_radius=44)
    msgs = _problems(raw)
    for key in ("A", "B", "D", "kappa", "lambda"):
        assert any(m.startswith(f"mechanism.{key}: is required for a finger follower")
                   for m in msgs), key


def test_lift_form_needs_its_section_and_no_other():
    raw = _raw()
    raw["lift"]["form"] = "exp_poly"
    msgs = _problems(raw)
    assert any(m.startswith("lift.exp_poly: is missing") for m in msgs)
    assert any(m.startswith("lift.four_power: is given but form = 'exp_poly'") for m in msgs)


def test_cam_lift_needs_inspection_radius_for_pivoted():
    raw = _raw()
    raw["mechanism"].update(type="domed", follower_radius=250)
    raw["lift"]["measured_at"] = "cam"
    assert any(m.startswith("lift.inspection_radius: is required") for m in _problems(raw))


def _table_deck(angles, lifts):
    raw = _raw()
    raw["lift"] = {"form": "table", "table": {"angles": angles, "lifts": lifts}}
    return raw


def test_table_angles_must_increase():
    angles = [-40, -30, -20, -10, 0, 10, 5, 30, 40]
    raw = _table_deck(angles, [0.0] * len(angles))
    msgs = _problems(raw)
    assert any("lift.table.angles[6]: angle decreases (got 5.0)" in m for m in msgs)


def test_table_duplicate_angles():
    angles = [-40, -30, -20, -10, 0, 0, 20, 30, 40]
    raw = _table_deck(angles, [0.0] * len(angles))
    assert any("lift.table.angles[5]: angle repeats" in m for m in _problems(raw))


def test_table_lengths_must_match():
    raw = _table_deck(list(range(10)), [0.0] * 9)
    assert any("lift.table.lifts: has 9 values but angles has 10" in m for m in _problems(raw))


def test_unknown_effect_name():
    raw = _raw()
    raw["effects"] = ["kinematic"]
    assert any("effects[0]: is not a known effect (got 'kinematic')" in m and
               "did you mean 'kinematics'?" in m for m in _problems(raw))


def test_effects_must_be_auto_or_list():
    raw = _raw()
    raw["effects"] = "all"
    assert any(m.startswith("effects: is not an allowed choice") for m in _problems(raw))


def test_section_given_as_value():
    raw = _raw()
    raw["cam"] = 18
    assert any(m.startswith("cam: must be a table, not a number") for m in _problems(raw))


def test_roundtrip_through_toml_writer():
    """A deck written back with tomli-w validates to the same model."""
    raw = _raw()
    again = load_deck_text(tomli_w.dumps(raw)).model
    assert again == load_deck_text(MINIMAL_DECK).model
