"""The engine deck kind: template, check (echo, plan, unit advice), input errors, plan, outputs,
sweeps over nested engine fields."""
from __future__ import annotations

import tomllib

import pytest
from click.testing import CliRunner

import camtrain.api as ct
from camtrain.catalogue import KINDS, kind_of
from camtrain.cli import main
from camtrain.deck.load import load_deck_text, validate
from camtrain.deck.templates import render_template
from camtrain.errors import InputError
from camtrain.scene import resolve

from .engine_decks import RUSTON, ZETA, deck


def invoke(*args):
    return CliRunner().invoke(main, list(args))


def test_engine_is_a_deck_kind_with_its_plan():
    d = deck()
    assert kind_of(d) is KINDS["engine"]
    assert resolve(d).chosen == ["crank_loads", "crank_bearings"]


def test_template_is_valid_and_names_every_section():
    text = render_template("engine")
    loaded = load_deck_text(text)
    assert kind_of(loaded.model) is KINDS["engine"]
    for section in ("[speed]", "[engine]", "[[cylinders]]", "[[crank_components]]",
                    "[[pressure]]", "[bearings.big_end]", "[bearings.main]", "[solver]"):
        assert section in text
    res = invoke("template", "engine")
    assert res.exit_code == 0 and res.output == text


def test_check_echoes_the_deck_and_plan():
    res = invoke("check", str(RUSTON))
    assert res.exit_code == 0, res.output
    for word in ("crank_loads", "crank_bearings", "0.08255", "260.35", "valid"):
        assert word in res.output


def _raw(path=RUSTON):
    return tomllib.loads(path.read_text(encoding="utf-8"))


def test_check_warns_when_a_moment_looks_like_the_other_unit():
    """Yang prints "N m" for both engines: Ruston's 139.19 is plausible in N·m, Zeta's 134.10
    only in N·mm. Each deck in the wrong unit is flagged, naming the plausible unit."""
    assert deck().advisories() == [a for a in deck().advisories() if "moment" not in a]
    wrong = _raw()
    for c in wrong["crank_components"]:
        c["moment_unit"] = "N·mm"
    msgs = [a for a in validate(wrong).advisories() if "moment" in a]
    assert len(msgs) == 6 and "plausible in N·m" in msgs[0]
    assert not [a for a in deck(ZETA).advisories() if "moment" in a]
    zeta = _raw(ZETA)
    for c in zeta["crank_components"]:
        c["moment_unit"] = "N·m"
    msgs = [a for a in validate(zeta).advisories() if "moment" in a]
    assert len(msgs) == 12 and "plausible in N·mm" in msgs[0]


def test_check_prints_the_advice(tmp_path):
    raw = RUSTON.read_text(encoding="utf-8").replace('moment_unit = "N·m"',
                                                     'moment_unit = "N·mm"')
    path = tmp_path / "r.toml"
    path.write_text(raw, encoding="utf-8")
    res = invoke("check", str(path))
    assert res.exit_code == 0 and "warning:" in res.output and "moment_unit" in res.output


@pytest.mark.parametrize("change, name", [
    ({"speed": {"engine": 700.0}}, "pressure"),
    ({"engine": {"strokes": 3}}, "engine.strokes"),
    ({"bearings": {"big_end": {"grooving": "central"}}}, "bearings.big_end.groove_width"),
    ({"solver": {"crank_step": 0.7}}, "solver.crank_step"),
    ({"solver": {"mobility_factor": "yang"}}, "solver.mobility_factor"),
    ({"solver": {"methods": ["orbit"]}}, "solver.methods"),
])
def test_bad_engine_field_is_named(change, name):
    raw = _raw()
    for section, fields in change.items():
        node = raw[section]
        for k, v in fields.items():
            if isinstance(v, dict):
                node[k].update(v)
            else:
                node[k] = v
    with pytest.raises(InputError) as exc:
        validate(raw, "r.toml")
    assert name in str(exc.value)


@pytest.mark.parametrize("entry, field, value, name", [
    ("cylinders", "bay", 7, "cylinders[0].bay"),
    ("cylinders", "position", 500.0, "cylinders[0].position"),
    ("crank_components", "moment_unit", "kg", "crank_components[0].moment_unit"),
    ("pressure", "reference", "relative", "pressure[0].reference"),
])
def test_bad_array_entry_is_named(entry, field, value, name):
    raw = _raw()
    raw[entry][0][field] = value
    with pytest.raises(InputError) as exc:
        validate(raw, "r.toml")
    assert name in str(exc.value)


