"""Declarative deck fields: one description drives validation, SI conversion, templates and JSON Schema.

A deck section is a frozen dataclass whose fields carry metadata made by :func:`quantity`,
:func:`option` or :func:`section`. The model holds SI values; the metadata keeps the deck unit,
the bounds (in deck units), a prompt-like description and an example for templates.
"""
from __future__ import annotations

import dataclasses
import difflib
import functools
import math
import types
import typing
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Any, Literal, get_args, get_origin

from camtrain.errors import Problem
from camtrain.lazy import resolve
from camtrain.units import UNITS


class _Required:
    def __repr__(self) -> str:
        return "REQUIRED"


REQUIRED: Any = _Required()


@dataclass(frozen=True)
class FieldInfo:
    """What a deck field is: its prompt, unit, bounds (deck units), example and applicability."""

    doc: str
    unit: str = "-"
    gt: float | None = None
    ge: float | None = None
    lt: float | None = None
    le: float | None = None
    example: Any = None
    applies: str = ""
    min_items: int = 0
    max_items: int | None = None
    key: str = ""  # deck key when it differs from the Python name (e.g. "lambda")
    #: an optional section whose class lives in a module of its own, "module:Class": imported
    #: when a deck has the section (or the whole schema is walked), not for every deck
    schema: str = ""

    def bounds_text(self) -> str:
        parts = []
        if self.gt is not None:
            parts.append(f"> {self.gt:g}")
        if self.ge is not None:
            parts.append(f">= {self.ge:g}")
        if self.lt is not None:
            parts.append(f"< {self.lt:g}")
        if self.le is not None:
            parts.append(f"<= {self.le:g}")
        return " and ".join(parts)

    def expected_text(self) -> str:
        text = "a number"
        if self.bounds_text():
            text += " " + self.bounds_text()
        if self.unit != "-":
            text += f" in {self.unit}"
        return text


def quantity(doc: str, unit: str = "-", *, default: Any = REQUIRED, gt=None, ge=None, lt=None,
             le=None, example=None, applies: str = "", min_items: int = 0,
             max_items: int | None = None, key: str = "") -> Any:
    """A numeric deck field (or list of numbers) with one unit; stored in SI in the model."""
    if unit not in UNITS:
        raise ValueError(f"unknown unit {unit!r}")
    info = FieldInfo(doc, unit, gt, ge, lt, le, example, applies, min_items, max_items, key)
    # defaults are written in deck units, like everything a user sees; the model holds SI
    factor = UNITS[unit][0]
    if isinstance(default, float) and factor != 1.0:
        default = default * factor
    elif isinstance(default, list | tuple) and factor != 1.0:
        default = tuple(v * factor for v in default)
    return _field(default, info)


def option(doc: str, *, default: Any = REQUIRED, example=None, applies: str = "") -> Any:
    """A non-numeric deck field: a choice (Literal), a flag, a string or a list of strings."""
    return _field(default, FieldInfo(doc, example=example, applies=applies))


def section(doc: str, *, required: bool = False, applies: str = "", default: Any = None,
            schema: str = "") -> Any:
    """A nested section ([table] in TOML). Optional sections default to ``default`` (None).

    ``schema`` ("module:Class") defers an optional section's class: the owner's module names
    the class for type checkers only, and the class's module is imported when the section is
    first read (a deck that has it, a schema walker), so a deck without it does not pay for it.
    """
    if schema and (required or default is not None):
        raise ValueError("only an optional section without a default is deferred")
    info = FieldInfo(doc, applies=applies, schema=schema)
    return _field(REQUIRED if required else default, info)


def _field(default: Any, info: FieldInfo) -> Any:
    meta = {"deck": info}
    if default is REQUIRED:
        return dataclasses.field(metadata=meta)
    if isinstance(default, list):
        default = tuple(default)
    return dataclasses.field(default=default, metadata=meta)


def info_of(f: dataclasses.Field) -> FieldInfo:
    return f.metadata.get("deck", FieldInfo(""))


# --------------------------------------------------------------------------- cross-field rules

