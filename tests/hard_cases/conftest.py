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
    """Run deck text with every numpy floating-point warning raised as an error."""
    with np.errstate(all="raise"):
        return api.run(api.loads(text))


def finite_columns(result, names) -> None:
    """Every named column finite; film columns only where the cam carries load (the film is
    documented as undefined, NaN, where the contact is unloaded or lost)."""
    loaded = result["load"] > 0 if "load" in result.columns else slice(None)
    for name in names:
        values = result[name][loaded] if name.startswith(("film", "lambda")) else result[name]
        assert np.all(np.isfinite(values)), name
