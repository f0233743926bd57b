"""Benchmarks of the front door (pytest-benchmark; run with `make bench`, never asserted in tests)."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from camtrain.deck.load import load_deck_text
from camtrain.scene import resolve

DECK = (Path(__file__).resolve().parent.parent / "decks" / "harrison_flat.toml").read_text()


def test_bench_help_process(benchmark):
    """`camtrain --help` as a whole process (target < 0.3 s)."""
    benchmark(lambda: subprocess.run([sys.executable, "-m", "camtrain.cli", "--help"],
                                     capture_output=True, check=True))


def test_bench_load_and_plan(benchmark):
    """Parse, validate and plan the flagship deck."""
    benchmark(lambda: resolve(load_deck_text(DECK).model))