def test_missing_unit_choices_are_required(tmp_path):
    """The gauge/absolute choice, the pressure unit and the moment unit have no default."""
    raw = _raw()
    del raw["pressure"][0]["reference"], raw["pressure"][0]["unit"]
    del raw["crank_components"][0]["moment_unit"]
    with pytest.raises(InputError) as exc:
        validate(raw, "r.toml")
    for name in ("pressure[0].reference", "pressure[0].unit", "crank_components[0].moment_unit"):
        assert name in str(exc.value)


def test_cli_exit_2_without_traceback(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(RUSTON.read_text(encoding="utf-8").replace("engine = 600.0", "engine = 650.0"),
                    encoding="utf-8")
    for command in ("check", "run"):
        res = invoke(command, str(path))
        assert res.exit_code == 2 and "pressure" in res.output
        assert "Traceback" not in res.output


def test_a_rod_shorter_than_the_crank_is_physically_impossible(tmp_path):
    path = tmp_path / "short.toml"
    path.write_text(RUSTON.read_text(encoding="utf-8").replace("rod_length = 782.32",
                                                               "rod_length = 150.0"),
                    encoding="utf-8")
    res = invoke("run", str(path), "--no-plots", "--out", str(tmp_path / "out"))
    assert res.exit_code == 3 and "engine.rod_length" in res.output
    assert "Traceback" not in res.output
    assert not (tmp_path / "out").exists()
    checked = invoke("check", str(path))
    assert checked.exit_code == 3 and "engine.rod_length" in checked.output
    assert "Traceback" not in checked.output


def test_check_says_the_crank_train_geometry_was_checked():
    res = invoke("check", str(RUSTON))
    assert res.exit_code == 0 and "geometry checked (crank train)" in res.output


def test_absolute_table_is_the_gauge_table_plus_the_crankcase():
    """An absolute table with its crankcase pressure gives the same loads as the gauge one."""
    raw = _raw()
    raw["pressure"][0]["values"] = [v + 1.0 for v in raw["pressure"][0]["values"]]
    raw["pressure"][0]["reference"] = "absolute"
    raw["pressure"][0]["crankcase"] = 1.0
    raw["solver"] = {"crank_step": 2.0, "methods": ["petroff"]}
    a = ct.run(validate(raw))
    b = ct.run(deck(solver__crank_step=2.0, solver__methods=["petroff"]))
    import numpy as np

    np.testing.assert_allclose(a["big_end_1_load"], b["big_end_1_load"], rtol=1e-12)


def test_viscosity_per_speed_is_interpolated_and_must_cover_the_speed():
    z = deck(ZETA)
    from camtrain.assemble.engine import bearing

    assert bearing(z, "big_end").viscosity == pytest.approx(2.90e-3, rel=1e-12)
    assert bearing(z, "main").viscosity == pytest.approx(2.57e-3, rel=1e-12)
    z = deck(ZETA, speed__engine=6400.0)
    assert bearing(z, "main").viscosity == pytest.approx(1.68e-3, rel=1e-12)
    with pytest.raises(InputError, match="bearings.big_end.viscosity_speeds"):
        raw = _raw(ZETA)
        raw["speed"]["engine"] = 8000.0
        raw["pressure"][-1]["speeds"] = [7000.0, 8000.0]
        validate(raw)


def test_run_writes_the_bearing_table_orbits_and_load_sheet(tmp_path):
    d = ct.load(RUSTON)
    r = ct.run(deck(solver__crank_step=2.0))
    files = {p.name for p in ct.write(r, d, tmp_path)}
    assert {"report.txt", "cycle.csv", "summary.json", "sheet_engine_loads.png",
            "orbit_big_end_1.png", "orbit_main_7.png"} <= files
    text = (tmp_path / "report.txt").read_text(encoding="utf-8")
    assert "CRANK BEARINGS" in text and "main 7" in text and "Total (kW)" in text
    assert "600 rpm engine" in text


def test_results_have_components_on_the_crank_angle_axis():
    r = ct.run(deck(ZETA, solver__crank_step=2.0))
    assert r.axes == ["crank_angle"]
    for comp in ("big_end_1", "big_end_4", "main_1", "main_5"):
        assert comp in r.components
    m3 = r.component("main_3")
    # partial grooving: both extremes, the power their mean (FLAME)
    assert {"eccentricity_ungrooved", "eccentricity_grooved"} <= set(m3.columns)
    assert "main_6" not in r.components


def test_sweep_over_a_nested_engine_field(tmp_path):
    res = invoke("sweep", str(RUSTON), "-p", "bearings.big_end.clearance", "--values",
                 "0.06,0.08255", "--set", "solver.crank_step=2.0", "--out", str(tmp_path))
    assert res.exit_code == 0, res.output
    rows = (tmp_path / "sweep.csv").read_text().splitlines()
    assert len(rows) == 3 and "big_end_1_min_film_dynamic" in rows[0]


def test_accuracy_knobs_of_an_engine_deck():
    """`camtrain accuracy` offers the engine's knobs (and not the valve train's); a model
    choice is a two-rung ladder whose reference is the default."""
    from camtrain.study.accuracy import relevant_knobs, render_table, study_knob

    raw = _raw()
    assert relevant_knobs(raw) == ["bearing_mesh", "bearing_model", "crank_step",
                                   "period_tolerance", "step_tolerance",
                                   "pressure_interpolation", "mobility"]
    raw["solver"].update(crank_step=2.0, methods=["steady", "petroff"])
    assert raw["solver"]["bearing_model"] == "short"
    assert "mobility" not in relevant_knobs(raw)
    k = study_knob(raw, "pressure_interpolation", 1e-3)
    assert [r["status"] for r in k["rungs"]] == ["ok", "ok"]
    total = k["metrics"]["total_power_steady"]
    assert total["errors"][1] == 0.0 and 0.0 < total["errors"][0] < 0.01
    text = render_table({"title": "t", "tolerance": 1e-3, "knobs": {"pressure_interpolation": k}})
    assert "periodic_cubic" in text and "linear" in text


def test_json_schema_of_the_engine_kind():
    import json

    res = invoke("schema", "--kind", "engine")
    assert res.exit_code == 0
    schema = json.loads(res.output)
    props = schema["properties"]
    assert props["kind"]["enum"] == ["engine"]
    assert set(props["pressure"]["items"]["properties"]["reference"]["enum"]) == {"gauge",
                                                                                 "absolute"}
    assert "moment_unit" in props["crank_components"]["items"]["required"]
    assert "big_end" in props["bearings"]["properties"]


@pytest.mark.derived
def test_pure_gas_load_lies_along_the_rod_through_the_deck():
    """Massless piston and rod, no crank components: every big-end load lies along the rod
    (x_r = 0) and at firing TDC equals the gas force (pi/4) D^2 p; the mains then carry exactly
    the pin forces (Yang §1.2.1-1.2.2)."""
    import math

    import numpy as np

    raw = _raw()
    raw["engine"].update(piston_mass=0.0, rod_mass=0.0)
    raw["crank_components"] = []
    raw["solver"] = {"crank_step": 2.0, "methods": ["petroff"]}
    r = ct.run(validate(raw))
    for k in range(1, 7):
        assert np.max(np.abs(r[f"big_end_{k}_load_x"])) == 0.0
    p0 = 47.37e5
    assert r["big_end_1_load_y"][0] == pytest.approx(0.25 * math.pi * 0.26035 ** 2 * p0,
                                                    rel=1e-12)
    total = sum(r[f"main_{k}_load_y"] for k in range(1, 8))
    pins = -sum(r[f"big_end_{k}_load_y"] * np.cos(np.arcsin(
        0.18415 / 0.78232 * np.sin(r["crank_angle"] - math.radians(a))))
        for k, a in zip(range(1, 7), (0, 120, 600, 240, 480, 360), strict=True))
    np.testing.assert_allclose(total, pins, atol=1e-9 * np.max(np.abs(pins)))


def test_two_stroke_single_cylinder_engine():
    """A 2-stroke single: the cycle is 360 deg, one bay, two mains; the orbits close over 360."""
    import math

    raw = _raw()
    raw["engine"].update(strokes=2, bay_lengths=[444.5])
    raw["cylinders"] = raw["cylinders"][:1]
    raw["crank_components"] = raw["crank_components"][:1]
    raw["pressure"][0]["values"] = raw["pressure"][0]["values"][:36]
    raw["solver"] = {"crank_step": 2.0, "bearing_model": "short"}
    r = ct.run(validate(raw))
    assert r["crank_angle"].size == 180
    assert math.degrees(r["crank_angle"][-1]) == pytest.approx(358.0)
    assert set(r.components) == {"big_end_1", "main_1", "main_2"}
    assert r.metrics["big_end_1_cycles"].value <= 4
    raw["pressure"][0]["values"] = _raw()["pressure"][0]["values"]
    with pytest.raises(InputError, match="pressure"):
        validate(raw)


def test_film_model_is_the_shared_bearing_definition():
    """The engine's bearings take their film model from the one definition of every bearing:
    auto by default (finite for the Ruston's land b/d 0.28), short in the shipped decks (as
    Yang); the plan says which model each bearing gets."""
    raw = _raw()
    del raw["solver"]["bearing_model"]
    plan = resolve(validate(raw))
    why = next(s.reason for s in plan.steps if s.effect == "crank_bearings")
    assert why.count("auto: land b/d = 0.281 > 0.05") == 2 and why.count("mesh 72 x 6") == 2
    why = next(s.reason for s in resolve(deck()).steps if s.effect == "crank_bearings")
    assert "short bearing (Ocvirk)" in why
