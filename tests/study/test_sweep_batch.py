"""Sweep cases run as one vectorised batch give the records the case-by-case path gives.

The batch broadcasts the swept scalars as (cases, 1) columns through the same physics on
(cases, angles) arrays; every metric of every case must equal the single run's to 1e-12
relative, with the same names, order, units, status and message. Cases the batch cannot take
(invalid geometry, lost contact) and sweeps whose physics branches per case fall back to the
case-by-case path, and the route says why.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.study.batch import BatchJob, route, run_batch
from camtrain.study.case_model import datum_key
from camtrain.study.executors import Job, run_case
from camtrain.study.runner import prepare, run_sweep

from .conftest import DECKS

pytestmark = pytest.mark.derived


def _deck(tmp_path, name: str, points: int = 120, **replace: str):
    text = (DECKS / name).read_text(encoding="utf-8")
    text = text.replace("angle_points = 1440", f"angle_points = {points}")
    if "angle_points" not in text:
        text += f"\n[solver]\nangle_points = {points}\n"
    for old, new in replace.items():
        assert old in text or old.startswith("_"), old
        text = text.replace(old, new) if not old.startswith("_") else text + new
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _both(sweep, keep=frozenset(), monkeypatch=None):
    """(batch records, single-run records); with ``monkeypatch``, also checks that the batch ran
    alone exactly the cases that are not ok (it never fell back as a whole)."""
    import camtrain.study.executors as executors

    key = datum_key(sweep.raw, sweep.name, sweep.base_dir)
    ran_alone = []
    if monkeypatch is not None:
        monkeypatch.setattr(executors, "run_case",
                            lambda job: ran_alone.append(job.case.index) or run_case(job))
    batch = run_batch(BatchJob(sweep.raw, tuple(sweep.params), tuple(sweep.cases), sweep.name,
                               sweep.base_dir, keep, key))
    if monkeypatch is not None:
        monkeypatch.undo()
    alone = [run_case(Job(sweep.raw, tuple(sweep.params), c, sweep.name, sweep.base_dir,
                          c.index in keep, key)) for c in sweep.cases]
    if monkeypatch is not None:
        assert ran_alone == [r["index"] for r in alone if r["status"] != "ok"]
    return batch, alone


def _assert_same(batch, alone, rtol=1e-12):
    assert [r["index"] for r in batch] == [r["index"] for r in alone]
    for b, a in zip(batch, alone, strict=True):
        assert (b["status"], b["message"], b["values"]) == (a["status"], a["message"], a["values"])
        assert list(b["metrics"]) == list(a["metrics"]), a["index"]
        for name, (value, unit) in a["metrics"].items():
            got, got_unit = b["metrics"][name]
            assert got_unit == unit, name
            if math.isnan(value):
                assert math.isnan(got), name
            else:
                assert got == pytest.approx(value, rel=rtol, abs=0.0), (a["index"], name)
        assert (b["curves"] is None) == (a["curves"] is None)
        for name, (unit, values) in (a["curves"] or {}).items():
            assert b["curves"][name][0] == unit
            np.testing.assert_array_equal(b["curves"][name][1], values)


GOCMEN_STEADY = {'film_model = "averaged_reynolds"': 'film_model = "steady"'}


@pytest.mark.parametrize(("deck", "replace", "specs"), [
    # base radius down into the concave cam (12 mm < 13.59 mm): failed cases run alone
    ("harrison_flat.toml", {}, [("base_radius", "range", "12:22:15")]),
    # speed beyond the bounce speed: lost-contact cases run alone
    ("harrison_flat.toml", {}, [("speed", "values", "1200,2500,4500"),
                                ("spring_rate", "values", "25,38.254")]),
    ("harrison_flat.toml", {'entrainment = "sum"': 'entrainment = "mean"\n'
                            'friction_model = "lambda_cap"'},
     [("viscosity", "values", "0.01,0.05"), ("cam_width", "values", "8,12"),
      ("tribology.boundary_friction", "values", "0.05,0.1"),
      ("materials.cam_modulus", "values", "150,207")]),
    ("harrison_flat.toml", {}, [("spring.preload_compression", "values", "3,6.4"),
                                ("equivalent_mass", "values", "0.1,0.25"),
                                ("lubricant.roughness", "values", "0.1,0.4"),
                                ("lubricant.pressure_viscosity", "values", "10,22")]),
    # table lift, lash adjuster (base-circle load), half-mean entrainment, the 1966 film
    ("gocmen_table31.toml", GOCMEN_STEADY, [("speed", "range", "500:3000:6"),
                                            ("base_radius", "values", "16,18")]),
    ("gocmen_table31.toml", {'film_model = "averaged_reynolds"':
                             'film_model = "steady"\nfriction_model = "greenwood_tripp"'},
     [("speed", "values", "800,1500,2500")]),
    # domed follower on a tapered cam (point contact): the friction/load iteration converges
    # case by case; guides; speeds beyond bounce
    ("zeta_intake.toml", {}, [("speed", "values", "1500,4000,7000"),
                              ("follower_radius", "values", "25,40")]),
    ("zeta_intake.toml", {"_": '\n[tribology]\nfriction_model = "lambda"\n'},
     [("viscosity", "values", "0.005,0.02"), ("base_radius", "values", "15,17")]),
    # a roller tappet (mechanism.follower = "roller"): the cylindrical face of a single run
    ("harrison_roller.toml", {'follower_shape = "cylindrical"': 'follower = "roller"'},
     [("speed", "values", "1500,2500"), ("follower_radius", "values", "10,12")]),
])
def test_batch_metrics_equal_the_case_by_case_metrics(tmp_path, monkeypatch, deck, replace,
                                                       specs):
    sweep = prepare(_deck(tmp_path, deck, **replace), specs)
    assert route(sweep.raw, sweep.params, sweep.name, sweep.base_dir).batch
    batch, alone = _both(sweep, monkeypatch=monkeypatch)
    _assert_same(batch, alone)


def test_fallback_cases_are_the_single_runs_and_kept_curves_the_rows(tmp_path, monkeypatch):
    """Failed and lost-contact cases come from the single-run path (status and message); the
    overlay curves of a kept case from its row of the batch equal the single run's columns."""
    sweep = prepare(_deck(tmp_path, "harrison_flat.toml"),
                    [("base_radius", "values", "12,18"), ("speed", "values", "2500,4500")])
    batch, alone = _both(sweep, keep=frozenset({1, 2, 3}), monkeypatch=monkeypatch)
    assert [r["status"] for r in alone] == ["failed", "failed", "ok", "lost_contact"]
    assert [r["curves"] is not None for r in batch] == [False, False, True, True]
    _assert_same(batch, alone)


