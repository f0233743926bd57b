"""Sweep cases: parameter names and dotted deck paths, value lists, grids and zips.

A case is the raw TOML dictionary of the deck with some numeric fields replaced (in the deck's own
units), then validated and run like any deck. Nothing here imports numpy: the command line parses
and checks its arguments before any heavy import.
"""
from __future__ import annotations

import copy
import itertools
import math
import re
from dataclasses import dataclass, field

from camtrain.errors import InputError, Problem

#: Ball's seven design variables (1988, §4.2.4) -> dotted deck path. 'speed' is resolved per deck.
ALIASES: dict[str, str] = {
    "base_radius": "cam.base_radius",
    "cam_width": "cam.width",
    "spring_rate": "spring.rate",
    "speed": "speed.camshaft",
    "follower_radius": "mechanism.follower_radius",
    "viscosity": "lubricant.viscosity",
    "equivalent_mass": "masses.valve_side",
}

_TOKEN = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?$")


@dataclass(frozen=True)
class Parameter:
    """One swept (or fixed) deck field: its name, dotted path, unit and values in that unit."""

    name: str
    path: str
    unit: str
    integer: bool
    datum: float | None
    values: tuple[float, ...] = ()
    info: object = field(default=None, repr=False, compare=False)

    @property
    def label(self) -> str:
        """Column label with the unit, e.g. ``base_radius[mm]``."""
        return f"{self.name}[{self.unit}]"


@dataclass(frozen=True)
class Case:
    """One point of a sweep: its index and the value of every swept parameter (deck units)."""

    index: int
    values: tuple[tuple[str, float], ...]

    def as_dict(self) -> dict[str, float]:
        return dict(self.values)


def _bad(option: str, value: object, message: str, expected: str = "") -> InputError:
    return InputError(Problem(option, message, value, expected))


# --------------------------------------------------------------------------- paths

def _split(path: str, option: str) -> list[tuple[str, int | None]]:
    tokens = []
    for part in path.split("."):
        m = _TOKEN.match(part)
        if not m:
            raise _bad(option, path, "is not a dotted deck path",
                       "a parameter name or a path such as cam.base_radius or "
                       "lift.four_power.coefficients[0]")
        tokens.append((m.group(1), None if m.group(2) is None else int(m.group(2))))
    return tokens


def _schema_of(raw: dict) -> type:
    """The schema class of a raw deck's kind (valve_train when it names none or an unknown)."""
    import importlib

    from camtrain.catalogue import DEFAULT_KIND, KINDS

    kind = KINDS.get(raw.get("kind", DEFAULT_KIND), KINDS[DEFAULT_KIND])
    module, cls = kind.schema.split(":")
    return getattr(importlib.import_module(module), cls)


#: leaf kinds ``--set`` may also change (a sweep's parameters are numbers)
SCALARS = ("boolean", "string", "choice")


def _field_at(path: str, option: str, schema: type | None = None, scalars: bool = False):
    """Walk the deck schema along ``path``; return (Shape, FieldInfo, default in SI) of the leaf:
    a number, or with ``scalars`` also a boolean, string or choice."""
    from camtrain.deck.fields import deck_key, schema_paths, section_fields
    from camtrain.deck.schema import Deck

    Deck = schema or Deck  # noqa: N806 - the schema class the path is read against
    cls, done = Deck, []
    tokens = _split(path, option)
    for i, (key, index) in enumerate(tokens):
        fields = {deck_key(f): (f, shape, info) for f, shape, info in section_fields(cls)}
        where = ".".join(done) or "the deck"
        if key not in fields:
            import difflib

            close = difflib.get_close_matches(key, list(fields), n=1)
            hint = f"did you mean {'.'.join(done + [close[0]])}?" if close else \
                "known keys here: " + ", ".join(sorted(fields))
            elsewhere = schema_paths(Deck).get(key)
            if not close and elsewhere:
                hint = f"did you mean {elsewhere[0]}?"
            raise InputError(Problem(option, f"{key!r} is not a key of {where}", path, "", hint))
        f, shape, info = fields[key]
        done.append(key if index is None else f"{key}[{index}]")
        last = i == len(tokens) - 1
        if shape.kind == "section" and not last and index is None:
            cls = shape.section
        elif shape.kind == "sections" and not last and index is not None:
            cls = shape.section
        elif last and shape.kind in ("number", "integer") and index is None:
            return shape, info, f.default
        elif last and shape.kind == "numbers" and index is not None:
            return shape, info, None
        elif last and scalars and shape.kind in SCALARS and index is None:
            return shape, info, f.default
        else:
            raise _bad(option, path, "does not name a single number in the deck",
                       "a numeric field (a list entry needs an index, e.g. [0])")
    raise _bad(option, path, "does not name a single number in the deck")  # pragma: no cover


