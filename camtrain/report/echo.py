"""The input echo ("see the input data", as in Ball's program): every given field with its unit."""
from __future__ import annotations

import dataclasses

from camtrain.deck.fields import deck_key, section_fields
from camtrain.deck.schema import Deck
from camtrain.units import UNITS


def echo_rows(deck: Deck) -> list[tuple[str, str, str, str]]:
    """Rows (path, description, value in deck units, unit) for every field of the model."""
    rows: list[tuple[str, str, str, str]] = []
    _walk(deck, "", rows)
    return rows


def _fmt(value, unit: str) -> str:
    factor = UNITS[unit][0]
    if isinstance(value, bool) or isinstance(value, str):
        return str(value).lower() if isinstance(value, bool) else value
    if isinstance(value, int) and not isinstance(value, bool):
        return str(value)
    if isinstance(value, float):
        return f"{value / factor:.6g}"
    if isinstance(value, tuple):
        if len(value) > 8:
            return f"{len(value)} values"
        return "[" + ", ".join(_fmt(v, unit) for v in value) + "]"
    return str(value)


def _walk(obj, prefix: str, rows: list) -> None:
    for f, shape, info in section_fields(type(obj)):
        value = getattr(obj, f.name)
        key = deck_key(f)
        path = f"{prefix}.{key}" if prefix else key
        if value is None:
            continue
        if shape.kind == "section":
            _walk(value, path, rows)
        elif shape.kind == "sections":
            for i, item in enumerate(value):
                _walk(item, f"{path}[{i}]", rows)
        elif dataclasses.is_dataclass(value):  # pragma: no cover
            _walk(value, path, rows)
        else:
            if path == "lift.table.angles":  # stored in rad whatever the deck's angle_unit
                unit, text = "-", f"{len(value)} values"
            else:
                unit = info.unit
                text = _fmt(value, unit)
            rows.append((path, info.doc, text, "" if unit == "-" else unit))


def given_paths(raw: dict, prefix: str = "") -> set[str]:
    """The dotted paths (``camshaft.lobes[0].max_lift_angle``) a deck's TOML sets itself."""
    out = set()
    for key, value in raw.items():
        path = f"{prefix}.{key}" if prefix else key
        if isinstance(value, dict):
            out |= given_paths(value, path)
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            for i, item in enumerate(value):
                out |= given_paths(item, f"{path}[{i}]")
        else:
            out.add(path)
    return out


def given_rows(deck: Deck, raw: dict) -> tuple[list[tuple[str, str, str, str]], int]:
    """The echo rows of the fields the deck sets itself, and how many other fields (defaults)
    the full echo holds."""
    rows = echo_rows(deck)
    given = given_paths(raw)
    mine = [r for r in rows if r[0] in given]
    return mine, len(rows) - len(mine)
