"""`camtrain optimize`: known optima, constraints met when the optimum is rerun as an ordinary
deck, the batch route, interruption, the command line."""
from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest
from scipy.optimize import brentq

import camtrain.api as ct
from camtrain.assemble.lift_law import build_lift_law
from camtrain.study import optimize as opt
from tests.conftest import DECKS, ROOT

HARRISON = DECKS / "harrison_flat.toml"
ROLLER = DECKS / "harrison_roller.toml"
STEP = 1e-3        # the default finite-difference step, a fraction of each variable's range


@pytest.mark.derived
def test_base_radius_optimum_is_balls_smallest_radius_for_a_convex_flank():
    """Friction falls with the base radius (Ball 1988 Ch 5), so under "no concave flank" the
    optimum is the smallest radius for which r_c = r_B + l + l'' > 0 (Ball §2.2.1): r_B,min =
    -min(l + l''), 13.590 mm for Harrison's four-power lift (Ball's "just over 20 %" below
    the datum 18 mm; docs/references/ball1988.md, DERIVED), here computed from the lift law
    on a 0.001 deg grid."""
    law = build_lift_law(ct.load(HARRISON).model.lift)
    c = law.evaluate(np.radians(np.arange(-180.0, 180.0, 0.001)))
    r_min = -np.min(c.lift + c.d2) * 1e3
    assert r_min == pytest.approx(13.590, abs=5e-4)
    lower, upper = 10.0, 25.0
    out = opt.optimize(HARRISON, [("base_radius", lower, upper)],
                       constraints=["no_concave_flank"])
    assert out.status == "converged"
    (r,) = out.optimum.x
    assert r == pytest.approx(r_min, abs=STEP * (upper - lower))
    assert r >= r_min        # on the convex side
    assert "no_concave_flank" in out.active()
    assert out.evaluations <= 200
    assert out.optimum.objective < out.datum.objective


@pytest.mark.derived
def test_preload_optimum_is_where_the_bounce_speed_equals_the_over_speed():
    """Friction rises with the preload; "no separation up to the over-speed" then holds the
    preload where camtrain's bounce speed (camtrain.loads.bounce: min over angles of
    sqrt(-a/b), the rigid train's W = a + omega^2 b) equals the over-speed, found here by a
    root search on that formula alone."""
    from camtrain.assemble.mechanism import kinematics
    from camtrain.loads.bounce import bounce_speed
    from camtrain.tabulate.lift import lift_curve
    from camtrain.units import to_si

    model = ct.load(HARRISON).model
    kin, _ = kinematics(model, lift_curve(model.lift, model.solver.angle_points))
    over = 3000.0

    def excess(preload_mm):
        b = bounce_speed(kin, rate=model.spring.rate, preload_compression=preload_mm * 1e-3,
                         valve_mass=model.masses.valve_side,
                         clearance=model.clearance.valve_clearance)
        return b.omega - to_si(over, "rpm")

    expected = brentq(excess, 0.5, 12.0, xtol=1e-9)
    lower, upper = 1.0, 12.0
    out = opt.optimize(HARRISON, [("spring.preload_compression", lower, upper)],
                       constraints=[f"no_separation={over:g}"])
    (p,) = out.optimum.x
    assert p == pytest.approx(expected, abs=STEP * (upper - lower))
    assert out.optimum.metrics["bounce_speed"][0] >= over - 1e-6
    assert out.active() == [f"no_separation={over:g}"]


@pytest.mark.parametrize("deck, film", [(HARRISON, 0.0), (ROLLER, 0.2)], ids=["flat", "roller"])
def test_optimum_rerun_as_an_ordinary_deck_meets_every_constraint(deck, film, tmp_path):
    # the flat tappet's film vanishes at its zero-entrainment points: no film constraint there
    constraints = ["no_separation=3200", "hertz_limit=560"]
    constraints += [f"min_film_parameter={film:g}"] if film else []
    out = ct.optimize(deck, ["base_radius=14:24", "spring.preload_compression=2:10"],
                      constraints=constraints, out_dir=tmp_path, plots=False)
    assert out.status == "converged"
    gain = out.gains()[0]
    assert gain[0] == "power_loss_mean" and gain[4] < 0.0     # less friction than the datum
    rerun = ct.run(tmp_path / "optimum.toml")
    m = rerun.metrics
    assert m["bounce_speed"].value >= 3200 - 1e-6
    assert m["hertz_max"].value <= 560e6 * (1 + 1e-9)
    assert m["film_min"].value / ct.load(deck).model.lubricant.roughness >= film - 1e-9
    assert m["power_loss_mean"].value == pytest.approx(gain[3], rel=1e-9)
    report = json.loads((tmp_path / "optimize.json").read_text(encoding="utf-8"))
    assert all(c["met"] for c in report["constraints"])
    assert report["gain"][0]["change"] == pytest.approx(gain[4])


def test_batch_route_is_used_where_the_variables_allow(monkeypatch):
    from camtrain.study import batch

    calls = []
    real = batch.run_batch

    def counting(job):
        calls.append(len(job.cases))
        return real(job)

    monkeypatch.setattr(batch, "run_batch", counting)
    out = opt.optimize(HARRISON, ["base_radius=12:24", "spring_rate=20:60"],
                       constraints=["no_concave_flank"], maxiter=5)
    assert out.problem.route.batch
    assert sum(calls) == out.evaluations
    assert max(calls) == 3          # a point and its two neighbours in one batch
    lift = opt.optimize(HARRISON, ["lift.four_power.half_period=55:65"], maxiter=2)
    assert not lift.problem.route.batch