def _get(raw: dict, path: str):
    node = raw
    for key, index in _split(path, "--param"):
        if not isinstance(node, dict) or key not in node:
            return None
        node = node[key]
        if index is not None:
            if not isinstance(node, list) or index >= len(node):
                return None
            node = node[index]
    return node


def set_path(raw: dict, path: str, value) -> None:
    """Set a dotted path in a raw deck dict in place, creating missing tables."""
    tokens = _split(path, "--param")
    node = raw
    for key, index in tokens[:-1]:
        node = node.setdefault(key, {}) if index is None else node[key][index]
    key, index = tokens[-1]
    if index is None:
        node[key] = value
    else:
        node[key][index] = value


def resolve_path(raw: dict, name: str, option: str = "--param") -> Parameter:
    """A parameter name (alias or dotted path) -> Parameter with unit, type and datum value."""
    from camtrain.units import UNITS

    if "." not in name and name not in ALIASES:
        import difflib

        close = difflib.get_close_matches(name, list(ALIASES), n=1)
        raise InputError(Problem(option, "is not a parameter name", name,
                                 "one of " + ", ".join(ALIASES) + " or a dotted deck path",
                                 f"did you mean {close[0]}?" if close else ""))
    path = ALIASES.get(name, name)
    if name == "speed" and _get(raw, "speed.engine") is not None:
        path = "speed.engine"
    shape, info, default = _field_at(path, option, _schema_of(raw))
    datum = _get(raw, path)
    if isinstance(datum, bool) or not isinstance(datum, int | float):
        datum = None
    if datum is None and isinstance(default, int | float) and not isinstance(default, bool):
        datum = default / UNITS[info.unit][0] if shape.kind == "number" else default
    return Parameter(name, path, info.unit, shape.kind == "integer",
                     None if datum is None else float(datum), (), info)


# --------------------------------------------------------------------------- values

def _number(text: str, option: str, spec: str) -> float:
    try:
        x = float(text.strip().rstrip("%"))
    except ValueError:
        raise _bad(option, spec, f"{text.strip()!r} is not a number") from None
    if not math.isfinite(x):
        raise _bad(option, spec, "values must be finite")
    return x


def _count(text: str, option: str, spec: str) -> int:
    try:
        n = int(text.strip())
    except ValueError:
        raise _bad(option, spec, f"the number of points {text.strip()!r} is not a whole number",
                   "START:STOP:N") from None
    if n < 1 or n > 100_000:
        raise _bad(option, spec, f"the number of points {n} is out of range", "1 to 100000")
    return n


def _linspace(a: float, b: float, n: int) -> list[float]:
    # endpoints exact, interior points rounded so that 14:22:9 gives 15.0, not 15.000000000000002
    if n == 1:
        return [a]
    return [float(f"{a + (b - a) * i / (n - 1):.12g}") for i in range(n)]


def parse_values(kind: str, spec: str, datum: float | None, name: str) -> tuple[float, ...]:
    """Values of one parameter from ``--values a,b,c``, ``--range START:STOP:N`` or
    ``--relative -50%:+50%:N`` (percent change from the deck's datum value)."""
    option = f"--{kind}"
    if kind == "values":
        parts = [p for p in spec.split(",") if p.strip()]
        if not parts:
            raise _bad(option, spec, "no values given", "comma-separated numbers")
        return tuple(_number(p, option, spec) for p in parts)
    parts = spec.split(":")
    if len(parts) != 3:
        expected = "START:STOP:N" if kind == "range" else "-PCT%:+PCT%:N, e.g. -50%:+50%:11"
        raise _bad(option, spec, "needs three fields", expected)
    a, b = _number(parts[0], option, spec), _number(parts[1], option, spec)
    n = _count(parts[2], option, spec)
    points = _linspace(a, b, n)
    if kind == "range":
        return tuple(points)
    if datum is None:
        raise _bad(option, spec, f"{name} has no value in the deck to take a percentage of",
                   "--values or --range")
    return tuple(float(f"{datum * (1.0 + p / 100.0):.12g}") for p in points)


