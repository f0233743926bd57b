"""Regression tier: every shipped deck reproduces its golden file to 1e-9 relative.

Regenerate (after reviewing the printed differences) with
``PYTHONPATH=. python -m tests.golden.regenerate --write``.
"""
from __future__ import annotations

import pytest

from tests.shared_runs import run_deck

from .regenerate import VARIANTS, deck_paths, differences, snapshot


@pytest.mark.parametrize("path", deck_paths(), ids=lambda p: p.stem)
def test_deck_matches_golden_file(path):
    # a shipped deck's run is the session's one run of it (tests/report/test_every_deck.py and
    # the generated pages run it unchanged too); a variant is run here
    result = None if path.stem in VARIANTS else run_deck(path)[1]
    meta, arrays = snapshot(path, result)
    assert differences(path.stem, meta, arrays) == []