@pytest.mark.parametrize(("deck", "replace", "specs", "why"), [
    ("harrison_flat.toml", {}, [("lift.four_power.half_period", "values", "55,65")],
     "lift.four_power.half_period is not a scalar"),
    ("harrison_flat.toml", {}, [("clearance.valve_clearance", "values", "0.2,0.4")],
     "clearance.valve_clearance is not a scalar"),
    ("harrison_flat.toml", {'rotation = "clockwise"': 'rotation = "anticlockwise"'},
     [("speed", "values", "2000")], "anticlockwise"),
    ("gocmen_table31.toml", {'film_model = "averaged_reynolds"': 'film_model = "squeeze"'},
     [("speed", "values", "1000")], "squeeze film"),
    ("gocmen_table31.toml", {'film_model = "averaged_reynolds"':
                             'film_model = "steady"\nfriction_model = "greenwood_tripp"'},
     [("viscosity", "values", "0.01")], "greenwood_tripp"),
    ("pinto_finger.toml", {}, [("speed", "values", "2000")], "finger follower"),
    ("pinto_finger.toml", {}, [("base_radius", "values", "14,16")],
     "on a finger follower cam.base_radius moves other fields with it"),
    ("zeta_intake_camshaft.toml", {}, [("speed", "values", "2000")], "camshaft_torque"),
    ("harrison_roller.toml", {'rotation = "clockwise"': 'rotation = "clockwise"\n'
                              'follower = "roller"\n[mechanism.roller]\ncrown_radius = 300.0'},
     [("speed", "values", "2000")], "crowned roller"),
])
def test_route_falls_back_where_the_physics_branches_per_case(tmp_path, deck, replace, specs,
                                                                why):
    sweep = prepare(_deck(tmp_path, deck, **replace), specs)
    r = route(sweep.raw, sweep.params, sweep.name, sweep.base_dir)
    assert not r.batch and why in r.reason
    assert r.describe().startswith("cases run one by one: ")
    # a reason never names as not batched what its own list calls batched
    assert not ("is not a scalar" in r.reason and specs[0][0].replace("_", " ") in r.reason)


