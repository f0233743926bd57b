"""Transient film laws on the Göçmen deck (docs/transient_film.md "Cost"), each as a ratio to a
floor measured in the same run. Nothing here asserts a time.

Floors: level 1 against the steady film law of the same angles (the closed-form formula it
marches from); level 2 against a bare-numpy rigid Reynolds load over the same nodes, evaluated as
many times as the march evaluated its balance (so the ratio is the cost of everything around the
quadrature: root finding, cavitation, flow factors, asperities, the march).
"""
from __future__ import annotations

import numpy as np
import pytest
from conftest import ROOT, note, paired, record

from camtrain import mechanisms as M
from camtrain.assemble.lift_law import build_lift_law
from camtrain.contact.film import steady_film
from camtrain.contact.model import CamContact
from camtrain.deck.load import load_deck_text
from camtrain.effects.loads import solve_loads
from camtrain.lift import angle_grid

DECK = (ROOT / "decks" / "gocmen_table31.toml").read_text()


def gocmen_pair(model: str, points: int = 720, nodes: int = 401):
    text = DECK.replace('film_model = "averaged_reynolds"', f'film_model = "{model}"')
    deck = load_deck_text(text + f"\n[solver]\nangle_points = {points}\nfilm_nodes = {nodes}\n"
                          ).model
    curve = build_lift_law(deck.lift).evaluate(angle_grid(points))
    kin = M.flat_faced(curve, base_radius=deck.cam.base_radius, omega=deck.speed.omega)
    return CamContact.from_deck(deck), kin, solve_loads(deck, kin).load


def bare_reynolds_loads(nodes: int, count: int) -> float:
    """``count`` rigid half-Sommerfeld line-contact loads over ``nodes`` nodes, bare numpy."""
    x = np.linspace(-3.6e-4, 3.6e-4, nodes)
    total = 0.0
    for k in range(count):
        h = 1e-7 * (1.0 + 1e-6 * k) + x * x / 0.036
        inv = 12.0 * 0.014 / h**3
        dx = np.diff(x)
        i0 = np.concatenate(([0.0], np.cumsum(0.5 * (inv[1:] + inv[:-1]) * dx)))
        a = 0.9425 * h * inv
        i1 = np.concatenate(([0.0], np.cumsum(0.5 * (a[1:] + a[:-1]) * dx)))
        p = np.maximum(i1 - i1[-1] / i0[-1] * i0, 0.0)
        total += float(np.dot(0.5 * (p[1:] + p[:-1]), dx))
    return total


@pytest.mark.parametrize("points", [720, 3600])
def test_bench_level1_squeeze(benchmark, points):
    """Level 1 (Teodorescu squeeze march) over the cycle against the steady film it marches
    from; target: tens of ms per cycle."""
    contact, kin, load = gocmen_pair("squeeze", points)
    timing = paired(lambda: contact.film(kin, load), lambda: steady_film(contact, kin, load),
                    rounds=20, warmup=2)
    cycles = contact.film(kin, load).solution.cycles
    record(benchmark, f"level-1 squeeze film, {points} angles / steady film", timing,
           "tens of ms per cycle")
    note(f"level-1 squeeze film, {points} angles, per cycle",
         f"{timing['subject_median'] / cycles * 1e3:.3g} ms", "tens of ms")
    benchmark.pedantic(contact.film, args=(kin, load), rounds=3, iterations=1)


def test_bench_level2_averaged_reynolds(benchmark):
    """Level 2 at 401 nodes and 0.5 deg (720 angles) against the bare quadrature of as many
    balance evaluations; target: a few seconds per cycle."""
    contact, kin, load = gocmen_pair("averaged_reynolds", 720, 401)
    film = contact.film(kin, load)
    evaluations, cycles = film.solution.film.evaluations, film.solution.film.cycles
    timing = paired(lambda: contact.film(kin, load),
                    lambda: bare_reynolds_loads(401, evaluations), rounds=2, warmup=0)
    record(benchmark, "level-2 averaged Reynolds, 401 nodes, 0.5 deg / bare quadrature", timing,
           "a few s per cycle")
    note("level-2 averaged Reynolds, 401 nodes, 0.5 deg, per cycle",
         f"{timing['subject_median'] / cycles:.3g} s ({cycles} cycles, {evaluations} balance "
         "evaluations)", "a few s")
    benchmark.pedantic(contact.film, args=(kin, load), rounds=1, iterations=1)