@dataclass(frozen=True)
class When:
    """A cross-field rule of a section, stated once for the JSON Schema: when ``key`` takes one
    of ``values`` (or, ``negate``, none of them), the keys in ``require`` must be given, those in
    ``forbid`` must not, ``equal`` fixes values, and ``reject`` refuses the value itself. A
    section lists its rules in a class attribute ``schema_rules``; its ``problems()`` enforces
    the same rules with messages."""

    key: str
    values: tuple
    require: tuple[str, ...] = ()
    forbid: tuple[str, ...] = ()
    equal: tuple[tuple[str, Any], ...] = ()
    negate: bool = False
    reject: bool = False    # the value itself is not allowed (e.g. a speed of 0)
    #: ``require`` is met as well by giving any one of these keys instead (a section that
    #: states the same data another way, e.g. a pivoted follower's drawn layout)
    or_given: tuple[str, ...] = ()


@dataclass(frozen=True)
class WhenItem:
    """When an item of the array of tables ``items`` has ``key`` in ``values``, the keys in
    ``require`` must be given in the section itself."""

    items: str
    key: str
    values: tuple
    require: tuple[str, ...]


@dataclass(frozen=True)
class ExactlyOne:
    """Exactly one of the groups of keys is given (a group counts when any of its keys is)."""

    groups: tuple[tuple[str, ...], ...]


@dataclass(frozen=True)
class Together:
    """The keys are given all together or not at all."""

    keys: tuple[str, ...]


# --------------------------------------------------------------------------- type introspection

@dataclass(frozen=True)
class Shape:
    """The deck-level shape of a field type."""

    kind: str  # number, integer, boolean, string, choice, numbers, strings, section, sections,
    #            choice_or_strings
    optional: bool
    choices: tuple = ()
    #: a section's class, or where a deferred one lives ("module:Class", FieldInfo.schema)
    schema: type | str | None = None

    @property
    def section(self) -> type | None:
        """The section's class (a deferred one is imported now), None for a leaf field."""
        if isinstance(self.schema, str):
            return resolve(self.schema)
        return self.schema


class _Deferred:
    """Stands for a deferred section's class while its owner's type hints are read."""


def shape_of(tp: Any, deferred: str = "") -> Shape:
    """The shape of a field's type; ``deferred`` is where the class of a deferred section
    (``_Deferred`` in the hint) lives."""
    optional = False
    origin = get_origin(tp)
    if origin in (typing.Union, types.UnionType):
        args = [a for a in get_args(tp) if a is not type(None)]
        optional = len(args) < len(get_args(tp))
        if len(args) == 2:
            lit = next((a for a in args if get_origin(a) is Literal), None)
            other = next((a for a in args if a is not lit), None)
            if lit is not None and get_origin(other) is tuple:
                return Shape("choice_or_strings", optional, get_args(lit))
        if len(args) != 1:
            raise TypeError(f"unsupported union {tp}")
        tp = args[0]
        origin = get_origin(tp)
    if tp is float:
        return Shape("number", optional)
    if tp is int:
        return Shape("integer", optional)
    if tp is bool:
        return Shape("boolean", optional)
    if tp is str:
        return Shape("string", optional)
    if origin is Literal:
        return Shape("choice", optional, get_args(tp))
    if origin is tuple:
        inner = get_args(tp)[0]
        if inner is float:
            return Shape("numbers", optional)
        if inner is str:
            return Shape("strings", optional)
        if dataclasses.is_dataclass(inner):
            return Shape("sections", optional, schema=inner)
    if tp is _Deferred and deferred:
        return Shape("section", optional, schema=deferred)
    if dataclasses.is_dataclass(tp):
        return Shape("section", optional, schema=tp)
    raise TypeError(f"unsupported deck field type {tp}")


def deck_key(f: dataclasses.Field) -> str:
    """The key a deck uses for a model field."""
    return info_of(f).key or f.name


@functools.cache
def section_fields(cls: type) -> tuple[tuple[dataclasses.Field, Shape, FieldInfo], ...]:
    """The fields of a section with their shapes (cached: the schema never changes at run time,
    and resolving type hints dominates validation otherwise). A deferred section's class is
    not imported here: its hint reads as ``_Deferred`` (see :func:`section`)."""
    fields = dataclasses.fields(cls)
    deferred = {info_of(f).schema.split(":")[1]: _Deferred for f in fields if info_of(f).schema}
    hints = typing.get_type_hints(cls, localns=deferred) if deferred else \
        typing.get_type_hints(cls)
    return tuple((f, shape_of(hints[f.name], info_of(f).schema), info_of(f)) for f in fields)