def check_values(param: Parameter, option: str) -> None:
    """Values inside the field's bounds, whole numbers for integer fields: else exit code 2."""
    info = param.info
    for x in param.values:
        if param.integer and x != int(x):
            raise _bad(option, x, f"{param.path} takes whole numbers", "an integer")
        bad = ((info.gt is not None and not x > info.gt) or (info.ge is not None and not x >= info.ge)
               or (info.lt is not None and not x < info.lt)
               or (info.le is not None and not x <= info.le))
        if bad:
            raise _bad(option, x, f"is out of range for {param.path}", info.expected_text())


def parse_bounds(option: str, text: str, expected: str = "LOW:HIGH") -> tuple[float, float]:
    """``LOW:HIGH`` (deck units) -> (low, high): two finite numbers with low < high, else exit
    code 2 naming ``option``. The one reader of a bounds pair (``fit --bounds``, ``optimize
    --var NAME=LOW:HIGH``)."""
    try:
        low, high = (float(p) for p in text.split(":"))
    except ValueError:
        raise _bad(option, text, "needs two numbers", expected) from None
    return checked_bounds(option, low, high, text)


def checked_bounds(option: str, low: float, high: float, shown: object = None
                   ) -> tuple[float, float]:
    """(low, high) when both are finite and low < high, else exit code 2."""
    shown = f"{low:g}:{high:g}" if shown is None else shown
    if not (math.isfinite(low) and math.isfinite(high)):
        raise _bad(option, shown, "the bounds must be finite numbers", "LOW:HIGH")
    if not high > low:
        raise _bad(option, shown, "the upper bound must exceed the lower", "LOW < HIGH")
    return low, high


def bounded(param: Parameter, low: float, high: float, option: str) -> Parameter:
    """``param`` with its bounds as its two values, each checked against the field's range
    (:func:`check_values`)."""
    out = Parameter(param.name, param.path, param.unit, param.integer, param.datum,
                    (low, high), param.info)
    check_values(out, option)
    return out


def build_parameters(raw: dict, specs: list[tuple[str, str, str]]) -> list[Parameter]:
    """``specs`` = [(name, kind, text)] with kind values|range|relative -> checked Parameters."""
    params: list[Parameter] = []
    for name, kind, text in specs:
        p = resolve_path(raw, name)
        if any(q.path == p.path for q in params):
            raise _bad("--param", name, f"{p.path} is swept twice")
        values = parse_values(kind, text, p.datum, name)
        p = Parameter(p.name, p.path, p.unit, p.integer, p.datum, values, p.info)
        check_values(p, f"--{kind}")
        params.append(p)
    return params


def cases(params: list[Parameter], zipped: bool = False) -> list[Case]:
    """All cases: the full grid (first parameter varies slowest), or the values paired (--zip)."""
    if not params:
        raise _bad("--param", None, "nothing to sweep", "at least one --param")
    names = [p.name for p in params]
    if zipped:
        lengths = {p.name: len(p.values) for p in params}
        if len(set(lengths.values())) != 1:
            raise _bad("--zip", lengths, "zipped parameters need the same number of values")
        combos = zip(*(p.values for p in params), strict=True)
    else:
        combos = itertools.product(*(p.values for p in params))
    return [Case(i, tuple(zip(names, combo, strict=True))) for i, combo in enumerate(combos)]


# --------------------------------------------------------------------------- applying a case

def case_raw(raw: dict, params: list[Parameter], case: Case) -> dict:
    """A deep copy of the raw deck with the case's values written in (pivot rules applied)."""
    out = copy.deepcopy(raw)
    values = case.as_dict()
    for p in params:
        x = values[p.name]
        set_path(out, p.path, int(x) if p.integer else float(x))
    from camtrain.study.pivot import apply_pivot_rules

    apply_pivot_rules(raw, out, {p.path for p in params})
    return out
