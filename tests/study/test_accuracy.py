"""The accuracy-study machinery: Richardson, observed order, ladders, cheapest setting, CLI.

Wall times are recorded by the study but never asserted here.
"""
from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from camtrain.cli_accuracy import accuracy
from camtrain.errors import InputError
from camtrain.study import accuracy as acc
from camtrain.study.accuracy_plot import pareto_front
from tests.report.declarations import StoredPlan

#: the plan of a lubricated valve train (the knobs' tests on deck options narrow it)
CHAIN = StoredPlan("valve_train", ["kinematics", "loads", "hertz", "film", "friction", "power"])
COUPLED = StoredPlan("valve_train", ["kinematics", "dynamics", "hertz", "film", "friction",
                                     "power", "camshaft_torque", "camshaft_coupled"])

HARRISON = Path(__file__).resolve().parents[2] / "decks" / "harrison_flat.toml"


@settings(max_examples=50, deadline=None)
@given(order=st.floats(0.5, 4.0), c=st.floats(-10.0, 10.0).filter(lambda c: abs(c) > 1e-3),
       exact=st.floats(-100.0, 100.0), ratio=st.sampled_from([2.0, 3.0, 4.0]))
def test_richardson_recovers_a_known_order(order, c, exact, ratio):
    """f(h) = f* + C h^p sampled at h, h/r, h/r^2: order p and f* come back exactly."""
    hs = [0.1, 0.1 / ratio, 0.1 / ratio**2]
    f = [exact + c * h**order for h in hs]
    p = acc.observed_order(*f, ratio)
    assert p == pytest.approx(order, rel=1e-6, abs=1e-6)
    assert acc.richardson(f[1], f[2], ratio, p) == pytest.approx(exact, abs=1e-7 * (1 + abs(c)))


def test_order_unreadable_when_differences_vanish_or_oscillate():
    assert acc.observed_order(1.0, 1.0, 1.0, 2.0) is None
    assert acc.observed_order(1.0, 2.0, 1.5, 2.0) is None  # sign change: not asymptotic


def test_analyse_uses_richardson_then_falls_back_to_finest():
    steps = [1 / 90, 1 / 180, 1 / 360, 1 / 720]
    clean = [3.0 + 2.0 * h**2 for h in steps]
    a = acc.analyse(clean, steps)
    assert a["reference_kind"] == "richardson" and a["order"] == pytest.approx(2.0)
    assert a["reference"] == pytest.approx(3.0, abs=1e-12)
    assert all(e1 > e2 for e1, e2 in zip(a["errors"], a["errors"][1:], strict=False))
    noisy = [3.0, 3.1, 2.9, 3.05]
    b = acc.analyse(noisy, steps)
    assert b["reference_kind"] == "finest" and b["errors"][-1] == 0.0
    failed = acc.analyse([3.0, None, 3.2, 3.1], steps)  # a failed rung breaks the triples
    assert failed["orders"][2] is None and failed["errors"][1] is None


def test_cheapest_is_coarsest_with_every_finer_rung_within_tolerance():
    rungs = [{}] * 5
    assert acc.cheapest(rungs, [1e-2, 5e-4, 2e-3, 5e-4, 0.0], 1e-3) == 3  # lucky rung 1 skipped
    assert acc.cheapest(rungs, [1e-2, 5e-4, 2e-4, 5e-5, 0.0], 1e-3) == 1
    assert acc.cheapest(rungs, [1e-2, 5e-4, 2e-4, None, 0.0], 1e-3) == 4
    assert acc.cheapest(rungs, [1e-2, 1e-2, 1e-2, 1e-2, 2e-3], 1e-3) is None


@pytest.mark.parametrize("text, value", [("0.1%", 1e-3), ("1e-3", 1e-3), (" 2 % ", 0.02)])
def test_parse_tolerance(text, value):
    assert acc.parse_tolerance(text) == pytest.approx(value)


@pytest.mark.parametrize("text", ["abc", "0", "-1%", "150%", "nan", ""])
def test_parse_tolerance_rejects(text):
    with pytest.raises(InputError, match="--tolerance"):
        acc.parse_tolerance(text)