# --------------------------------------------------------------------------- parsing

def _is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _type_name(value: Any) -> str:
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, int | float):
        return "a number"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "a table"
    return type(value).__name__


#: the magnitudes a deck number may have, in deck units (mm, rpm, GPa, ...): anything outside is a
#: slip (a unit, an exponent), and beyond it floating point overflows or divides by zero
MAGNITUDE = (1e-12, 1e12)


def _check_number(value: Any, info: FieldInfo, path: str, problems: list[Problem]) -> float | None:
    """Validate one number in deck units; return it converted to SI, or None after a problem."""
    if not _is_number(value):
        problems.append(Problem(path, f"must be a number, not {_type_name(value)}", value,
                                info.expected_text()))
        return None
    x = float(value)
    if not math.isfinite(x):
        problems.append(Problem(path, "must be finite", value, info.expected_text()))
        return None
    if x != 0.0 and not MAGNITUDE[0] <= abs(x) <= MAGNITUDE[1]:
        problems.append(Problem(
            path, "is beyond the magnitudes camtrain computes with", value,
            f"0 or a magnitude between {MAGNITUDE[0]:g} and {MAGNITUDE[1]:g} {info.unit}",
            "check the unit: the deck is written in the units its prompts name"))
        return None
    bad = ((info.gt is not None and not x > info.gt) or (info.ge is not None and not x >= info.ge)
           or (info.lt is not None and not x < info.lt) or (info.le is not None and not x <= info.le))
    if bad:
        problems.append(Problem(path, "is out of range", value, info.expected_text()))
        return None
    return x * UNITS[info.unit][0]


def _suggest(key: str, known: list[str], path: str, all_paths: Mapping[str, list[str]]) -> str:
    close = difflib.get_close_matches(key, known, n=1, cutoff=0.6)
    if close:
        where = f"{path}.{close[0]}" if path else close[0]
        return f"did you mean `{where}`?"
    elsewhere = all_paths.get(key, [])
    if elsewhere:
        return f"did you mean `{elsewhere[0]}`?"
    fuzzy = difflib.get_close_matches(key, list(all_paths), n=1, cutoff=0.75)
    if fuzzy:
        return f"did you mean `{all_paths[fuzzy[0]][0]}`?"
    return "known keys here: " + ", ".join(sorted(known))


class SchemaPaths(Mapping):
    """:func:`schema_paths` of a schema, walked when a hint first reads it: a valid deck never
    does, and the walk imports every deferred section's module."""

    def __init__(self, cls: type) -> None:
        self._cls = cls

    def _paths(self) -> dict[str, list[str]]:
        return schema_paths(self._cls)

    def __getitem__(self, key: str) -> list[str]:
        return self._paths()[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._paths())

    def __len__(self) -> int:
        return len(self._paths())


@functools.cache
def schema_paths(cls: type, prefix: str = "") -> dict[str, list[str]]:
    """Map every key name to the dotted paths where it occurs in the schema (for hints).

    Cached; callers must not modify the returned mapping."""
    out: dict[str, list[str]] = {}
    for f, shape, _ in section_fields(cls):
        key = deck_key(f)
        path = f"{prefix}.{key}" if prefix else key
        out.setdefault(key, []).append(path)
        if shape.section is not None:
            for key, paths in schema_paths(shape.section, path).items():
                out.setdefault(key, []).extend(paths)
    return out


