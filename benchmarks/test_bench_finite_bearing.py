"""Finite-length journal bearing (`make bench`; figures in docs/bearings.md and performance.md).

* One Reynolds solution at the default mesh (120 x 12, b/d 0.72, eps 0.8, Swift-Stieber
  cavitation) against its floor: one sparse LU solve of the same-size five-point system (the
  unavoidable part of any implicit solution).
* The steady eccentricity-from-load solve (~12 Reynolds solutions), in ms.
* An orbit to periodicity through the finite mobility map against the short-bearing orbit of
  the same load diagram (the exact pi-film mobility): the ratio the cost class is judged by.
* Building one map (~200 coarse Reynolds solutions), once per b/d, then cached.
"""
from __future__ import annotations

import math

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from conftest import note, paired, record

from camtrain.bearings import JournalBearing, bearing_orbit
from camtrain.bearings.finite import finite_steady
from camtrain.bearings.reynolds import FilmGrid, solve_film

BRG = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
OMEGA = 1500 * 2 * math.pi / 60
TH = np.arange(36) * (2 * math.pi / 36)
LX, LY = np.zeros(36), -2000.0 * (1.2 + np.cos(TH))


def _floor_solve(grid: FilmGrid):
    n = grid.size
    nt = grid.n_theta
    lap = sp.diags([-1.0, -1.0, 4.0, -1.0, -1.0], [-nt, -1, 0, 1, nt], shape=(n, n),
                   format="csc")
    b = np.ones(n)
    return lambda: spla.splu(lap, permc_spec="MMD_AT_PLUS_A").solve(b)


def test_bench_reynolds_solve(benchmark):
    grid = FilmGrid(0.72, 120, 12)
    timing = paired(lambda: solve_film(grid, 0.8, cavitation="reynolds"), _floor_solve(grid),
                    rounds=30)
    record(benchmark, "finite bearing: one Reynolds solution (120 x 12, reynolds)", timing)
    benchmark.pedantic(solve_film, args=(grid, 0.8), rounds=3, iterations=1)


def test_bench_steady_finite(benchmark):
    finite_steady(BRG, 500.0, OMEGA)
    benchmark.pedantic(finite_steady, args=(BRG, 500.0, OMEGA), rounds=5, iterations=1)
    note("finite bearing: steady eccentricity-from-load solve (default mesh)",
         f"{benchmark.stats.stats.median * 1e3:.3g} ms")


def test_bench_finite_orbit_vs_short(benchmark, tmp_path, monkeypatch):
    import time

    from camtrain.bearings.finite_map import _correction_table, bearing_mobility_map

    monkeypatch.setenv("CAMTRAIN_CACHE", str(tmp_path))
    t = time.perf_counter()
    _correction_table.__wrapped__(0.72, "reynolds", 72, 6, False)
    note("finite bearing: one mobility map table (cold, ~200 solutions)",
         f"{time.perf_counter() - t:.3g} s", "once per b/d, then cached")
    fmap = bearing_mobility_map(BRG)
    timing = paired(lambda: bearing_orbit(BRG, LX, LY, TH, OMEGA, mobility=fmap),
                    lambda: bearing_orbit(BRG, LX, LY, TH, OMEGA), rounds=30)
    record(benchmark, "finite-map orbit against the short-bearing orbit (floor)", timing,
           "a few x")
    benchmark.pedantic(bearing_orbit, args=(BRG, LX, LY, TH, OMEGA),
                       kwargs={"mobility": fmap}, rounds=3, iterations=1)
