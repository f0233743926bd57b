"""Deck loading and planning (`make bench`)."""
from __future__ import annotations

from conftest import ROOT

from camtrain.deck.load import load_deck_text
from camtrain.scene import resolve

DECK = (ROOT / "decks" / "harrison_flat.toml").read_text()


def test_bench_load_and_plan(benchmark):
    """Parse, validate and plan the flagship deck."""
    benchmark(lambda: resolve(load_deck_text(DECK).model))
