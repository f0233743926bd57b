"""Valve trains on the elastic camshaft (`make bench`; figures in docs/camshaft_dynamics.md).

Four elastic trains (one lobe per cylinder of the Zeta intake camshaft) on the elastic shaft,
marched together to their periodic state, warm (the compiled revolution loaded from its cache).
The issue's target: about 100 states through a periodic cycle in under 2 s on 2 cores. The march
has no bare-numpy floor: its figure is absolute.
"""
from __future__ import annotations

import time
import tomllib

from conftest import ROOT, note

from camtrain import api
from camtrain.deck.load import validate


def _four_trains(film_model: str = "steady", solver: str = "monolithic"):
    raw = tomllib.loads((ROOT / "decks" / "zeta_intake_camshaft_coupled.toml").read_text("utf-8"))
    raw["camshaft"]["lobes"] = raw["camshaft"]["lobes"][::2]
    raw["camshaft"]["flexibility"]["coupling_solver"] = solver
    raw["camshaft"]["method"] = "petroff"
    raw.setdefault("tribology", {})["film_model"] = film_model
    return validate(raw, "four trains", ROOT / "decks")


def _bench(benchmark, model, what: str) -> None:
    api.run(model)
    benchmark.pedantic(api.run, args=(model,), rounds=3, iterations=1)
    cpu = time.process_time()
    r = api.run(model)
    cpu = time.process_time() - cpu
    note(what, f"{benchmark.stats.stats.median:.3g} s ({cpu:.3g} s CPU; "
         f"{r.metrics['coupling_passes'].value:.0f} revolutions)", "< 2 s")


def test_bench_four_trains_on_the_elastic_shaft(benchmark):
    _bench(benchmark, _four_trains(), "four elastic trains on the elastic camshaft, periodic, warm")


def test_bench_four_trains_with_the_squeeze_film(benchmark):
    """The same with the level-1 squeeze film of every contact carried through the march."""
    _bench(benchmark, _four_trains("squeeze"),
           "the same, level-1 squeeze film at every step, warm")


def test_bench_four_trains_staggered(benchmark):
    """The same marched by the staggered solver (passes of every step until its load agrees)."""
    _bench(benchmark, _four_trains(solver="staggered"), "the same, staggered solver, warm")
