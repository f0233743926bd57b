"""Regression tier: every shipped deck reproduces its golden file to 1e-9 relative.

Regenerate (after reviewing the printed differences) with
``PYTHONPATH=. python -m tests.golden.regenerate --write``.
"""
from __future__ import annotations

import pytest

from tests.shared_runs import run_model

from .regenerate import VARIANTS, deck_paths, differences, snapshot, variant_model


@pytest.mark.parametrize("path", deck_paths(), ids=lambda p: p.stem)
def test_deck_matches_golden_file(path):
    # the session's one run of the deck (tests/report/test_every_deck.py and the generated
    # pages run the shipped decks, and docs/examples.md's conventions table the variants, too)
    from camtrain import api

    model = variant_model(path.stem) if path.stem in VARIANTS else api.load(path).model
    meta, arrays = snapshot(path, run_model(model))
    assert differences(path.stem, meta, arrays) == []
