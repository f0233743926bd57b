"""The generated documentation says what the shipped decks give today: docs/examples.md (its
text; the images are linked as they are in docs/img) and the FLAME table of docs/piston.md.
Regenerate with `python docs/make_examples.py` (or `--no-images` for the text alone)."""
from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

from tests.shared_runs import run_model

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def make_examples():
    spec = importlib.util.spec_from_file_location("make_examples",
                                                  ROOT / "docs" / "make_examples.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module._execute = run_model   # the deck runs other tests make too are made once
    return module


def _first_difference(page: str, now: str) -> str:
    for i, (a, b) in enumerate(zip(page.splitlines(), now.splitlines(), strict=False)):
        if a != b:
            return f"line {i + 1}:\n  page: {a}\n  decks: {b}"
    return "lengths differ"


def test_examples_page_matches_the_decks(make_examples):
    page = (ROOT / "docs" / "examples.md").read_text(encoding="utf-8")
    now = make_examples.examples_md(draw=False)
    assert page == now, ("docs/examples.md is stale (python docs/make_examples.py): "
                         + _first_difference(page, now))


def test_piston_page_flame_table_matches_the_deck(make_examples):
    page = (ROOT / "docs" / "piston.md").read_text(encoding="utf-8")
    now = make_examples.piston_md(page)
    assert page == now, ("docs/piston.md's FLAME table is stale (python docs/make_examples.py): "
                         + _first_difference(page, now))
