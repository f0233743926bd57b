"""The friction correlations on the Ford Zeta engine beside FLAME (docs/engine.md, "Friction
correlations"), the bare engine deck, the load and oil-temperature options and the maps.

The Zeta table (FLAME, PNH 1989 and Sandoval-Heywood 2003 at 2000-7000 rpm) pins the signs of
the speed trends of every total and term, not their ratios: the models are compared, not fitted.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from camtrain.deck.load import load_deck, validate
from camtrain.engine.correlations import MODELS, OperatingPoint, correlation_terms
from camtrain.errors import InputError
from camtrain.result import Result
from tests.conftest import DECKS
from tests.engine.test_zeta_flame import SPEEDS, run_at, zeta

BARE = DECKS / "zeta_bare_engine.toml"
MODEL_NAMES = ("pnh1989", "sandoval_heywood2003")
#: the sign of d(term)/d(speed) over 2000-7000 rpm: hydrodynamic and turbulent terms rise,
#: boundary-factor terms (1 + N_0/N) fall, the seals and the constant do not move
TREND = {"crankshaft_seals": 0, "main_bearings": 1, "turbulent_dissipation": 1,
         "piston_skirt": 1, "piston_rings": -1, "ring_gas_loading": -1, "rod_bearings": 1,
         "camshaft_bearings": 1, "valve_train_constant": 0, "follower": -1,
         "oscillating_hydrodynamic": 1, "oscillating_mixed": -1}


def _correlations(model):
    from camtrain.effects import correlations

    result = Result()
    return correlations.run(model, {}, result), result


def _signs(values):
    d = np.diff(np.asarray(values, dtype=float))
    scale = max(abs(v) for v in values)
    if np.all(np.abs(d) <= 1e-12 * scale):
        return {0}
    return set(np.sign(d[np.abs(d) > 1e-12 * scale]).astype(int))


@pytest.fixture(scope="module")
def zeta_table():
    """FLAME (full runs) and the correlations (the same runs' metrics) at 2000-7000 rpm."""
    rows = {}
    for rpm in SPEEDS:
        m = {k: v.value for k, v in run_at(rpm).metrics.items()}
        rows[rpm] = m
    return rows


def test_zeta_table_speed_trends_of_every_total_and_term(zeta_table):
    rows = [zeta_table[s] for s in SPEEDS]
    for name in ("flame_total", "flame_bearings", "flame_valve_train", "flame_piston",
                 "pnh1989_power", "sandoval_heywood2003_power"):
        assert _signs([r[name] for r in rows]) == {1}, name
    for model in MODEL_NAMES:
        for term, sign in TREND.items():
            assert _signs([r[f"{model}_{term}_fmep"] for r in rows]) == {sign}, (model, term)
        # the fmep of the whole engine rises with speed in both models, as FLAME's does
        assert _signs([r[f"{model}_fmep"] for r in rows]) == {1}
    assert _signs([r["fmep"] for r in rows]) == {1}


def test_zeta_table_ordering_correlations_above_flame(zeta_table):
    """The 1980s-data correlations lose more than FLAME's component physics at every speed
    (both include accessories), and their difference grows with speed."""
    gaps = []
    for rpm in SPEEDS:
        r = zeta_table[rpm]
        for model in MODEL_NAMES:
            assert r[f"{model}_power"] > r["flame_total"], (rpm, model)
        gaps.append(r["pnh1989_power"] - r["flame_total"])
    assert _signs(gaps) == {1}


def test_bare_deck_gives_the_full_decks_correlations():
    bare = load_deck(str(BARE)).model
    full = zeta()
    a, _ = _correlations(bare)
    b, _ = _correlations(full)
    for model in MODEL_NAMES:
        assert a.totals[model] == pytest.approx(b.totals[model], rel=1e-12)
        for term in a.terms[model]:
            assert a.terms[model][term] == pytest.approx(b.terms[model][term], rel=1e-12)


def test_bare_deck_plan_runs_the_correlations_alone():
    from camtrain.scene import resolve

    plan = resolve(load_deck(str(BARE)).model)
    chosen = [s.effect for s in plan.steps if s.chosen]
    assert chosen == ["correlations"]
    why = {s.effect: s.reason for s in plan.steps}
    assert "engine.rod_length" in why["crank_loads"] and "[[pressure]]" in why["crank_loads"]
    assert "alone" in why["correlations"] and "chen_flynn" in why["correlations"]


@pytest.mark.parametrize("layout", ["sohc_finger", "sohc_rocker", "sohc_direct", "dohc_finger",
                                    "dohc_direct"])
def test_pnh_roller_valve_train_loses_less_than_flat_most_at_low_speed(layout):
    """Roller followers lower the valve-train friction (Staron & Willermet 1983; the roller
    follower's boundary term becomes a rolling one): PNH's roller train is below its flat one
    at every speed, and the saving shrinks with speed (the boundary factor falls)."""
    bare = load_deck(str(BARE)).model
    from camtrain.assemble.correlations import correlation_engine

    flat = dataclasses.replace(correlation_engine(bare), layout=layout, follower="flat")
    roller = dataclasses.replace(flat, follower="roller")
    speeds = np.arange(1000.0, 7001.0, 500.0) * 2 * math.pi / 60
    vt = {}
    for name, eng in (("flat", flat), ("roller", roller)):
        t = correlation_terms(MODELS["pnh1989"], eng, OperatingPoint(speeds))
        vt[name] = sum(t[k] for k in ("camshaft_bearings", "valve_train_constant", "follower",
                                      "oscillating_hydrodynamic", "oscillating_mixed"))
    saving = vt["flat"] - vt["roller"]
    assert np.all(saving > 0)
    assert _signs(saving) == {-1}


def test_sandoval_heywood_thins_with_oil_temperature_pnh_does_not():
    from camtrain.study.friction_map import correlation_map

    fmap = correlation_map(load_deck(str(BARE)).model, [2000, 4000], [0.5, 1.0],
                           [40.0, 90.0, 130.0])
    sh, pnh = fmap.totals["sandoval_heywood2003"], fmap.totals["pnh1989"]
    assert np.all(np.diff(sh, axis=2) < 0)
    assert np.all(np.diff(pnh, axis=2) == 0)
    assert np.all(np.diff(pnh, axis=1) > 0)        # more intake pressure, more ring gas load
    # a bare deck's load axis is p_i/p_a: Chen-Flynn keeps the deck's peak pressure
    assert np.all(np.diff(fmap.totals["chen_flynn"], axis=1) == 0)


def test_vectorised_map_equals_the_effect_at_every_point():
    """The map's one call per model gives what the correlations effect gives at each point,
    with the diagram scaled to the point's IMEP and the oil at the point's temperature."""
    from camtrain.study.friction_map import correlation_map
    from camtrain.units import to_si

    model = dataclasses.replace(zeta(), flame=None, piston=None)
    fmap = correlation_map(model, [3000, 6000], [6.0, 9.0], [80.0, 110.0], measure="imep")
    load = validate({**_raw_with_load(6.0)}, "zeta_engine.toml", DECKS).load
    for i, rpm in enumerate((3000, 6000)):
        for j, imep in enumerate((6.0, 9.0)):
            for k, temp in enumerate((80.0, 110.0)):
                point = dataclasses.replace(
                    model, speed=dataclasses.replace(model.speed, engine=to_si(rpm, "rpm")),
                    load=dataclasses.replace(load, value=to_si(imep, "bar")),
                    oil=dataclasses.replace(model.oil, temperature=temp))
                out, _ = _correlations(point)
                for name in MODEL_NAMES:
                    assert fmap.totals[name][i, j, k] == pytest.approx(out.power(name),
                                                                       rel=1e-12)


def _raw_with_load(value):
    import tomllib

    raw = tomllib.loads((DECKS / "zeta_engine.toml").read_text(encoding="utf-8"))
    raw["load"] = {"measure": "imep", "value": value}
    return raw


@pytest.mark.parametrize("measure,target", [("imep", 7.5), ("peak_pressure", 80.0)])
def test_load_scales_the_diagram_to_the_asked_value(measure, target):
    from camtrain.assemble.engine import pressure_table
    from camtrain.engine.pressure import net_imep

    raw = _raw_with_load(target)
    raw["load"]["measure"] = measure
    model = validate(raw, "zeta_engine.toml", DECKS)
    table = pressure_table(model)
    if measure == "imep":
        got = net_imep(table, model.engine.crank_radius, model.engine.rod_length,
                       model.solver.pressure_interpolation)
    else:
        got = max(table.gauge())
    assert got == pytest.approx(target * 1e5, rel=1e-9)


def test_net_imep_of_a_constant_pressure_is_zero_and_of_a_step_is_its_work():
    """Derived: a constant pressure does no net work; a pressure p0 on the first stroke only
    (0-180 deg, the piston moving down) does p0 x stroke volume over the cycle: net IMEP = p0
    (the ramp of the linear table from 179 to 180 deg, near BDC, costs 5e-5)."""
    from camtrain.engine.pressure import PressureTable, net_imep

    angles = tuple(math.radians(a) for a in range(0, 720, 1))
    const = PressureTable(angles, tuple(5e5 for _ in angles))
    assert abs(net_imep(const, 0.044, 0.137, "linear")) < 1e-6
    step = PressureTable(angles, tuple(1e6 if a < 180 else 0.0 for a in range(0, 720, 1)))
    assert net_imep(step, 0.044, 0.137, "linear", step=math.radians(0.01)) == \
        pytest.approx(1e6, rel=1e-4)


def test_oil_reference_temperature_moves_flames_viscosities_by_the_grade_ratio():
    from camtrain.assemble.engine import bearing
    from camtrain.formulas.engine_friction import oil_grade_viscosity

    base = zeta()
    hot = dataclasses.replace(base, oil=dataclasses.replace(base.oil, temperature=125.0))
    ratio = oil_grade_viscosity("10W30", 125.0) / oil_grade_viscosity("10W30", 95.0)
    for which in ("big_end", "main"):
        assert bearing(hot, which).viscosity == pytest.approx(
            bearing(base, which).viscosity * ratio, rel=1e-12)


@pytest.mark.parametrize("change,field,words", [
    ({"correlations": {"cylinders": None}}, "correlations.cylinders", "required"),
    ({"correlations": {"valve_train": {"layout": "ohv", "follower": "roller"}}},
     "correlations.valve_train.follower", "misprint"),
    ({"load": {"measure": "imep", "value": 8.0}}, "load", "pressure diagram"),
    ({"oil": {"viscosity": 10.0}}, "oil", "exactly one"),
])
def test_bare_deck_input_errors_name_the_field(change, field, words):
    import tomllib

    raw = tomllib.loads(BARE.read_text(encoding="utf-8"))
    for section, values in change.items():
        node = raw.setdefault(section, {})
        for k, v in values.items():
            if isinstance(v, dict):
                node.setdefault(k, {}).update(v)
            elif v is None:
                node.pop(k, None)
            else:
                node[k] = v
    with pytest.raises(InputError) as err:
        validate(raw, BARE.name, DECKS)
    assert any(p.path == field and words in p.render() for p in err.value.problems), \
        err.value.render()


def test_engine_deck_without_correlations_still_needs_its_crank_train():
    import tomllib

    raw = tomllib.loads((DECKS / "zeta_crank_bearings.toml").read_text(encoding="utf-8"))
    del raw["bearings"]
    del raw["engine"]["rod_mass"]
    with pytest.raises(InputError) as err:
        validate(raw, "zeta_crank_bearings.toml", DECKS)
    paths = {p.path for p in err.value.problems}
    assert {"bearings", "engine.rod_mass"} <= paths


def test_friction_map_command_on_the_bare_deck(tmp_path):
    from click.testing import CliRunner

    from camtrain.cli import main

    out = tmp_path / "map"
    res = CliRunner().invoke(main, ["friction-map", str(BARE), "--speeds", "2000,4000,6000",
                                    "--loads", "0.5,1", "--temperatures", "60,100",
                                    "--out", str(out)])
    assert res.exit_code == 0, res.output
    text = (out / "friction_map.csv").read_text()
    assert text.count("\n") == 1 + 3 * 2 * 2 * 3      # header + points x three models
    assert (out / "plots" / "friction_map_contour.png").is_file()
    assert (out / "plots" / "friction_map_shares.png").is_file()
    bad = CliRunner().invoke(main, ["friction-map", str(BARE), "--speeds", "2000,x",
                                    "--loads", "1", "--temperatures", "90", "--out",
                                    str(tmp_path / "bad")])
    assert bad.exit_code == 2 and "--speeds" in bad.output and "Traceback" not in bad.output


def test_sweep_route_writes_the_same_map_as_the_vectorised_one(tmp_path):
    """`camtrain sweep` over speed, intake pressure ratio and oil temperature on the bare deck
    writes friction_map.csv; its totals are the vectorised map's."""
    from camtrain.study.friction_map import correlation_map, map_from_records
    from camtrain.study.runner import prepare, run_sweep

    sweep = prepare(BARE, [("speed", "values", "2000,5000"),
                           ("correlations.intake_pressure_ratio", "values", "0.5,1"),
                           ("oil.temperature", "values", "60,110")])
    outcome = run_sweep(sweep, tmp_path, jobs=1, plots=False)
    assert (tmp_path / "friction_map.csv").is_file()
    fmap = map_from_records(sweep.params, outcome.records, "p_i/p_a")
    ref = correlation_map(load_deck(str(BARE)).model, [2000, 5000], [0.5, 1.0], [60.0, 110.0])
    for name in ("pnh1989", "sandoval_heywood2003", "chen_flynn"):
        # records hold the deck's units at print precision (kW to 4+ significant digits)
        assert np.allclose(fmap.totals[name], ref.totals[name], rtol=1e-6), name


def test_a_diagram_without_positive_imep_cannot_be_scaled_exit_3():
    """A motored-looking diagram (constant pressure: no net work) cannot be scaled to an IMEP:
    a physically impossible request (exit 3), not a number."""
    from camtrain.assemble.engine import load_factor
    from camtrain.errors import GeometryError

    raw = _raw_with_load(8.0)
    for table in raw["pressure"]:
        table["values"] = [1.0] * len(table["values"])
    model = validate(raw, "zeta_engine.toml", DECKS)
    with pytest.raises(GeometryError, match="load.measure") as err:
        load_factor(model)
    assert err.value.exit_code == 3
