"""Sweep throughput and memory: 1000 base-radius cases of decks/harrison_flat.toml as whole
`camtrain sweep` processes, tables only (`make bench`; figures in docs/performance.md).

Floor: one process that imports numpy and runs the bare-numpy Harrison chain
(``harrison_floor.py``) for the same 1000 base radii.
"""
from __future__ import annotations

import subprocess
import sys

import pytest
from conftest import ENV, ROOT, note, paired, record

DECK = str(ROOT / "decks" / "harrison_flat.toml")
CASES = 1000
FLOOR = ("import sys; sys.path.insert(0, 'benchmarks'); import numpy as np; "
         "from harrison_floor import HARRISON, harrison_floor\n"
         f"for r in np.linspace(14e-3, 22e-3, {CASES}): harrison_floor(720, dict(HARRISON, "
         "base_radius=float(r)))")
# Peak resident memory of the sweep and every worker it started (the largest single process).
PEAK = ("import resource, subprocess, sys; subprocess.run(sys.argv[1:], check=True, "
        "capture_output=True); print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")


def _sweep_cmd(out, jobs: int, points: int | None = None) -> list[str]:
    grid = ["--set", f"solver.angle_points={points}"] if points else []
    return [sys.executable, "-m", "camtrain.cli", "sweep", DECK, "-p", "base_radius", "--range",
            f"14:22:{CASES}", *grid, "--no-plots", "--quiet", "--force", "--jobs", str(jobs), "--out",
            str(out)]


def _floor(points: int) -> str:
    return FLOOR.replace("harrison_floor(720,", f"harrison_floor({points},")


def _run(cmd):
    return lambda: subprocess.run(cmd, capture_output=True, check=True, cwd=ROOT, env=ENV)


@pytest.mark.parametrize("points", [1440, 720])
@pytest.mark.parametrize("jobs", [1, 2])
def test_bench_sweep_1000(benchmark, tmp_path, jobs, points):
    """At the deck's grid (1440 angles, the default) and at the 720 of the target's setting."""
    sweep = _run(_sweep_cmd(tmp_path / "out", jobs, None if points == 1440 else points))
    timing = paired(sweep, _run([sys.executable, "-c", _floor(points)]), rounds=2, warmup=0)
    what = f"sweep, {CASES} cases, {points} angles, --jobs {jobs}"
    record(benchmark, f"{what}, whole process", timing, cpu=True)
    note(f"{what}: cases/s",
         f"{CASES / timing['subject_median']:.0f}/s, fastest round "
         f"{CASES / timing['subject_min']:.0f}/s (floor {CASES / timing['floor_median']:.0f}/s)",
         ">= 1000/s")
    benchmark.extra_info["cases_per_second"] = CASES / timing["subject_median"]
    benchmark.pedantic(sweep, rounds=1, iterations=1)


@pytest.mark.parametrize("points", [1440, 720])
def test_bench_sweep_jobs_2_against_jobs_1(benchmark, tmp_path, points):
    """`--jobs 2` against `--jobs 1`, run in turn (five pairs after one of each): the ratio of
    their medians is the figure, since a few per cent decide it and the load moves both."""
    grid = None if points == 1440 else points
    two = _run(_sweep_cmd(tmp_path / "two", 2, grid))
    one = _run(_sweep_cmd(tmp_path / "one", 1, grid))
    timing = paired(two, one, rounds=5)
    record(benchmark, f"sweep, {CASES} cases, {points} angles, --jobs 2 / --jobs 1", timing,
           "< 1x", cpu=True)
    benchmark.pedantic(two, rounds=1, iterations=1)


def test_bench_sweep_peak_memory(benchmark, tmp_path):
    cmd = [sys.executable, "-c", PEAK, *_sweep_cmd(tmp_path / "out", 2)]
    out = benchmark.pedantic(lambda: subprocess.run(cmd, capture_output=True, check=True,
                                                    cwd=ROOT, text=True, env=ENV).stdout,
                             rounds=1, iterations=1)
    mb = int(out.split()[-1]) / 1024.0
    benchmark.extra_info["peak_rss_mb"] = mb
    note(f"peak memory, {CASES}-case sweep (largest process)", f"{mb:.0f} MB", "<= 95 MB")
