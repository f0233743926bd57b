"""JSON Schema of every deck kind, derived from the deck schemas, so editors (taplo,
check-jsonschema, VS Code) validate decks while typing.

Generic over the registered deck kinds (``KINDS`` in the catalogue) and over the field
descriptions: each field's type, bounds, unit, choices and default (in deck units) come from its
metadata; a section's cross-field rules from its ``schema_rules`` (``When``, ``ExactlyOne``,
``Together`` in camtrain.deck.fields). A rule its ``problems()`` enforces but JSON Schema cannot
state (equal list lengths, a fit that must converge) is left to camtrain.
"""
from __future__ import annotations

import dataclasses

from camtrain import __version__
from camtrain.catalogue import DEFAULT_KIND, KINDS
from camtrain.deck.fields import (
    ExactlyOne,
    FieldInfo,
    Shape,
    Together,
    When,
    WhenItem,
    deck_key,
    section_fields,
)
from camtrain.lazy import resolve
from camtrain.units import UNITS

#: where a template's ``#:schema`` line points (written by ``camtrain schema --out``)
SCHEMA_FILE = "camtrain-deck.schema.json"


def _number(info: FieldInfo, integer: bool = False) -> dict:
    out: dict = {"type": "integer" if integer else "number"}
    for name, key in (("gt", "exclusiveMinimum"), ("ge", "minimum"), ("lt", "exclusiveMaximum"),
                      ("le", "maximum")):
        if getattr(info, name) is not None:
            out[key] = getattr(info, name)
    return out


def _deck_default(value, shape: Shape, info: FieldInfo):
    """A field's default as the deck writes it (deck units, JSON types), or None for none."""
    if value is None or dataclasses.is_dataclass(value):
        return None
    factor = UNITS.get(info.unit, (1.0,))[0] if shape.kind in ("number", "numbers") else 1.0

    def one(v):
        if isinstance(v, bool) or not isinstance(v, int | float):
            return v
        x = v / factor if factor != 1.0 else v
        return float(f"{x:.12g}") if isinstance(x, float) else x
    if isinstance(value, tuple | list):
        return [one(v) for v in value]
    return one(value)


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


def _given(key: str) -> dict:
    return {"required": [key]}


def _rule(rule, defaults: dict) -> dict:
    """One cross-field rule as JSON Schema (if/then, oneOf, ...)."""
    if isinstance(rule, ExactlyOne):
        return {"oneOf": [_given(g[0]) if len(g) == 1 else {"anyOf": [_given(k) for k in g]}
                          for g in rule.groups]}
    if isinstance(rule, WhenItem):
        item = {"properties": {rule.key: {"enum": list(rule.values)}}, "required": [rule.key]}
        return {"if": {"properties": {rule.items: {"contains": item}}, "required": [rule.items]},
                "then": {"required": list(rule.require)}}
    if isinstance(rule, Together):
        return {"anyOf": [{"required": list(rule.keys)},
                          {"not": {"anyOf": [_given(k) for k in rule.keys]}}]}
    if not isinstance(rule, When):  # pragma: no cover
        raise TypeError(rule)
    values = {"enum": list(rule.values)}
    cond: dict = {"properties": {rule.key: {"not": values} if rule.negate else values}}
    # an absent key takes its default: the condition holds for it only if the default does
    has_default = rule.key in defaults
    default_matches = has_default and ((defaults[rule.key] in rule.values) != rule.negate)
    if not default_matches:
        cond["required"] = [rule.key]
    if rule.reject:
        return {"if": cond, "then": False}
    then: dict = {}
    if rule.require and rule.or_given:
        then["anyOf"] = [{"required": list(rule.require)}] + [_given(k) for k in rule.or_given]
    elif rule.require:
        then["required"] = list(rule.require)
    if rule.forbid:
        then["not"] = {"anyOf": [_given(k) for k in rule.forbid]}
    if rule.equal:
        then["properties"] = {k: {"const": v} for k, v in rule.equal}
    return {"if": cond, "then": then}


def section_schema(cls: type) -> dict:
    props, required, defaults = {}, [], {}
    for f, shape, info in section_fields(cls):
        key = deck_key(f)
        props[key] = _property(shape, info)
        if f.default is dataclasses.MISSING:
            required.append(key)
            continue
        defaults[key] = f.default
        default = _deck_default(f.default, shape, info)
        if default is not None:
            props[key]["default"] = default
    out = {"type": "object", "description": (cls.__doc__ or "").strip().splitlines()[0],
           "properties": props, "additionalProperties": False}
    if required:
        out["required"] = required
    rules = [_rule(r, defaults) for r in getattr(cls, "schema_rules", ())]
    if rules:
        out["allOf"] = rules
    return out


def kind_schema(name: str) -> dict:
    """The schema of one deck kind (its top-level section, with its ``kind`` key)."""
    schema = section_schema(resolve(KINDS[name].schema))
    kind = {"enum": [name], "description": f"Deck kind ({', '.join(KINDS)})"}
    if name == DEFAULT_KIND:
        kind["default"] = name
    schema["properties"]["kind"] = {**schema["properties"].get("kind", {}), **kind}
    if name != DEFAULT_KIND and "kind" not in schema.get("required", []):
        schema.setdefault("required", []).insert(0, "kind")
    return schema


def deck_json_schema(kind: str | None = None) -> dict:
    """The JSON Schema (draft 2020-12) of a camtrain deck of any registered kind: ``kind``
    in the deck picks the kind's schema (a deck without ``kind`` is a valve-train deck). With
    ``kind`` given here, the schema of that kind alone."""
    if kind is not None:
        title = "deck" if kind == DEFAULT_KIND else f"{kind} deck"
        return {"$schema": "https://json-schema.org/draft/2020-12/schema",
                "title": f"camtrain {title} (camtrain {__version__})", **kind_schema(kind)}
    branches = []
    for name in KINDS:
        cond = {"properties": {"kind": {"const": name}}}
        if name != DEFAULT_KIND:
            cond["required"] = ["kind"]
        branches.append({"if": cond, "then": {"$ref": f"#/$defs/{name}"}})
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": f"camtrain deck (camtrain {__version__})",
        "description": "A camtrain deck; kind = " + " | ".join(KINDS)
                       + f" (default {DEFAULT_KIND}).",
        "type": "object",
        "properties": {"kind": {"enum": list(KINDS), "default": DEFAULT_KIND,
                                "description": "Deck kind"}},
        "allOf": branches,
        "$defs": {name: kind_schema(name) for name in KINDS},
    }
