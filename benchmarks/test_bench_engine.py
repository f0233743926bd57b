"""Benchmarks of the crank train (`make bench`): one Ruston big-end orbit to periodicity and a
whole Ruston engine (6 big-ends, 7 mains) at one speed, with a bare-numpy floor of the same
number of right-hand-side evaluations. Targets (docs/engine.md): an orbit well under 1 s, an
engine in a few seconds. Nothing here asserts a time."""
from __future__ import annotations

import math

import numpy as np

from camtrain.bearings import bearing_orbit
from camtrain.engine import SolverOptions, crank_grid, cylinder_loads, solve_engine_bearings
from tests.engine.yang_engines import (
    RUSTON_OMEGA,
    RUSTON_PRESSURE_BAR,
    ruston_bearing,
    ruston_crank,
    ruston_engine,
    table,
)

TH = crank_grid(4.0 * math.pi, math.radians(0.5))
LOADS = cylinder_loads(ruston_crank(), table(RUSTON_PRESSURE_BAR), 0.0, TH, RUSTON_OMEGA)
BRG = ruston_bearing().variants()["ungrooved"]


def _orbit(mobility):
    return bearing_orbit(BRG, LOADS.load_x, LOADS.load_y, TH, LOADS.omega_journal, 0.0,
                         angle_rate=RUSTON_OMEGA, period=4.0 * math.pi, film="2pi",
                         mobility=mobility, start="centre")


def test_bench_ruston_big_end_orbit_booker(benchmark):
    """One big-end orbit, Booker mobility, 0.5 deg, 3 cycles to period_tol 1e-5."""
    benchmark.pedantic(_orbit, args=("booker",), rounds=3, iterations=1)


def test_bench_ruston_big_end_orbit_exact(benchmark):
    """The same with the exact pi-film mobility (the default)."""
    benchmark.pedantic(_orbit, args=("exact",), rounds=3, iterations=1)


def test_bench_ruston_engine(benchmark):
    """Loads, dynamic + steady + Petroff for 13 bearings (shifted duplicates reused)."""
    benchmark.pedantic(solve_engine_bearings, args=(ruston_engine(), RUSTON_OMEGA,
                                                     ruston_bearing(), ruston_bearing()),
                       kwargs=dict(options=SolverOptions()), rounds=1, iterations=1)


def test_bench_orbit_floor(benchmark):
    """Floor: the same count of Booker mobility evaluations (3 cycles x 1440 intervals x ~7
    stages) done as one vectorised numpy expression."""
    n = 3 * TH.size * 7
    xi = np.linspace(-0.9, 0.9, n)
    mu = np.linspace(0.5, -0.5, n)

    def floor():
        s = 1.0 - xi
        return s ** 2.5 / math.pi, -4.0 * mu * s ** 1.5 / math.pi ** 2

    benchmark(floor)


def _floor():
    """The orbit floor above as a function: one vectorised pass over the mobility count of
    one big-end orbit (3 cycles x 1440 intervals x ~7 stages)."""
    n = 3 * TH.size * 7
    xi = np.linspace(-0.9, 0.9, n)
    mu = np.linspace(0.5, -0.5, n)
    s = 1.0 - xi
    return s ** 2.5 / math.pi, -4.0 * mu * s ** 1.5 / math.pi ** 2


def test_bench_ruston_big_end_orbit_ratio(benchmark, record_ratio):
    """One bearing orbit to periodicity (exact mobility, 0.5 deg), paired with its floor."""
    from conftest import paired

    timing = paired(lambda: _orbit("exact"), _floor, rounds=3)
    record_ratio(benchmark, "Ruston big-end orbit to periodicity", timing, "well under 1 s")
    benchmark.pedantic(_orbit, args=("exact",), rounds=1, iterations=1)


def test_bench_ruston_deck(benchmark, record_ratio):
    """The whole Ruston engine at one speed through the deck and the effects (crank_loads,
    crank_bearings: 6 big-ends, 7 mains, dynamic + steady + Petroff), as `camtrain run` does
    it without writing."""
    from conftest import ROOT, paired

    import camtrain.api as api

    model = api.load(ROOT / "decks" / "ruston_6veb.toml").model
    timing = paired(lambda: api.run(model), _floor, rounds=2)
    record_ratio(benchmark, "Ruston engine deck at 600 rpm (13 bearings)", timing, "a few s")
    benchmark.pedantic(api.run, args=(model,), rounds=1, iterations=1)


def test_bench_zeta_deck(benchmark, record_ratio):
    """The Zeta crank-bearing deck at 3000 rpm: partially grooved mains, so every main is
    solved twice (ungrooved and grooved)."""
    from conftest import ROOT, paired

    import camtrain.api as api

    model = api.load(ROOT / "decks" / "zeta_crank_bearings.toml").model
    timing = paired(lambda: api.run(model), _floor, rounds=2)
    record_ratio(benchmark, "Zeta crank-bearing deck at 3000 rpm (4 + 2 x 5 orbits)", timing,
                 "a few s")
    benchmark.pedantic(api.run, args=(model,), rounds=1, iterations=1)
