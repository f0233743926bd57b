"""A validated deck written back as TOML, in the deck's units (tomli-w).

The model holds SI; each field goes back through its unit (and a table's inline angles through
their ``angle_unit``), rounded to 12 significant digits so 0.018 m is written 18.0 mm again.
Every field is written, defaults included, so the file pins exactly what ran; fields without a
value (None) are left out. Reading the text back gives an equal model.
"""
from __future__ import annotations

import math
from pathlib import Path

from camtrain.deck.fields import deck_key, section_fields
from camtrain.units import UNITS


def deck_dict(deck) -> dict:
    """The deck model (any kind) as the TOML data a user would write."""
    return _section(deck)


def to_toml(deck, header: str = "") -> str:
    """The deck model as TOML text (``header``: comment lines to put first)."""
    import tomli_w

    text = tomli_w.dumps(deck_dict(deck))
    lines = [f"# {line}" if line else "#" for line in header.splitlines()]
    return ("\n".join(lines) + "\n\n" if lines else "") + text


def save(deck, path: str | Path, header: str = "") -> Path:
    """Write the deck model to ``path`` as TOML; returns the path."""
    path = Path(path)
    path.write_text(to_toml(deck, header), encoding="utf-8")
    return path


def _section(obj) -> dict:
    out: dict = {}
    for f, shape, info in section_fields(type(obj)):
        value = getattr(obj, f.name)
        if value is None:
            continue
        key = deck_key(f)
        if shape.section is not None:
            out[key] = [_section(v) for v in value] if isinstance(value, tuple) \
                else _section(value)
        elif shape.kind in ("number", "numbers"):
            factor = UNITS[info.unit][0]
            if f.name == "angles" and getattr(obj, "angle_unit", None) == "deg":
                factor = math.pi / 180.0          # inline table angles are held in rad
            out[key] = [_number(v, factor) for v in value] if isinstance(value, tuple) \
                else _number(value, factor)
        elif isinstance(value, tuple):
            out[key] = list(value)
        else:
            out[key] = value
    return out


def _number(value, factor: float):
    if isinstance(value, bool) or isinstance(value, int) and factor == 1.0:
        return value
    x = value / factor
    return float(f"{x:.12g}") if math.isfinite(x) else x
