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
