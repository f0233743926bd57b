"""``--set PATH=VALUE``: one deck field changed before the deck is validated (``run`` and
``sweep``). A number or whole number is read in the field's deck unit and checked against its
bounds; a boolean is ``true`` or ``false``; a choice one of its options; a string any text."""
from __future__ import annotations

import copy
import difflib

from camtrain.errors import InputError, Problem
from camtrain.study.sweep import (
    ALIASES,
    Parameter,
    _bad,
    _field_at,
    _number,
    _schema_of,
    check_values,
    resolve_path,
    set_path,
)


def parse_assignment(raw: dict, text: str) -> Parameter:
    """``--set path=value`` -> a Parameter holding the one value (a number in deck units, or
    the boolean or string itself)."""
    if "=" not in text:
        raise _bad("--set", text, "needs PATH=VALUE",
                   "e.g. solver.angle_points=720 or tribology.entrainment=mean")
    name, value = (part.strip() for part in text.split("=", 1))
    if name not in ALIASES:       # an alias names a number; any other path may name a scalar
        shape, info, _ = _field_at(name, "--set", _schema_of(raw), scalars=True)
        if shape.kind not in ("number", "integer"):
            return Parameter(name, name, "-", False, None, (_typed(shape, value, name, text),),
                             info)
    p = resolve_path(raw, name, "--set")
    p = Parameter(p.name, p.path, p.unit, p.integer, p.datum, (_number(value, "--set", text),),
                  p.info)
    check_values(p, "--set")
    return p


def _typed(shape, value: str, path: str, text: str) -> bool | str | int:
    """The deck value of a boolean, choice or string field from its command-line text."""
    value = value.strip().strip("'\"")
    if shape.kind == "boolean":
        if value.lower() not in ("true", "false"):
            raise _bad("--set", text, f"{path} is true or false", "true or false")
        return value.lower() == "true"
    if shape.kind == "choice":
        for choice in shape.choices:
            if str(choice) == value:
                return choice
        close = difflib.get_close_matches(value, [str(c) for c in shape.choices], n=1)
        raise InputError(Problem("--set", f"{value!r} is not an allowed choice of {path}", text,
                                 "one of " + ", ".join(str(c) for c in shape.choices),
                                 f"did you mean {close[0]}?" if close else ""))
    if not value:
        raise _bad("--set", text, f"{path} needs a non-empty string")
    return value


def apply_fixed(raw: dict, fixed: list[Parameter]) -> dict:
    """The raw deck with every ``--set`` value written in (pivot rules applied)."""
    out = copy.deepcopy(raw)
    for p in fixed:
        value = p.values[0]
        if not isinstance(value, bool | str):
            value = int(value) if p.integer else float(value)
        set_path(out, p.path, value)
    if fixed:
        from camtrain.study.pivot import apply_pivot_rules

        apply_pivot_rules(raw, out, {p.path for p in fixed})
    return out


def assignment_text(fixed: list[Parameter]) -> str:
    """The changes as TOML comment lines, appended to the deck text a run records (its hash
    then differs from the file's, as the deck that ran does)."""
    def shown(v) -> str:
        if isinstance(v, bool):
            return "true" if v else "false"
        return f"{v:g}" if isinstance(v, float) else str(v)

    return "".join(f"\n# --set {p.path} = {shown(p.values[0])}" for p in fixed) + \
        ("\n" if fixed else "")
