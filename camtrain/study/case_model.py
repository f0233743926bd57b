"""The model of one sweep case: the validated datum deck with only the swept fields changed.

A sweep process validates its datum deck once (:func:`datum_model`, cached per process). A case
then replaces the swept numbers in that immutable model (deck units converted to SI as the
validator does) and re-runs the cross-field checks (``problems``) of every section on the path,
which is all a full validation would re-check: the other sections are unchanged and valid, and
the values themselves were range-checked when the sweep was prepared. Cases that change more
than their own field (the pivot rules of fingers and rockers, list entries, lift tables) are
built and validated from the raw deck as before.
"""
from __future__ import annotations

import dataclasses
import functools
import json
from pathlib import Path

from camtrain.errors import InputError
from camtrain.study.pivot import PIVOTED, TRIGGERS
from camtrain.study.sweep import Case, Parameter, case_raw

#: validated datum decks of this process, by (name, base directory, raw deck)
_DATUMS: dict[str, object] = {}
_MAX_DATUMS = 8


def datum_key(raw: dict, name: str, base_dir: str) -> str:
    """Identity of a datum deck: its name, directory and content."""
    return json.dumps([name, base_dir, raw], sort_keys=True, default=str)


def datum_model(raw: dict, name: str, base_dir: str, key: str = ""):
    """The validated model of ``raw``, built once per process (per distinct deck)."""
    key = key or datum_key(raw, name, base_dir)
    model = _DATUMS.get(key)
    if model is None:
        from camtrain.deck.load import validate

        model = validate(raw, name, Path(base_dir))
        if len(_DATUMS) >= _MAX_DATUMS:
            _DATUMS.pop(next(iter(_DATUMS)))
        _DATUMS[key] = model
    return model


def changes_only_its_field(raw: dict, param: Parameter) -> bool:
    """True when setting ``param`` changes that one field of the model and nothing else."""
    if "[" in param.path or param.path.startswith("lift.table"):
        return False
    mech = raw.get("mechanism") if isinstance(raw.get("mechanism"), dict) else {}
    return not (mech.get("type") in PIVOTED and param.path in TRIGGERS)


def case_model(raw: dict, params: list[Parameter], case: Case, name: str, base_dir: str,
               key: str = ""):
    """The validated model of one case (InputError / GeometryError as full validation gives)."""
    if not all(changes_only_its_field(raw, p) for p in params):
        from camtrain.deck.load import validate

        return validate(case_raw(raw, params, case), name, Path(base_dir))
    model = datum_model(raw, name, base_dir, key)
    values = case.as_dict()
    for p in params:
        model = _replaced(model, p.path.split("."), _si(p, values[p.name]), "", name)
    return model


def _si(param: Parameter, value: float):
    """The deck value in the model's units, exactly as the validator converts it."""
    if param.integer:
        return int(value)
    from camtrain.units import UNITS

    return float(value) * UNITS[param.unit][0]


def _replaced(obj, keys: list[str], value, prefix: str, name: str):
    """``obj`` with the field at ``keys`` set to ``value``; each rebuilt section re-checked."""
    field = _fields_of(type(obj))[keys[0]]
    path = f"{prefix}.{keys[0]}" if prefix else keys[0]
    if len(keys) > 1:
        child = getattr(obj, field.name)
        if child is None:   # the section is absent from the datum deck: validate it properly
            raise _Absent(path)
        value = _replaced(child, keys[1:], value, path, name)
    new = dataclasses.replace(obj, **{field.name: value})
    check = getattr(new, "problems", None)
    if check is not None:
        problems = check(prefix)
        if problems:
            raise InputError(problems, source=name)
    return new


@functools.cache
def _fields_of(cls) -> dict:
    """A section's dataclass fields by deck key (the schema is fixed: looked up once)."""
    from camtrain.deck.fields import deck_key, section_fields

    return {deck_key(f): f for f, _, _ in section_fields(cls)}


class _Absent(Exception):
    """A swept field inside a section the datum deck does not have."""


def build_case_model(raw: dict, params: list[Parameter], case: Case, name: str, base_dir: str,
                     key: str = ""):
    """:func:`case_model`, falling back to full validation where a section must be created."""
    try:
        return case_model(raw, params, case, name, base_dir, key)
    except _Absent:
        from camtrain.deck.load import validate

        return validate(case_raw(raw, params, case), name, Path(base_dir))
