"""Regression tier: every shipped deck reproduces its golden file to 1e-9 relative.

Regenerate (after reviewing the printed differences) with
``PYTHONPATH=. python -m tests.golden.regenerate --write``.
"""
from __future__ import annotations

import pytest

from .regenerate import deck_paths, differences, snapshot


@pytest.mark.parametrize("path", deck_paths(), ids=lambda p: p.stem)
def test_deck_matches_golden_file(path):
    meta, arrays = snapshot(path)
    assert differences(path.stem, meta, arrays) == []