def build_section(cls: type, raw: Any, path: str, problems: list[Problem],
                  all_paths: Mapping[str, list[str]]) -> Any:
    """Build ``cls`` from raw TOML data at ``path``; append every problem found; None on failure."""
    if not isinstance(raw, dict):
        problems.append(Problem(path, f"must be a table, not {_type_name(raw)}", raw))
        return None
    fields = section_fields(cls)
    known = [deck_key(f) for f, _, _ in fields]
    for key in raw:
        if key not in known:
            kpath = f"{path}.{key}" if path else key
            problems.append(Problem(kpath, "is not a known key", None, "",
                                    _suggest(key, known, path, all_paths)))
    values: dict[str, Any] = {}
    ok = True
    n_before = len(problems)
    for f, shape, info in fields:
        key = deck_key(f)
        fpath = f"{path}.{key}" if path else key
        if key not in raw:
            if f.default is dataclasses.MISSING:
                what = "section" if shape.kind in ("section", "sections") else "field"
                problems.append(Problem(fpath, f"required {what} is missing", None,
                                        _describe_expected(shape, info)))
                ok = False
            continue
        value = _convert(raw[key], shape, info, fpath, problems, all_paths)
        if value is _INVALID:
            ok = False
        else:
            values[f.name] = value
    if not ok or len(problems) > n_before:
        return None
    obj = cls(**values)
    check = getattr(obj, "problems", None)
    if check is not None:
        extra = check(path)
        if extra:
            problems.extend(extra)
            return None
    return obj


_INVALID = object()


def _describe_expected(shape: Shape, info: FieldInfo) -> str:
    if shape.kind in ("number", "integer"):
        return info.expected_text()
    if shape.kind == "numbers":
        return f"a list of numbers in {info.unit}"
    if shape.kind in ("choice", "choice_or_strings"):
        return "one of " + ", ".join(repr(c) for c in shape.choices)
    if shape.kind == "boolean":
        return "true or false"
    if shape.kind in ("section", "sections"):
        return "a table"
    return "a string"


def _convert(value: Any, shape: Shape, info: FieldInfo, path: str, problems: list[Problem],
             all_paths: Mapping[str, list[str]]) -> Any:
    kind = shape.kind
    if kind == "number":
        x = _check_number(value, info, path, problems)
        return _INVALID if x is None else x
    if kind == "integer":
        if not isinstance(value, int) or isinstance(value, bool):
            problems.append(Problem(path, f"must be a whole number, not {_type_name(value)}",
                                    value, info.expected_text().replace("a number", "an integer")))
            return _INVALID
        x = _check_number(value, info, path, problems)
        return _INVALID if x is None else int(value)
    if kind == "boolean":
        if not isinstance(value, bool):
            problems.append(Problem(path, f"must be true or false, not {_type_name(value)}", value))
            return _INVALID
        return value
    if kind == "string":
        if not isinstance(value, str) or not value.strip():
            problems.append(Problem(path, "must be a non-empty string", value))
            return _INVALID
        return value
    if kind == "choice" or (kind == "choice_or_strings" and not isinstance(value, list)):
        if value not in shape.choices or isinstance(value, bool):
            hint = ""
            if isinstance(value, str):
                close = difflib.get_close_matches(value, [str(c) for c in shape.choices], n=1)
                hint = f"did you mean {close[0]!r}?" if close else ""
            problems.append(Problem(path, "is not an allowed choice", value,
                                    "one of " + ", ".join(repr(c) for c in shape.choices), hint))
            return _INVALID
        return value
    if kind in ("numbers", "strings", "choice_or_strings", "sections"):
        if not isinstance(value, list):
            problems.append(Problem(path, f"must be a list, not {_type_name(value)}", value))
            return _INVALID
        if len(value) < info.min_items or (info.max_items is not None
                                           and len(value) > info.max_items):
            most = "" if info.max_items is None else f" and at most {info.max_items}"
            problems.append(Problem(path, f"has {len(value)} entries", None,
                                    f"at least {info.min_items}{most}"))
            return _INVALID
        if kind == "numbers":
            n_before = len(problems)
            out = [_check_number(v, info, f"{path}[{i}]", problems) for i, v in enumerate(value)]
            return _INVALID if len(problems) > n_before else tuple(out)
        if kind == "sections":
            items = [build_section(shape.section, v, f"{path}[{i}]", problems, all_paths)
                     for i, v in enumerate(value)]
            return _INVALID if any(it is None for it in items) else tuple(items)
        bad = [v for v in value if not isinstance(v, str)]
        if bad:
            problems.append(Problem(path, "must be a list of strings", value))
            return _INVALID
        return tuple(value)
    if kind == "section":
        obj = build_section(shape.section, value, path, problems, all_paths)
        return _INVALID if obj is None else obj
    raise TypeError(kind)  # pragma: no cover - schema programming error
