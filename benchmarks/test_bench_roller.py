"""The roller chain (docs/rollers.md) against the flat-follower chain of the same cam at the same
grid, each as a ratio measured in the same run. Nothing here asserts a time.

Subject: decks/harrison_roller_needle.toml run through the API (kinematics, loads, Hertz, the
roller's speed, film and friction at that speed, power), quasi-static and inertial. Floors:
decks/harrison_flat.toml, the same lift, spring and masses on a flat tappet, and
decks/harrison_roller.toml, the same roller not turning, each at the same 1440 angles. Target:
the quasi-static roller chain within 3x of the flat chain; the inertial march's ratio is
stated.
"""
from __future__ import annotations

import pytest
from conftest import ROOT, paired, record

from camtrain import api

NEEDLE = ROOT / "decks" / "harrison_roller_needle.toml"
FLOORS = {"flat-follower chain": ROOT / "decks" / "harrison_flat.toml",
          "non-rotating roller chain": ROOT / "decks" / "harrison_roller.toml"}


@pytest.mark.parametrize("floor", sorted(FLOORS))
@pytest.mark.parametrize("solver, target", [("quasi_static", "within 3x"),
                                            ("inertial", "stated")])
def test_bench_roller_chain(benchmark, solver, target, floor):
    """The roller deck's whole in-process run against the flat tappet of the same cam and
    against the same roller not turning (decks/harrison_roller.toml), at 1440 angles."""
    roller = api.load(NEEDLE, (f"roller.solver={solver}",))
    other = api.load(FLOORS[floor])
    api.run(roller)   # compile the march once (disk cache) before timing
    timing = paired(lambda: api.run(roller), lambda: api.run(other), rounds=9, warmup=1)
    record(benchmark, f"roller chain ({solver}), 1440 angles / {floor}", timing,
           target if floor.startswith("flat") else "stated")
    benchmark.pedantic(api.run, args=(roller,), rounds=1, iterations=1)
