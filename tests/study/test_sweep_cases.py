"""Case generation: parameter names, value specs, grids and zips, bounds, Ball's pivot rules."""
from __future__ import annotations

import tomllib

import pytest

from camtrain.errors import InputError
from camtrain.study.assign import parse_assignment
from camtrain.study.sweep import (
    ALIASES,
    build_parameters,
    case_raw,
    cases,
    parse_values,
    resolve_path,
)

from .conftest import DECKS


def _raw(name: str) -> dict:
    return tomllib.loads((DECKS / name).read_text(encoding="utf-8"))


def test_value_specs():
    assert parse_values("values", "14,16,18,20", None, "x") == (14.0, 16.0, 18.0, 20.0)
    assert parse_values("range", "14:22:9", None, "x") == tuple(float(v) for v in range(14, 23))
    assert parse_values("relative", "-50%:+50%:5", 18.0, "x") == (9.0, 13.5, 18.0, 22.5, 27.0)
    assert parse_values("relative", "-10:10:3", 2500.0, "x") == (2250.0, 2500.0, 2750.0)
    assert parse_values("range", "5:5:1", None, "x") == (5.0,)


@pytest.mark.parametrize("kind,spec,fragment", [
    ("values", "", "no values"), ("values", "1,a", "'a' is not a number"),
    ("range", "1:2", "three fields"), ("range", "1:2:x", "whole number"),
    ("range", "1:2:0", "out of range"), ("values", "1,inf", "finite"),
    ("relative", "-5%:5%:3", "no value in the deck")])
def test_bad_value_specs_name_the_option(kind, spec, fragment):
    with pytest.raises(InputError) as err:
        parse_values(kind, spec, None, "follower_radius")
    assert f"--{kind}" in str(err.value) and fragment in str(err.value)


def test_all_seven_aliases_resolve_with_units_and_datums():
    raw = _raw("harrison_flat.toml")
    units = {n: resolve_path(raw, n).unit for n in ALIASES if n != "follower_radius"}
    assert units == {"base_radius": "mm", "cam_width": "mm", "spring_rate": "N/mm",
                     "speed": "rpm", "viscosity": "Pa·s", "equivalent_mass": "kg"}
    assert resolve_path(raw, "spring_rate").datum == 38.254
    assert resolve_path(_raw("pinto_finger.toml"), "follower_radius").datum == 44.0
    assert resolve_path(raw, "follower_radius").datum is None  # a flat follower has none


def test_speed_alias_follows_the_deck(tmp_path):
    raw = _raw("harrison_flat.toml")
    raw["speed"] = {"engine": 5000.0}
    p = resolve_path(raw, "speed")
    assert (p.path, p.datum) == ("speed.engine", 5000.0)


def test_dotted_paths_defaults_and_list_entries():
    raw = _raw("harrison_flat.toml")
    p = resolve_path(raw, "lift.four_power.coefficients[1]")
    assert (p.unit, p.datum) == ("mm", 2.8498942)
    p = resolve_path(raw, "tribology.boundary_friction")  # not in the deck: the default
    assert p.datum == pytest.approx(0.08)
    assert resolve_path(raw, "solver.angle_points").integer


@pytest.mark.parametrize("name,fragment", [
    ("bse_radius", "did you mean base_radius"), ("cam.bse_radius", "did you mean cam.base_radius"),
    ("cam", "is not a parameter name"), ("lift.four_power", "single number"),
    ("mechanism.type", "single number"), ("lift.four_power.coefficients", "needs an index"),
    ("cam..width", "dotted deck path")])
def test_unknown_or_non_numeric_paths(name, fragment):
    with pytest.raises(InputError) as err:
        resolve_path(_raw("harrison_flat.toml"), name)
    assert fragment in str(err.value)


def test_values_checked_against_field_bounds():
    raw = _raw("harrison_flat.toml")
    with pytest.raises(InputError, match="out of range for cam.base_radius"):
        build_parameters(raw, [("base_radius", "values", "18,-1")])
    with pytest.raises(InputError, match="whole numbers"):
        build_parameters(raw, [("solver.angle_points", "values", "360.5")])
    with pytest.raises(InputError, match="swept twice"):
        build_parameters(raw, [("speed", "values", "1"), ("speed.camshaft", "values", "2")])


