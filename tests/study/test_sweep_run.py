"""Running sweeps: executors agree, failures are recorded, resume, outputs, the command line."""
from __future__ import annotations

import csv
import dataclasses

import pytest
from click.testing import CliRunner

from camtrain.cli_sweep import sweep as sweep_command
from camtrain.study.executors import SerialExecutor, run_case
from camtrain.study.runner import prepare, run_sweep
from camtrain.study.sweep_output import read_finished


def _rows(path):
    with path.open(newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def test_serial_and_process_pool_write_identical_tables(fast_flat, tmp_path):
    sweep = prepare(fast_flat, [("speed", "range", "1500:3000:4")])
    run_sweep(sweep, tmp_path / "serial", jobs=1, plots=False)
    run_sweep(sweep, tmp_path / "pool", jobs=2, plots=False)
    for name in ("sweep.csv", "trends.csv", "trends.md"):
        assert (tmp_path / "serial" / name).read_bytes() == (tmp_path / "pool" / name).read_bytes()


def test_failing_case_in_the_middle_does_not_stop_the_sweep(fast_flat, tmp_path):
    # 12 mm is below the concavity limit of the Harrison cam (13.59 mm): invalid geometry
    sweep = prepare(fast_flat, [("base_radius", "values", "16,12,20")])
    outcome = run_sweep(sweep, tmp_path, executor=SerialExecutor(), plots=False)
    assert [r["status"] for r in outcome.records] == ["ok", "failed", "ok"]
    rows = _rows(tmp_path / "sweep.csv")
    assert rows[1]["status"] == "failed" and "GeometryError" in rows[1]["message"]
    assert "base-circle radius must exceed" in rows[1]["message"]
    assert rows[1]["max_lift[mm]"] == "" and rows[2]["max_lift[mm]"] != ""
    assert rows[0]["base_radius[mm]"] == "16.0"


def test_loss_of_contact_is_recorded_and_left_out_of_trends(fast_flat, tmp_path):
    sweep = prepare(fast_flat, [("speed", "values", "2000,2500,4500")])
    outcome = run_sweep(sweep, tmp_path, executor=SerialExecutor(), plots=False)
    assert [r["status"] for r in outcome.records] == ["ok", "ok", "lost_contact"]
    assert "contact" in outcome.records[2]["message"]
    load = {t.parameter: t for t in outcome.trends if t.metric == "load_min"}["speed"]
    assert load.points == 2


class _StopAfter(SerialExecutor):
    """Serial executor that is 'interrupted' (Ctrl-C) after n cases, counting what it ran."""

    def __init__(self, n: int | None = None):
        self.n, self.ran = n, []

    def map(self, fn, jobs):
        for job in jobs:
            # a chunk of the batch path is taken case by case, so the interrupt can fall
            # between any two cases
            for one in ([job] if hasattr(job, "case") else
                        [dataclasses.replace(job, cases=(c,)) for c in job.cases]):
                if self.n is not None and len(self.ran) == self.n:
                    raise KeyboardInterrupt
                self.ran.append(one.case.index if hasattr(one, "case") else one.cases[0].index)
                yield fn(one)


def test_interrupted_sweep_keeps_finished_cases_and_resume_gives_the_same_table(fast_flat,
                                                                               tmp_path):
    sweep = prepare(fast_flat, [("base_radius", "values", "16,12,20"),
                                ("speed", "values", "1500,2500")])
    full = tmp_path / "full"
    run_sweep(sweep, full, executor=SerialExecutor(), plots=False)
    part = tmp_path / "part"
    with pytest.raises(KeyboardInterrupt):
        run_sweep(sweep, part, executor=_StopAfter(3), plots=False)
    assert len(_rows(part / "sweep.csv")) == 3
    second = _StopAfter()
    outcome = run_sweep(sweep, part, executor=second, resume=True, plots=False)
    assert second.ran == [3, 4, 5] and outcome.reused == 3
    for name in ("sweep.csv", "trends.csv", "trends.md"):
        assert (part / name).read_bytes() == (full / name).read_bytes()
    # resuming a finished sweep runs nothing
    third = _StopAfter()
    run_sweep(sweep, part, executor=third, resume=True, plots=False)
    assert third.ran == []


def test_resume_reruns_cases_whose_values_changed(fast_flat, tmp_path):
    run_sweep(prepare(fast_flat, [("speed", "values", "1500,2000")]), tmp_path,
              executor=SerialExecutor(), plots=False)
    sweep = prepare(fast_flat, [("speed", "values", "1500,2200")])
    assert sorted(read_finished(tmp_path / "sweep.csv", sweep.params, sweep.cases)) == [0]


def test_resume_refuses_a_changed_deck(fast_flat, tmp_path):
    run_sweep(prepare(fast_flat, [("speed", "values", "1500")]), tmp_path,
              executor=SerialExecutor(), plots=False)
    fast_flat.write_text(fast_flat.read_text().replace("width = 12.0", "width = 13.0"))
    with pytest.raises(Exception, match="changed since the sweep"):
        run_sweep(prepare(fast_flat, [("speed", "values", "1500")]), tmp_path,
                  executor=SerialExecutor(), resume=True, plots=False)


def test_internal_errors_are_recorded_not_raised(fast_flat):
    sweep = prepare(fast_flat, [("speed", "values", "1500")])
    job = __import__("camtrain.study.executors", fromlist=["Job"]).Job(
        {"not": "a deck", "cam": 5}, tuple(sweep.params), sweep.cases[0], "x", ".")
    record = run_case(job)
    assert record["status"] in ("failed", "error") and record["message"]


def test_outputs_plots_and_curves(fast_flat, tmp_path):
    sweep = prepare(fast_flat, [("speed", "values", "1500,2500")],
                    sets=["solver.angle_points=120"])
    outcome = run_sweep(sweep, tmp_path, executor=SerialExecutor(), overlay_max=2)
    names = {p.relative_to(tmp_path).as_posix() for p in outcome.written}
    assert {"sweep.csv", "sweep.json", "trends.csv", "trends.md", "plots/metrics_vs_speed.png",
            "plots/overlay_curves.png"} <= names
    assert (tmp_path / "curves" / "case_00001.csv").is_file()
    header = (tmp_path / "sweep.csv").read_text().splitlines()[0]
    assert header.startswith("case,speed[rpm],status,message,") and "max_lift[mm]" in header


def test_generic_trend_of_a_dotted_path(fast_flat, tmp_path):
    sweep = prepare(fast_flat, [("lift.ramps.opening_height", "values", "0.4,0.5"),
                                ("lift.ramps.closing_height", "values", "0.4,0.5")], zipped=True)
    outcome = run_sweep(sweep, tmp_path, executor=SerialExecutor(), plots=False)
    trends = {t.metric: t.trend for t in outcome.trends}
    assert trends["max_lift"] == "rises" and trends["opening_angle"] == "constant"


# ------------------------------------------------------------------ the command line

def _invoke(args):
    return CliRunner().invoke(sweep_command, [str(a) for a in args])


def test_cli_sweep_runs_and_writes(fast_flat, tmp_path):
    res = _invoke([fast_flat, "--param", "base_radius", "--values", "16,12", "--jobs", "1",
                   "--no-plots", "--out", tmp_path])
    assert res.exit_code == 0, res.output
    assert "1 ok, 1 failed" in res.output
    assert len(_rows(tmp_path / "sweep.csv")) == 2


def test_cli_relative_with_leading_minus_and_grid(fast_flat, tmp_path):
    res = _invoke([fast_flat, "-p", "speed", "--relative", "-20%:+20%:2", "-p", "cam_width",
                   "--values=11,12", "--jobs", "1", "--no-plots", "-q", "--out", tmp_path])
    assert res.exit_code == 0, res.output
    rows = _rows(tmp_path / "sweep.csv")
    assert [(r["speed[rpm]"], r["cam_width[mm]"]) for r in rows] == [
        ("2000.0", "11.0"), ("2000.0", "12.0"), ("3000.0", "11.0"), ("3000.0", "12.0")]


@pytest.mark.parametrize("args,fragment", [
    (["--param", "bse_radius", "--values", "1"], "did you mean base_radius"),
    (["--param", "base_radius", "--values", "-1"], "--values"),
    (["--param", "base_radius", "--range", "1:2"], "--range"),
    (["--param", "speed", "--values", "1,2", "--param", "cam_width", "--values", "1",
      "--zip"], "--zip"),
    (["--param", "speed", "--values", "1", "--jobs", "0"], "--jobs"),
    (["--param", "speed", "--values", "1", "--set", "cam.nope=3"], "--set"),
    (["--values", "1"], "give --param NAME before it"),
    (["--param", "speed"], "give its values"),
    (["--param", "speed", "--values", "1", "--range", "1:2:3"], "one list per --param"),
    ([], "nothing to sweep"),
])
def test_cli_bad_arguments_exit_2_without_traceback(fast_flat, tmp_path, args, fragment):
    res = _invoke([fast_flat, *args, "--out", tmp_path / "o"])
    assert res.exit_code == 2, res.output
    assert fragment in res.output and "Traceback" not in res.output


def test_cli_missing_deck_exits_2(tmp_path):
    res = _invoke([tmp_path / "nope.toml", "--param", "speed", "--values", "1"])
    assert res.exit_code == 2 and "does not exist" in res.output


def test_module_import_is_light():
    import subprocess
    import sys

    code = ("import sys, camtrain.cli_sweep; "
            "print(any(m in sys.modules for m in ('numpy', 'matplotlib', 'rich')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


# ------------------------------------------------------------------ Dask

def test_dask_cluster_gives_the_same_table(fast_flat, tmp_path):
    distributed = pytest.importorskip("dask.distributed", reason="dask is not installed "
                                      "(optional extra camtrain[dask])")
    sweep = prepare(fast_flat, [("speed", "range", "1500:3000:3")])
    run_sweep(sweep, tmp_path / "serial", executor=SerialExecutor(), plots=False)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster:
        run_sweep(sweep, tmp_path / "dask", scheduler=cluster.scheduler_address, plots=False)
    assert (tmp_path / "dask" / "sweep.csv").read_bytes() == \
        (tmp_path / "serial" / "sweep.csv").read_bytes()


def test_scheduler_without_dask_is_a_clear_error(fast_flat, tmp_path):
    try:
        import dask.distributed  # noqa: F401
        pytest.skip("dask is installed")
    except ImportError:
        pass
    res = _invoke([fast_flat, "--param", "speed", "--values", "1500", "--scheduler",
                   "tcp://127.0.0.1:1", "--out", tmp_path])
    assert res.exit_code == 2 and "camtrain[dask]" in res.output


@pytest.mark.parametrize("first, second", [
    (["--set", "solver.angle_points=120"], ["--set", "solver.angle_points=150"]),
    ([], ["--set", "spring.rate=30"]),
    (["--zip", "-p", "speed", "--values", "1500,2000"], ["-p", "speed", "--values", "1500,2000"]),
])
def test_resume_refuses_a_changed_sweep_definition(fast_flat, tmp_path, first, second):
    base = [str(fast_flat), "-p", "base_radius", "--values", "17,18", "--out", str(tmp_path),
            "-j", "1", "--no-plots", "-q"]
    res = CliRunner().invoke(sweep_command, base + first)
    assert res.exit_code == 0, res.output
    before = (tmp_path / "sweep.csv").read_bytes()
    res = CliRunner().invoke(sweep_command, base + second + ["--resume"])
    assert res.exit_code == 2, res.output
    assert "sweep definition changed" in res.output
    assert (tmp_path / "sweep.csv").read_bytes() == before
    res = CliRunner().invoke(sweep_command, base + first + ["--resume"])
    assert res.exit_code == 0, res.output