def test_knobs_follow_the_deck():
    flat = {"mechanism": {"type": "flat"}, "lift": {"form": "four_power"}}
    table = {"mechanism": {"type": "finger"}, "lift": {"form": "table", "table": {}}}
    assert acc.relevant_knobs(flat, CHAIN) == ["angle_points"]
    assert acc.relevant_knobs(table, CHAIN) == ["angle_points", "friction_tolerance", "table_smoothing"]
    with pytest.raises(InputError, match="--knob"):
        acc.check_knobs(flat, ["friction_tolerance"], CHAIN)
    with pytest.raises(InputError, match="--knob"):
        acc.check_knobs(flat, ["nope"], CHAIN)


def test_coupled_camshaft_climbs_its_cheaper_ladders():
    """Every rung of the two-way coupled camshaft marches all its trains with the shaft: its
    station and step ladders stop where a rung would cost minutes; the one-way shaft and the
    single train keep the full ladders."""
    one_way = {"dynamics": {}, "camshaft": {"flexibility": {"coupling": "one_way"}}}
    coupled = {"dynamics": {}, "camshaft": {"flexibility": {"coupling": "two_way"}}}
    stations, steps = acc.KNOBS["shaft_stations"], acc.KNOBS["steps_per_degree"]
    assert stations.ladder_of(one_way) == stations.ladder
    assert steps.ladder_of({"dynamics": {}}) == steps.ladder
    assert stations.ladder_of(coupled) == (0, 1, 2, 4)
    assert steps.ladder_of(coupled) == (6.0, 12.0, 24.0, 48.0)


def test_staggered_passes_are_a_knob_of_the_staggered_solver_only():
    """coupling_iterations sets the staggered march's passes per step: a knob of a two-way
    coupled camshaft with coupling_solver = "staggered", of no other deck."""
    flex = {"coupling": "two_way"}
    monolithic = {"dynamics": {}, "camshaft": {"flexibility": dict(flex)}}
    staggered = {"dynamics": {}, "camshaft": {"flexibility": dict(
        flex, coupling_solver="staggered")}}
    assert "coupling_iterations" not in acc.relevant_knobs(monolithic, COUPLED)
    assert "coupling_iterations" in acc.relevant_knobs(staggered, COUPLED)


def test_set_path_copies_and_creates_tables():
    raw = {"solver": {"angle_points": 720}}
    out = acc.set_path(raw, "lift.table.smoothing", 0.5)
    assert out["lift"]["table"]["smoothing"] == 0.5 and "lift" not in raw


def test_pareto_front_keeps_only_undominated_points():
    pts = [(1.0, 1e-2, "a"), (2.0, 1e-3, "b"), (3.0, 5e-3, "c"), (4.0, 1e-4, "d")]
    assert [p[2] for p in pareto_front(pts)] == ["a", "b", "d"]


@pytest.fixture(scope="module")
def harrison_ladder():
    import tomllib

    raw = tomllib.loads(HARRISON.read_text(encoding="utf-8"))
    return acc.study_knob(raw, "angle_points", 1e-3, ladder=(180, 360, 720, 1440, 2880))


def test_harrison_angle_ladder_error_decreases(harrison_ladder):
    """Power loss converges under angle refinement at about first order (the friction cap and the
    ramp joints make the integrand non-smooth); its error falls monotonically from 360 angles."""
    k = harrison_ladder
    assert all(r["status"] == "ok" and r["wall_time"] > 0 for r in k["rungs"])
    m = k["metrics"]["power_loss_mean"]
    assert m["reference_kind"] == "richardson" and 0.5 <= m["order"] <= 1.5
    errs = m["errors"]
    assert all(a > b for a, b in zip(errs[1:], errs[2:], strict=False))
    assert errs[-1] < 1e-3 < errs[0]
    # metrics evaluated exactly at the nose do not depend on the angle step
    assert k["metrics"]["cam_radius_at_max_lift"]["errors"] == [0.0] * 5
    assert k["cheapest"] is not None and k["cheapest"]["value"] in (1440, 2880)


