"""Magnitudes no engine part has: a deck written in metres (or inches) where millimetres are
asked for passes every bound yet describes a part the size of a grain of sand.

Generic over every deck kind: the walk follows the schema's field descriptions; a size is a
strictly positive millimetre field whose name says it is a dimension of a part.
"""
from __future__ import annotations

import dataclasses

from camtrain.deck.fields import deck_key, section_fields

#: names of millimetre fields that are sizes of parts (never below a millimetre or so)
SIZE_NAMES = frozenset({
    "base_radius", "width", "diameter", "length", "max_lift", "follower_radius", "face_length",
    "A", "B", "D", "rocker_pushrod_arm", "rocker_valve_arm", "pushrod_length", "bore", "stroke",
    "crank_radius", "rod_length", "journal_diameter", "pin_diameter", "skirt_length"})
#: below this [mm] a part size is implausible
SMALLEST_MM = 0.5


def implausible(deck) -> list[str]:
    """Warnings naming each implausibly small part size of a validated deck model (SI)."""
    out: list[str] = []
    _walk(deck, "", out)
    return out


def _walk(obj, path: str, out: list[str]) -> None:
    if not dataclasses.is_dataclass(obj):
        return
    for f, shape, info in section_fields(type(obj)):
        key = deck_key(f)
        where = f"{path}.{key}" if path else key
        value = getattr(obj, f.name, None)
        if shape.kind in ("section", "sections"):   # None (absent) walks nothing
            items = value if isinstance(value, tuple) else (value,)
            for i, item in enumerate(items):
                _walk(item, f"{where}[{i}]" if isinstance(value, tuple) else where, out)
        elif (info.unit == "mm" and f.name in SIZE_NAMES and isinstance(value, float)
              and 0.0 < value * 1e3 < SMALLEST_MM):
            mm = value * 1e3
            out.append(f"{where} = {mm:g} mm is implausibly small for a part: did you write "
                       f"metres? ({mm * 1e3:g} mm if so)")
