"""The deck reference page (docs/deck_reference.md), generated from the schema."""
from __future__ import annotations

import dataclasses

from camtrain.deck.bearing_schema import BearingDeck
from camtrain.deck.fields import FieldInfo, Shape, deck_key, section_fields
from camtrain.deck.schema import Deck
from camtrain.units import UNITS


def _default_text(f: dataclasses.Field, info: FieldInfo) -> str:
    if f.default is dataclasses.MISSING:
        return "required"
    value = f.default
    if value is None or value == ():
        return "optional"
    if dataclasses.is_dataclass(value):
        return "defaults"
    if isinstance(value, float):
        return f"{value / UNITS[info.unit][0]:g}"
    if isinstance(value, bool):
        return str(value).lower()
    return str(value)


def _type_text(shape: Shape) -> str:
    if shape.kind in ("choice", "choice_or_strings"):
        text = " \\| ".join(f"`{c}`" for c in shape.choices)
        return text + (" or list of names" if shape.kind == "choice_or_strings" else "")
    return {"number": "number", "integer": "integer", "boolean": "true/false",
            "string": "text", "numbers": "list of numbers", "strings": "list of text",
            "section": "table", "sections": "array of tables"}[shape.kind]


def markdown() -> str:
    lines = ["# Deck reference", "",
             "Generated from camtrain's deck schema (`camtrain schema --out "
             "camtrain-deck.schema.json` gives the same as JSON Schema, with defaults and the "
             "rules between fields; templates name it in their first line, `#:schema`). Units "
             "are the units written in the deck; camtrain converts them to SI inside and writes "
             "its tables, JSON, report and plots back in these units, each value with its unit "
             "(`--units si` for SI tables).", ""]
    _section(Deck, "", "The valve-train deck (top level)", lines)
    lines += ["# Journal-bearing decks", "",
              "A deck with `kind = \"journal_bearing\"` describes one journal bearing under a "
              "load diagram (`camtrain template journal_bearing`).", ""]
    _section(BearingDeck, "", "The journal-bearing deck (top level)", lines,
             label="journal bearing ")
    from camtrain.deck.schema_engine import EngineDeck

    lines += ["# Engine decks", "",
              "A deck with `kind = \"engine\"` describes an in-line crank train and its "
              "crankshaft bearings (`camtrain template engine`, docs/engine.md).", ""]
    _section(EngineDeck, "", "The engine deck (top level)", lines, label="engine ")
    return "\n".join(lines).rstrip() + "\n"


def _section(cls: type, path: str, title: str, lines: list[str], label: str = "") -> None:
    doc = (cls.__doc__ or "").strip()
    lines += [f"## {label}`[{path}]`" if path else f"## {title}", "", doc, "",
              "| key | what it is | unit | type | default | applies to |",
              "|---|---|---|---|---|---|"]
    nested = []
    for f, shape, info in section_fields(cls):
        key = deck_key(f)
        unit = "" if info.unit == "-" else info.unit
        extra = f" ({info.bounds_text()})" if info.bounds_text() else ""
        lines.append(f"| `{key}` | {info.doc}{extra} | {unit} | {_type_text(shape)} | "
                     f"{_default_text(f, info)} | {info.applies} |")
        if shape.section is not None:
            nested.append((shape, f"{path}.{key}" if path else key))
    lines.append("")
    for shape, sub in nested:
        _section(shape.section, sub, sub, lines, label)