def test_cli_writes_table_csv_json_png(tmp_path, fast_flat):
    out = tmp_path / "acc"
    res = CliRunner().invoke(accuracy, [str(fast_flat), "--knob", "angle_points",
                                        "--tolerance", "1%", "--out", str(out)])
    assert res.exit_code == 0, res.output
    assert "cheapest meeting 0.01" in res.output
    rows = list(csv.DictReader((out / "accuracy.csv").open(encoding="utf-8")))
    assert {r["knob"] for r in rows} == {"angle_points"}
    report = json.loads((out / "accuracy.json").read_text(encoding="utf-8"))
    assert report["tolerance"] == 0.01 and "angle_points" in report["knobs"]
    assert (out / "accuracy.png").stat().st_size > 1000
    assert all(math.isfinite(float(r["metric_value"])) for r in rows)


@pytest.mark.parametrize("args, option", [
    (["--knob", "bogus"], "--knob"), (["--knob", "table_smoothing"], "--knob"),
    (["--tolerance", "lots"], "--tolerance")])
def test_cli_bad_options_exit_2_naming_the_option(args, option):
    res = CliRunner().invoke(accuracy, [str(HARRISON), *args])
    assert res.exit_code == 2
    assert option in res.output and "Traceback" not in res.output


def test_help_names_every_knob():
    """`camtrain accuracy --help` lists every knob a deck can climb (the elastic film's
    ehl_nodes, ehl_inlet, ehl_angle_step and ehl_tolerance among them)."""
    from camtrain.study.accuracy_knobs import KNOBS

    res = CliRunner().invoke(accuracy, ["--help"], terminal_width=10_000)
    assert res.exit_code == 0
    help_text = " ".join(res.output.split())
    missing = [name for name in KNOBS if name not in help_text]
    assert not missing, missing


def test_table_says_met_or_not_met_never_ok_beside_a_large_error():
    """A rung that ran but misses the tolerance reads 'not met', one within it 'met'."""
    rung = {"status": "ok", "message": "", "wall_time": 0.01, "wall_spread": 0.05,
            "timed_runs": 2, "value": 720}
    report = {"title": "t", "tolerance": 1e-3, "knobs": {"angle_points": {
        "path": "solver.angle_points", "description": "d",
        "rungs": [dict(rung, value=720), dict(rung, value=1440, wall_spread=0.3)],
        "worst_error": [3.1e-2, 5e-4], "metrics": {}, "cheapest": None}}}
    lines = acc.render_table(report).splitlines()
    coarse = next(line for line in lines if line.strip().startswith("720 "))
    fine = next(line for line in lines if line.strip().startswith("1440 "))
    assert coarse.endswith("not met") and " ok" not in coarse and "5%" in coarse
    assert fine.endswith(" met") and "30%!" in fine


def test_rung_is_timed_until_its_two_fastest_runs_agree(monkeypatch):
    """Times 10, 5, 5.2 ms: the first pair differs by 100 %, the third run agrees with the
    second within 10 %, so three runs and the fastest kept, spread 4 %."""
    import tomllib

    from camtrain import api

    raw = tomllib.loads(HARRISON.read_text(encoding="utf-8"))
    raw["solver"]["angle_points"] = 180
    done = api.run(api.loads(HARRISON.read_text(encoding="utf-8"), "h"))
    monkeypatch.setattr(api, "run", lambda model: done)      # only the clock is timed here
    ticks = iter([0.0, 0.010, 1.0, 1.005, 2.0, 2.0052, 3.0, 3.001])
    monkeypatch.setattr(acc.time, "perf_counter", lambda: next(ticks))
    rung = acc._run_rung(raw, HARRISON.parent, repeat=5)
    assert rung["timed_runs"] == 3
    assert rung["wall_time"] == pytest.approx(0.005)
    assert rung["wall_spread"] == pytest.approx(0.04)
    assert acc.timing_spread([0.01]) == math.inf