def test_valve_open_area_held_within_its_tolerance():
    out = opt.optimize(HARRISON, ["lift.four_power.half_period=50:70"],
                       constraints=["open_area=2"])
    area = out.optimum.metrics["open_area"][0]
    datum = out.datum.metrics["open_area"][0]
    assert abs(area - datum) <= 0.02 * datum * (1 + 1e-9)
    assert out.optimum.objective <= out.datum.objective


def test_interrupted_search_keeps_the_best_point_so_far():
    seen = []

    def progress(problem):
        seen.append(len(problem.path))
        if len(seen) == 3:
            raise KeyboardInterrupt

    out = opt.optimize(HARRISON, ["base_radius=10:25"], constraints=["no_concave_flank"],
                       progress=progress)
    assert out.status == "interrupted"
    feasible = [p for p in out.problem.path if p.feasible]
    assert out.optimum.objective == min(p.objective for p in feasible)


def test_differential_evolution_finds_the_preload_optimum():
    local = opt.optimize(HARRISON, ["spring.preload_compression=1:12"],
                         constraints=["no_separation=3000"])
    glob = opt.optimize(HARRISON, ["spring.preload_compression=1:12"],
                        constraints=["no_separation=3000"], method="differential_evolution",
                        maxiter=20)
    assert glob.optimum.x[0] == pytest.approx(local.optimum.x[0], abs=STEP * 11)
    assert any(p.role == "population" for p in glob.problem.path)


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "camtrain.cli", *map(str, args)],
                          capture_output=True, text=True, cwd=ROOT)


def test_cli_writes_the_optimum_and_the_comparison(tmp_path):
    run = _cli("optimize", HARRISON, "--var", "base_radius=10:25", "--constraint",
               "no_concave_flank", "--out", tmp_path, "--quiet")
    assert run.returncode == 0, run.stderr
    for name in ("optimum.toml", "optimize.md", "optimize.json", "path.csv", "comparison.csv",
                 "comparison.png"):
        assert (tmp_path / name).is_file(), name
    assert ct.load(tmp_path / "optimum.toml").model.cam.base_radius == pytest.approx(
        13.5912e-3, abs=2e-7)


@pytest.mark.parametrize("args, field", [
    (["--var", "base_radius=25:10"], "--var"),
    (["--var", "cam.no_such_field=1:2"], "--var"),
    (["--var", "base_radius=10:25", "--constraint", "hertz_limit>=3"], "--constraint"),
    (["--var", "base_radius=10:25", "--objective", "no_such_metric"], "--objective"),
])
def test_cli_bad_arguments_exit_2_naming_the_option(args, field, tmp_path):
    run = _cli("optimize", HARRISON, *args, "--out", tmp_path / "out", "--quiet")
    assert run.returncode == 2, run.stderr
    assert field in run.stderr and "Traceback" not in run.stderr
    assert not (tmp_path / "out").exists()


def test_worker_processes_give_the_serial_optimum():
    serial = opt.optimize(HARRISON, ["base_radius=12:24", "spring.preload_compression=1:12"],
                          constraints=["no_separation=3000", "no_concave_flank"])
    shared = opt.optimize(HARRISON, ["base_radius=12:24", "spring.preload_compression=1:12"],
                          constraints=["no_separation=3000", "no_concave_flank"], jobs=2)
    assert shared.optimum.x == serial.optimum.x
    assert shared.optimum.objective == serial.optimum.objective


def test_dask_scheduler_gives_the_serial_optimum():
    distributed = pytest.importorskip("dask.distributed")
    serial = opt.optimize(HARRISON, ["spring.preload_compression=1:12"],
                          constraints=["no_separation=3000"])
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster:
        dask = opt.optimize(HARRISON, ["spring.preload_compression=1:12"],
                            constraints=["no_separation=3000"],
                            scheduler=cluster.scheduler_address)
    assert dask.optimum.x == serial.optimum.x
    assert dask.optimum.objective == serial.optimum.objective
    assert dask.evaluations == serial.evaluations


def test_design_events_as_variables_redesign_the_lift(tmp_path):
    import tomllib

    import tomli_w

    raw = tomllib.loads(HARRISON.read_text(encoding="utf-8"))
    raw["design"] = {"max_lift": 9.4, "checking_heights": [1.0], "opening_angles": [54.2],
                     "ramp_height": 0.5, "ramp_length": 25.0, "max_acceleration": 0.0324,
                     "max_deceleration": 0.0075, "symmetric": True}
    deck = tmp_path / "events.toml"
    deck.write_text(tomli_w.dumps(raw), encoding="utf-8")
    out = ct.optimize(deck, ["design.opening_angles[0]=50:58"], constraints=["open_area=3"],
                      out_dir=tmp_path / "out", plots=False, maxiter=2)
    assert not out.problem.route.batch
    assert out.optimum.designed_lift is not None
    rerun = ct.load(tmp_path / "out" / "optimum.toml").model
    assert rerun.lift.form == "spline"
    assert rerun.design.opening_angles[0] == pytest.approx(np.radians(out.optimum.x[0]))
    assert ct.run(rerun).metrics["power_loss_mean"].value == pytest.approx(
        out.optimum.objective, rel=1e-9)
