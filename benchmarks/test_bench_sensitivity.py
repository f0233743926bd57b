"""A 10,240-case Sobol' study of decks/harrison_flat.toml (flat tappet, 1440 angles) as a whole
`camtrain sensitivity` process through the batch route: 2048 base samples of three inputs
(viscosity, pressure-viscosity coefficient, cam width; Saltelli's N (D + 2) cases), tables only
(`make bench`; figures in docs/sensitivity.md). Target: under a minute of CPU time.

Floor: one process that imports numpy and runs the bare-numpy Harrison chain
(``harrison_floor.py``) for the same 10,240 sets of inputs.
"""
from __future__ import annotations

import subprocess
import sys

from conftest import ENV, ROOT, note, paired, record

DECK = str(ROOT / "decks" / "harrison_flat.toml")
SAMPLES = 2048
INPUTS = [("viscosity", "log-uniform", "0.01:0.1"),
          ("lubricant.pressure_viscosity", "log-uniform", "10:30"),
          ("cam_width", "uniform", "8:16")]
CASES = SAMPLES * (len(INPUTS) + 2)
FLOOR = f"""
import sys; sys.path.insert(0, 'benchmarks')
from harrison_floor import HARRISON, harrison_floor
from camtrain.study.sensitivity import prepare
study = prepare({DECK!r}, {INPUTS!r}, samples={SAMPLES}, seed=1)
for case in study.sweep.cases:
    v = case.as_dict()
    harrison_floor(1440, dict(HARRISON, eta0=v['viscosity'],
                   alpha=v['lubricant.pressure_viscosity'] * 1e-9, width=v['cam_width'] * 1e-3))
"""


def _cmd(out) -> list[str]:
    args = [a for name, kind, text in INPUTS for a in ("-p", name, f"--{kind}", text)]
    return [sys.executable, "-m", "camtrain.cli", "sensitivity", DECK, *args, "-n",
            str(SAMPLES), "--no-plots", "--quiet", "--jobs", "1", "--out", str(out)]


def _run(cmd):
    return lambda: subprocess.run(cmd, capture_output=True, check=True, cwd=ROOT, env=ENV)


def test_bench_sobol_10240_cases(benchmark, tmp_path):
    study = _run(_cmd(tmp_path / "out"))
    timing = paired(study, _run([sys.executable, "-c", FLOOR]), rounds=1, warmup=0)
    what = f"Sobol' study, {CASES} cases of harrison_flat (1440 angles), --jobs 1"
    record(benchmark, f"{what}, whole process", timing, cpu=True)
    note(f"{what}: CPU time", f"{timing['cpu_subject_min']:.1f} s", "< 60 s")
    benchmark.extra_info["cpu_seconds"] = timing["cpu_subject_min"]
    assert (tmp_path / "out" / "indices.csv").is_file()
    benchmark.pedantic(study, rounds=1, iterations=1)


def test_bench_sobol_10240_cases_on_a_local_dask_cluster(benchmark, tmp_path):
    """The same study on a local Dask cluster (two worker processes) gives the same indices as
    one process (to 1e-12: the cluster's batch chunks are cut differently, see
    tests/study/test_sensitivity.py)."""
    import math

    import pytest

    distributed = pytest.importorskip("dask.distributed")
    from camtrain.study.sensitivity import prepare
    from camtrain.study.sensitivity_run import run_study

    study = prepare(DECK, INPUTS, samples=SAMPLES, seed=1)
    serial = run_study(study, tmp_path / "serial", jobs=1, plots=False)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster:
        dask = benchmark.pedantic(lambda: run_study(study, tmp_path / "dask",
                                                    scheduler=cluster.scheduler_address,
                                                    plots=False), rounds=1, iterations=1)
    assert dask.route.batch and len(dask.indices) == len(serial.indices)
    worst = max(abs(a[k] - b[k]) / max(abs(b[k]), 1e-12)
                for a, b in zip(dask.indices, serial.indices, strict=True)
                for k in ("S1", "ST", "S1_conf", "ST_conf"))
    note(f"Sobol' study, {CASES} cases on a local Dask cluster: largest relative difference of "
         "an index from one process", f"{worst:.1e}", "<= 1e-12")
    assert math.isfinite(worst) and worst <= 1e-12
