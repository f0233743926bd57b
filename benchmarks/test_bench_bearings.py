"""Bearing orbits: one journal orbit of a 36-point load diagram, warm, and the whole Zeta intake
camshaft deck (five bearing orbits), warm (`make bench`; figures in docs/performance.md).

The orbit has no bare-numpy floor: it is a march in time; its targets are absolute (<= 1 ms for
one orbit, <= 0.1 s for the camshaft deck).
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import ENV, ROOT, note

from camtrain import api


def _orbit_case():
    from camtrain.bearings import JournalBearing

    brg = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
    th = np.arange(36) * (2 * math.pi / 36)
    return brg, np.zeros(36), -2000.0 * (1.2 + np.cos(th)), th


def test_bench_bearing_orbit(benchmark):
    """One journal orbit to periodicity, 36-point cyclic load diagram, exact mobility, warm."""
    import time

    from camtrain.bearings import bearing_orbit

    brg, fx, fy, th = _orbit_case()
    bearing_orbit(brg, fx, fy, th, 157.0)
    benchmark(bearing_orbit, brg, fx, fy, th, 157.0)
    c = time.process_time()
    for _ in range(100):
        bearing_orbit(brg, fx, fy, th, 157.0)
    cpu = (time.process_time() - c) / 100
    note("one journal orbit (36-point diagram), warm",
         f"{benchmark.stats.stats.median * 1e3:.3g} ms (min {benchmark.stats.stats.min * 1e3:.3g}"
         f" ms, cpu {cpu * 1e3:.3g} ms)", "<= 1 ms")


@pytest.mark.parametrize(("points", "orbit_points"), [(1440, 0), (1440, 360), (720, 0)])
def test_bench_zeta_camshaft(benchmark, points, orbit_points):
    """decks/zeta_intake_camshaft.toml in process (eight cams, five bearing orbits), warm, on
    the default grid (1440 angles) and on the 720 of the target's setting (the orbit's steps
    span load intervals, so its cost no longer follows the grid; the chain's still does), and
    with the orbits marched on 360 load angles (``camshaft.orbit_points``, within 0.05 % here)."""
    import dataclasses
    import time

    model = api.load(ROOT / "decks" / "zeta_intake_camshaft.toml").model
    model = dataclasses.replace(model, solver=dataclasses.replace(model.solver,
                                                                   angle_points=points),
                                camshaft=dataclasses.replace(model.camshaft,
                                                             orbit_points=orbit_points))
    api.run(model)
    cpu = []

    def timed():
        c = time.process_time()
        api.run(model)
        cpu.append(time.process_time() - c)

    benchmark.pedantic(timed, rounds=5, iterations=1)
    orbits = f", orbits on {orbit_points}" if orbit_points else ""
    note(f"`zeta_intake_camshaft` run, warm, {points} angles{orbits}",
         f"{benchmark.stats.stats.median:.3g} s (min {benchmark.stats.stats.min:.3g} s, "
         f"cpu min {min(cpu):.3g} s)", "<= 0.1 s")


_FIRST_CALL = """
import math, time
import numpy as np
from camtrain.bearings import JournalBearing, bearing_orbit
brg = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
th = np.arange(36) * (2 * math.pi / 36)
fx, fy = np.zeros(36), -2000.0 * (1.2 + np.cos(th))
t = time.perf_counter(); bearing_orbit(brg, fx, fy, th, 157.0); first = time.perf_counter() - t
t = time.perf_counter(); bearing_orbit(brg, fx, fy, th, 157.0); warm = time.perf_counter() - t
print(first, warm)
"""


def test_bench_orbit_first_call(benchmark, tmp_path):
    """First orbit of a process: compiling the kernel (empty numba cache) and loading it from
    the on-disk cache, reported apart from the warm orbit."""
    import subprocess
    import sys

    def first_call(cache):
        env = dict(ENV, NUMBA_CACHE_DIR=str(cache))
        out = subprocess.run([sys.executable, "-c", _FIRST_CALL], capture_output=True,
                             check=True, text=True, env=env, cwd=ROOT).stdout.split()
        return float(out[0]) - float(out[1])

    cold = benchmark.pedantic(first_call, args=(tmp_path / "numba",), rounds=1, iterations=1)
    cached = first_call(tmp_path / "numba")
    benchmark.extra_info.update(compile_s=cold, cached_load_s=cached)
    note("orbit kernel: compile on first call (empty cache)", f"{cold:.3g} s")
    note("orbit kernel: load from the disk cache (first call)", f"{cached * 1e3:.3g} ms")
