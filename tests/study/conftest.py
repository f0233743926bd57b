"""Fixtures for sweep tests: a fast copy of the Harrison deck (fewer angles)."""
from __future__ import annotations

from pathlib import Path

import pytest

DECKS = Path(__file__).resolve().parent.parent.parent / "decks"


@pytest.fixture
def fast_flat(tmp_path) -> Path:
    """decks/harrison_flat.toml at 180 angles per revolution: same physics, a quarter the work."""
    text = (DECKS / "harrison_flat.toml").read_text(encoding="utf-8")
    path = tmp_path / "flat.toml"
    path.write_text(text.replace("angle_points = 1440", "angle_points = 180"), encoding="utf-8")
    return path