def test_sweep_tables_are_the_same_on_both_paths(tmp_path, monkeypatch):
    sweep = prepare(_deck(tmp_path, "harrison_flat.toml"),
                    [("base_radius", "values", "12,16,20"), ("speed", "values", "2500,4500")])
    batched = run_sweep(sweep, tmp_path / "batch", jobs=1, plots=False, overlay_max=2)
    assert batched.route.batch
    import camtrain.study.batch as batch_module

    monkeypatch.setattr(batch_module, "route", lambda *a, **k: batch_module.Route(False, "test"))
    single = run_sweep(sweep, tmp_path / "single", jobs=1, plots=False, overlay_max=2)
    assert not single.route.batch
    for name in ("sweep.csv", "trends.csv", "trends.md"):
        assert (tmp_path / "batch" / name).read_text() == (tmp_path / "single" / name).read_text()
    assert '"batch": true' in (tmp_path / "batch" / "sweep.json").read_text()


def test_sub_batches_split_a_chunk_without_changing_it(tmp_path, monkeypatch):
    """Two cases per sub-batch: a sub-batch whose cases share a swept value other than the
    datum's (viscosity 0.02 here) computes with that value."""
    import camtrain.study.batch as batch_module

    sweep = prepare(_deck(tmp_path, "harrison_flat.toml"),
                    [("viscosity", "values", "0.02,0.08"), ("base_radius", "values", "15,19")])
    whole, alone = _both(sweep)
    monkeypatch.setattr(batch_module, "BATCH_POINTS", 2 * 120)
    split = _both(sweep, monkeypatch=monkeypatch)[0]
    _assert_same(split, whole, rtol=0.0)
    _assert_same(split, alone)


def test_a_shorter_plan_runs_over_the_cases_of_its_own_effects(tmp_path, monkeypatch):
    """Without [lubricant] the plan is kinematics, loads, hertz: the batch walks that plan
    (each effect's run over the case axis), and its metrics are the single runs'."""
    import re

    path = _deck(tmp_path, "harrison_flat.toml")
    path.write_text(re.sub(r"(?ms)^\[lubricant\].*?(?=^\[)", "", path.read_text()))
    sweep = prepare(path, [("speed", "values", "1000,4500"), ("spring_rate", "values", "25,38")])
    r = route(sweep.raw, sweep.params, sweep.name, sweep.base_dir)
    assert r.batch and "kinematics, loads, hertz run over a case axis" in r.reason
    batch, alone = _both(sweep, keep=frozenset({0, 1}), monkeypatch=monkeypatch)
    assert "film_min" not in alone[0]["metrics"] and "hertz_max" in alone[0]["metrics"]
    assert "film_min" not in alone[0]["curves"] and "load" in alone[0]["curves"]
    _assert_same(batch, alone)
