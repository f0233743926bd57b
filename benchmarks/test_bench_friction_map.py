"""Benchmarks of the engine friction maps (`make bench`; docs/engine.md, "Friction maps"):

* the Ford Zeta engine over 7 speeds x 4 loads (IMEP) x 3 oil temperatures, FLAME and the
  correlations at every point through the sweep machinery (one worker process), with its CPU
  time (this process and the workers it waited for), against a floor of the same count of
  ring-film steps;
* the correlation-only map of the bare engine deck on the same grid (vectorised), against a
  bare-numpy evaluation of the same 13 terms; target: well under a second.

Nothing here asserts a time."""
from __future__ import annotations

import time

import numpy as np
from conftest import cpu_seconds, note, paired

from camtrain import api
from camtrain.study.friction_map import correlation_map
from camtrain.study.friction_sweep import sweep_map
from tests.conftest import DECKS

SPEEDS = (2000, 3000, 4000, 5000, 6000, 6400, 7000)
IMEP = (4.0, 6.0, 8.0, 10.0)                 # bar
TEMPERATURES = (70.0, 95.0, 120.0)           # °C
BARE = api.load(DECKS / "zeta_bare_engine.toml").model
INTAKE = (0.4, 0.6, 0.8, 1.0)                # the bare deck's load axis: p_i/p_a


def ring_floor(points: int) -> float:
    """Floor: one vectorised parabolic-face load evaluation per ring step of the map (2 rings x
    (flooded + 2 starved passes) x ~2 cycles x 720 steps x ~20 root iterations per point)."""
    n = 2 * 3 * 2 * 720 * points * 20
    h = np.linspace(0.05e-6, 5e-6, n)
    t = 7.4e-4 / np.sqrt(2 * 0.063 * h)
    return float(np.sum(np.arctan(t) * (1 + t * t) / (h * h)))


def test_bench_zeta_friction_map(benchmark, record_ratio, tmp_path):
    """7 x 4 x 3 = 84 FLAME runs (and the correlations beside each) in one worker."""
    api.run(api.load(DECKS / "zeta_engine.toml").model)    # numba caches compiled on disk
    out = {}

    def subject():
        out["map"] = sweep_map(DECKS / "zeta_engine.toml", SPEEDS, IMEP, TEMPERATURES,
                               tmp_path / "sweep", measure="imep", jobs=1)

    cpu, start = cpu_seconds(), time.perf_counter()
    benchmark.pedantic(subject, rounds=1, iterations=1)
    wall, cpu = time.perf_counter() - start, cpu_seconds() - cpu
    t, c = time.perf_counter(), cpu_seconds()
    ring_floor(len(SPEEDS) * len(IMEP) * len(TEMPERATURES))
    fwall, fcpu = time.perf_counter() - t, cpu_seconds() - c
    timing = {"subject_median": wall, "subject_min": wall, "floor_median": fwall,
              "floor_min": fwall, "ratio": wall / fwall, "ratio_min": wall / fwall,
              "cpu_subject_min": cpu, "cpu_floor_min": fcpu,
              "cpu_ratio_min": cpu / max(fcpu, 1e-9)}
    fmap = out["map"]
    assert np.all(np.isfinite(fmap.totals["flame"]))
    record_ratio(benchmark, "Zeta friction map 7x4x3 (FLAME + correlations)", timing,
                 "CPU time reported", cpu=True)
    note("Zeta friction map 7x4x3: CPU time", f"{cpu:.1f} s ({cpu / 84:.2f} s a point)")


def _floor_terms():
    """Floor: the 13 terms' arithmetic on the 84 points in bare numpy."""
    n = np.repeat(np.asarray(SPEEDS, dtype=float), 12)
    r = np.sqrt(np.tile(np.repeat([12.0, 9.0, 7.0], 4), 7) / 10.6)
    pi = np.tile(np.asarray(INTAKE * 3), 7)
    sp = 2 * 88.0 / 1000 * n / 60
    total = (1.22e5 * 58 / (80.6**2 * 88 * 4) + 3.03e-4 * r * n * 58**3 * 18.3 * 5
             / (80.6**2 * 88 * 4) + 1.35e-10 * 58**2 * n**2 * 5 / 4 + 2.94e2 * r * sp / 80.6
             + 4.06e4 * (1 + 500 / n) / 80.6**2
             + 6.89 * pi * (0.088 * r * 10 + 0.182 * 10 ** (1.33 - 2.38e-2 * sp))
             + 3.03e-4 * r * n * 46.9**3 * 19.1 / (80.6**2 * 88) + 244 * r * n * 10
             / (80.6**2 * 88 * 4) + 4.12 + 133 * (1 + 500 / n) * 16 / (88 * 4)
             + 0.5 * r * 8.78**1.5 * np.sqrt(n) * 16 / (80.6 * 88 * 4)
             + 10.7 * (1 + 500 / n) * 8.78 * 16 / (88 * 4) + 6.23 + 5.22e-3 * n - 1.79e-7 * n**2)
    return float(np.sum(total))


def test_bench_bare_correlation_map(benchmark, record_ratio):
    """The bare engine deck's correlation map, 7 x 4 x 3, three models, vectorised."""
    def subject():
        correlation_map(BARE, SPEEDS, INTAKE, TEMPERATURES)

    timing = paired(subject, _floor_terms, rounds=21)
    benchmark.pedantic(subject, rounds=5, iterations=1)
    record_ratio(benchmark, "bare-engine correlation map 7x4x3", timing, "well under 1 s")