def test_grid_and_zip():
    raw = _raw("harrison_flat.toml")
    params = build_parameters(raw, [("base_radius", "values", "16,18"),
                                    ("speed", "values", "1500,2000,2500")])
    grid = cases(params)
    assert len(grid) == 6 and grid[1].as_dict() == {"base_radius": 16.0, "speed": 2000.0}
    params = build_parameters(raw, [("base_radius", "values", "16,18,20"),
                                    ("speed", "values", "1500,2000,2500")])
    zipped = cases(params, zipped=True)
    assert [c.as_dict()["speed"] for c in zipped] == [1500.0, 2000.0, 2500.0]
    assert [c.index for c in zipped] == [0, 1, 2]
    params = build_parameters(raw, [("base_radius", "values", "16,18"),
                                    ("speed", "values", "1500,2000,2500")])
    with pytest.raises(InputError, match="--zip"):
        cases(params, zipped=True)


def test_case_raw_writes_deck_units_and_leaves_the_datum_alone():
    raw = _raw("harrison_flat.toml")
    params = build_parameters(raw, [("solver.angle_points", "values", "360"),
                                    ("cam_width", "values", "10")])
    new = case_raw(raw, params, cases(params)[0])
    assert new["solver"]["angle_points"] == 360 and isinstance(new["solver"]["angle_points"], int)
    assert new["cam"]["width"] == 10.0 and raw["cam"]["width"] == 12.0


def test_set_assignment():
    p = parse_assignment(_raw("harrison_flat.toml"), "solver.angle_points=360")
    assert p.values == (360.0,)
    with pytest.raises(InputError, match="--set"):
        parse_assignment(_raw("harrison_flat.toml"), "solver.angle_points")


# ------------------------------------------------------------------ Ball's pivoted geometry rules

def _pinto_case(spec: list) -> dict:
    raw = _raw("pinto_finger.toml")
    params = build_parameters(raw, spec)
    return case_raw(raw, params, cases(params, zipped=True)[0])["mechanism"]


def test_pinto_improved_geometry_from_ball_rules():
    """r_f 44 -> 52.8 and r_B 15 -> 16.8 give Ball's improved Pinto geometry (§5.5)."""
    improved = _raw("pinto_finger_improved.toml")["mechanism"]
    mech = _pinto_case([("follower_radius", "values", "52.8"), ("base_radius", "values", "16.8")])
    for key in ("A", "D", "kappa", "lambda"):
        assert mech[key] == pytest.approx(improved[key], abs=2e-3), key
    assert mech["B"] == 61.8


def test_each_rule_alone():
    datum = _raw("pinto_finger.toml")["mechanism"]
    only_rb = _pinto_case([("base_radius", "values", "16.8")])
    assert only_rb["A"] == pytest.approx(datum["A"]) and only_rb["lambda"] == pytest.approx(31.9)
    assert only_rb["D"] == pytest.approx(47.19, abs=0.01)
    assert only_rb["kappa"] == pytest.approx(37.86, abs=0.01)
    only_rf = _pinto_case([("follower_radius", "values", "52.8")])
    assert only_rf["D"] == pytest.approx(datum["D"]) and only_rf["kappa"] == pytest.approx(39.7)
    assert only_rf["A"] == pytest.approx(57.98, abs=0.01)


def test_datum_values_keep_the_datum_geometry():
    datum = _raw("pinto_finger.toml")["mechanism"]
    mech = _pinto_case([("base_radius", "values", "15")])
    for key in ("A", "D", "kappa", "lambda"):
        assert mech[key] == pytest.approx(datum[key], abs=1e-9)


def test_explicitly_swept_geometry_is_not_overwritten():
    mech = _pinto_case([("base_radius", "values", "16.8"), ("mechanism.A", "values", "50")])
    assert mech["A"] == 50.0


def test_flat_decks_are_not_touched_by_pivot_rules():
    raw = _raw("harrison_flat.toml")
    params = build_parameters(raw, [("base_radius", "values", "20")])
    assert case_raw(raw, params, cases(params)[0])["mechanism"] == raw["mechanism"]
