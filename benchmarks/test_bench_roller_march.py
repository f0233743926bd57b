"""The roller's speed marched with the elastic train (docs/rollers.md) against the same deck with
the roller solved after the march, as a ratio measured in the same run. Nothing here asserts a
time.

Subject: decks/roller_finger_hla.toml run through the API (the elastic train with its hydraulic
lash adjuster, the roller's spin tables and its step in every Newmark step, then the chain).
Floor: the same deck with dynamics.roller = "after" (the march without the roller's state). The
ratio is stated (2.2-2.5x, docs/rollers.md): the roller's step in the march and the revolution
more it takes are most of it; the traction tables, which read the Greenwood-Tripp integrals
from their table, a tenth of a second.
"""
from __future__ import annotations

from conftest import ROOT, paired, record

from camtrain import api

DECK = ROOT / "decks" / "roller_finger_hla.toml"


def test_bench_roller_marched_with_the_train(benchmark):
    marched = api.load(DECK)
    after = api.load(DECK, ("dynamics.roller=after",))
    api.run(marched)   # compile the marches once (disk cache) before timing
    api.run(after)
    timing = paired(lambda: api.run(marched), lambda: api.run(after), rounds=3, warmup=0)
    record(benchmark, "roller finger on its HLA, roller marched with the train / solved after "
           "the march", timing, "stated")
    benchmark.pedantic(api.run, args=(marched,), rounds=1, iterations=1)
