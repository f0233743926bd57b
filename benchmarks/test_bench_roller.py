"""The roller chain (docs/rollers.md) against the flat-follower chain of the same cam at the same
grid, each as a ratio measured in the same run. Nothing here asserts a time.

Subject: decks/harrison_roller_needle.toml run through the API (kinematics, loads, Hertz, the
roller's speed, film and friction at that speed, power), quasi-static and inertial. Floor:
decks/harrison_flat.toml, the same lift, spring and masses on a flat tappet, at the same 1440
angles. Target: the quasi-static roller chain within 3x of the flat chain; the inertial march's
ratio is stated.
"""
from __future__ import annotations

import pytest
from conftest import ROOT, paired, record

from camtrain import api

NEEDLE = ROOT / "decks" / "harrison_roller_needle.toml"
FLAT = ROOT / "decks" / "harrison_flat.toml"


@pytest.mark.parametrize("solver, target", [("quasi_static", "within 3x"),
                                            ("inertial", "stated")])
def test_bench_roller_chain(benchmark, solver, target):
    roller = api.load(NEEDLE, (f"roller.solver={solver}",))
    flat = api.load(FLAT)
    api.run(roller)   # compile the march once (disk cache) before timing
    timing = paired(lambda: api.run(roller), lambda: api.run(flat), rounds=5, warmup=1)
    record(benchmark, f"roller chain ({solver}), 1440 angles / flat-follower chain", timing,
           target)
    benchmark.pedantic(api.run, args=(roller,), rounds=1, iterations=1)
