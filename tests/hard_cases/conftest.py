"""Helpers for the hard cases: deck variants as TOML text, runs with numpy warnings as errors."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from camtrain import api

DECKS = Path(__file__).resolve().parents[2] / "decks"
HARRISON = (DECKS / "harrison_flat.toml").read_text(encoding="utf-8")


def variant(text: str, *swaps: tuple[str, str]) -> str:
    """Deck text with each (old, new) line fragment replaced; fails loudly if one is missing."""
    for old, new in swaps:
        assert old in text, old
        text = text.replace(old, new)
    return text


def run_strict(text: str):
    """Run deck text with numpy's overflow, invalid-operation and division warnings raised as
    errors. Underflow is not: a value rounding to zero below ~1e-308 is harmless and routine
    inside library solvers (scipy's B-spline QR rotations underflow on a lift table), so
    raising it made these tests pass or fail with what an earlier test had cached."""
    with np.errstate(all="raise", under="ignore"):
        return api.run(api.loads(text))


def finite_columns(result, names) -> None:
    """Every named column finite; film columns only where the cam carries load (the film is
    documented as undefined, NaN, where the contact is unloaded or lost)."""
    loaded = result["load"] > 0 if "load" in result.columns else slice(None)
    for name in names:
        values = result[name][loaded] if name.startswith(("film", "lambda")) else result[name]
        assert np.all(np.isfinite(values)), name
