"""Benchmark of the whole Ford Zeta engine map (`make bench`): the engine deck at Yang's seven
Table 7.1 speeds (crank bearings, both camshafts, piston assembly, FLAME total), against a
bare-numpy floor of the same count of ring-film steps. Target (issue: whole engines part 2, and
docs/piston.md): the seven speeds in under a minute on the 2-core machine. Nothing here asserts
a time."""
from __future__ import annotations

import dataclasses
import math
import time

import numpy as np

from camtrain import api
from tests.conftest import DECKS

SPEEDS = (2000, 3000, 4000, 5000, 6000, 6400, 7000)
ZETA = api.load(DECKS / "zeta_engine.toml").model


def zeta_map():
    """Every speed of the map; returns the FLAME totals [W]."""
    out = []
    for rpm in SPEEDS:
        deck = dataclasses.replace(ZETA, speed=dataclasses.replace(
            ZETA.speed, engine=rpm * math.pi / 30.0))
        out.append(api.run(deck).metrics["flame_total"].value)
    return out


def floor():
    """Floor: one vectorised parabolic-face load evaluation per ring step of the map (2 rings x
    (flooded + 2 starved passes) x ~2 cycles x 720 steps x 7 speeds x ~20 root iterations)."""
    n = 2 * 3 * 2 * 720 * len(SPEEDS) * 20
    h = np.linspace(0.05e-6, 5e-6, n)
    t = 7.4e-4 / np.sqrt(2 * 0.063 * h)
    return float(np.sum(np.arctan(t) * (1 + t * t) / (h * h)))


def test_bench_zeta_engine_map(benchmark, record_ratio):
    """The whole Zeta map, 7 speeds (after one warm-up run: numba caches compile on disk)."""
    api.run(ZETA)
    cpu = time.process_time()
    timing = {"subject_median": 0.0}
    start = time.perf_counter()
    benchmark.pedantic(zeta_map, rounds=1, iterations=1)
    timing["subject_median"] = timing["subject_min"] = time.perf_counter() - start
    timing["cpu"] = time.process_time() - cpu
    t = time.perf_counter()
    floor()
    timing["floor_median"] = timing["floor_min"] = time.perf_counter() - t
    timing["ratio"] = timing["ratio_min"] = timing["subject_median"] / timing["floor_median"]
    record_ratio(benchmark, "Zeta engine map, 7 speeds (FLAME)", timing, "< 60 s")
