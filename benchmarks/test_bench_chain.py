"""Benchmarks of the analysis chain, a whole `camtrain run` and one bearing orbit (`make bench`).

Each is paired with a floor where one makes sense: the cost of comparable numpy work alone.
Numbers and targets are discussed in docs/performance.md; nothing here asserts a time.
"""
from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np

from camtrain import api
from camtrain.deck.load import load_deck_text

ROOT = Path(__file__).resolve().parent.parent
DECK = (ROOT / "decks" / "harrison_flat.toml").read_text()
N = 3600


def test_bench_chain_3600(benchmark):
    """All six effects of the Harrison deck at 3600 angles (target < 5 ms)."""
    model = load_deck_text(DECK.replace("angle_points = 720", f"angle_points = {N}")).model
    api.run(model)  # imports and caches outside the timing
    benchmark(api.run, model)


def test_bench_chain_floor_3600(benchmark):
    """Floor: the four-power law and its derivatives at 3600 angles plus 60 more elementwise
    array operations, about the array work the chain does (no Python-level structure)."""
    theta = -math.pi + 2 * math.pi * np.arange(N) / N
    exps = np.array([2.0, 9.0, 78.0, 80.0])
    coef = np.array([-11.69, 2.85, -0.589, 0.531])

    def floor():
        x = np.clip(np.abs(theta) / (math.pi / 3), 0.0, 1.0)
        powers = x[None, :] ** exps[:, None]
        lift = 8.9 + coef @ powers
        d1 = coef * exps @ (powers / np.maximum(x, 1e-12))
        y = lift
        for _ in range(60):
            y = y * 1.0000001 + d1
        return y

    benchmark(floor)


def test_bench_run_process(benchmark, tmp_path):
    """`camtrain run DECK --no-plots --quiet` as a whole process (target < 1 s)."""
    deck = ROOT / "decks" / "harrison_flat.toml"
    cmd = [sys.executable, "-m", "camtrain.cli", "run", str(deck), "--no-plots", "--quiet", "--out",
           str(tmp_path / "out")]
    benchmark.pedantic(lambda: subprocess.run(cmd, capture_output=True, check=True),
                       rounds=5, iterations=1)


def test_bench_python_start_floor(benchmark):
    """Floor of any process: the interpreter starting and importing numpy."""
    cmd = [sys.executable, "-c", "import numpy"]
    benchmark.pedantic(lambda: subprocess.run(cmd, capture_output=True, check=True),
                       rounds=5, iterations=1)


def test_bench_bearing_orbit(benchmark):
    """One journal orbit to periodicity: 36-point cyclic load diagram (target < 100 ms)."""
    from camtrain.bearings import JournalBearing, bearing_orbit

    brg = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
    th = np.arange(36) * (2 * math.pi / 36)
    fx, fy = np.zeros(36), -2000.0 * (1.2 + np.cos(th))
    benchmark(bearing_orbit, brg, fx, fy, th, 157.0)
