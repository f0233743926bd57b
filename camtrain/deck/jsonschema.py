"""JSON Schema of the deck, derived from the schema, so editors can validate decks while typing."""
from __future__ import annotations

import dataclasses

from camtrain import __version__
from camtrain.deck.fields import FieldInfo, Shape, deck_key, section_fields


def _number(info: FieldInfo, integer: bool = False) -> dict:
    out: dict = {"type": "integer" if integer else "number"}
    for name, key in (("gt", "exclusiveMinimum"), ("ge", "minimum"), ("lt", "exclusiveMaximum"),
                      ("le", "maximum")):
        if getattr(info, name) is not None:
            out[key] = getattr(info, name)
    return out


def _property(shape: Shape, info: FieldInfo) -> dict:
    unit = f" [{info.unit}]" if info.unit != "-" else ""
    desc = info.doc + unit + (f" (for {info.applies})" if info.applies else "")
    kind = shape.kind
    if kind == "number":
        prop = _number(info)
    elif kind == "integer":
        prop = _number(info, integer=True)
    elif kind == "boolean":
        prop = {"type": "boolean"}
    elif kind == "string":
        prop = {"type": "string", "minLength": 1}
    elif kind == "choice":
        prop = {"enum": list(shape.choices)}
    elif kind == "choice_or_strings":
        prop = {"anyOf": [{"enum": list(shape.choices)},
                          {"type": "array", "items": {"type": "string"}}]}
    elif kind in ("numbers", "strings"):
        items = _number(info) if kind == "numbers" else {"type": "string"}
        prop = {"type": "array", "items": items, "minItems": info.min_items}
        if info.max_items is not None:
            prop["maxItems"] = info.max_items
    elif kind == "section":
        prop = section_schema(shape.section)
    elif kind == "sections":
        prop = {"type": "array", "items": section_schema(shape.section)}
    else:  # pragma: no cover
        raise TypeError(kind)
    prop["description"] = desc
    return prop


def section_schema(cls: type) -> dict:
    props, required = {}, []
    for f, shape, info in section_fields(cls):
        key = deck_key(f)
        props[key] = _property(shape, info)
        if f.default is dataclasses.MISSING:
            required.append(key)
    out = {"type": "object", "description": (cls.__doc__ or "").strip().splitlines()[0],
           "properties": props, "additionalProperties": False}
    if required:
        out["required"] = required
    return out


def deck_json_schema(kind: str = "valve_train") -> dict:
    """The JSON Schema (draft 2020-12) of a camtrain deck of ``kind`` (a key of the catalogue's
    KINDS; default the valve-train deck)."""
    import importlib

    from camtrain.effects.catalogue import KINDS

    module, cls = KINDS[kind].schema.split(":")
    schema = section_schema(getattr(importlib.import_module(module), cls))
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    title = "deck" if kind == "valve_train" else f"{kind} deck"
    schema["title"] = f"camtrain {title} (camtrain {__version__})"
    return schema
