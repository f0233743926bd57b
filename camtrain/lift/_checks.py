"""Input validation shared by the lift laws.

Constructors take SI values; errors speak the units a deck uses (mm, deg), because the person
reading the message wrote millimetres and degrees. Every error names its deck field.
"""
from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from camtrain.errors import InputError, field_error
from camtrain.lift.base import DEG, MM

# (factor from SI to deck units, unit name) for the quantities a lift deck contains
UNITS = {"length": (1.0 / MM, "mm"), "angle": (1.0 / DEG, "deg"), "none": (1.0, ""),
         "accel_deg": (DEG**2 / MM, "mm/deg^2")}


def shown(value: float, kind: str) -> float:
    """``value`` (SI) in deck units, rounded for a readable message."""
    factor, _ = UNITS[kind]
    return float(f"{float(value) * factor:.6g}")


def unit(kind: str) -> str:
    return UNITS[kind][1]


def fail(path: str, message: str, value: object = None, expected: str = "",
         hint: str = "") -> InputError:
    """``field_error`` with the hint written as a sentence (it follows the expectation)."""
    return field_error(path, message, value, expected, hint[:1].upper() + hint[1:])


def scalar(value: object, path: str, kind: str = "none", *, minimum: float | None = None,
           strict: bool = False, maximum: float | None = None) -> float:
    """A finite real number, optionally bounded (bounds in SI)."""
    try:
        x = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise fail(path, "must be a number", value) from None
    if not np.isfinite(x):
        raise fail(path, "must be a finite number", value)
    u = unit(kind)
    if minimum is not None and (x < minimum or (strict and x == minimum)):
        rel = ">" if strict else ">="
        raise fail(path, f"is out of range{f' ({u})' if u else ''}", shown(x, kind),
                   f"a value {rel} {shown(minimum, kind):g} {u}".rstrip())
    if maximum is not None and x > maximum:
        raise fail(path, f"is out of range{f' ({u})' if u else ''}", shown(x, kind),
                   f"a value <= {shown(maximum, kind):g} {u}".rstrip())
    return x


def vector(values: object, path: str, *, min_len: int = 1, max_len: int | None = None,
           kind: str = "none") -> np.ndarray:
    """A 1-D array of finite reals with a length in [min_len, max_len]."""
    try:
        arr = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise fail(path, "must be a list of numbers", values) from None
    if arr.ndim == 0:
        arr = arr.reshape(1)
    if arr.ndim != 1:
        raise fail(path, "must be a flat list of numbers", arr.shape)
    if arr.size < min_len or (max_len is not None and arr.size > max_len):
        want = f"{min_len}" if max_len == min_len else (
            f"{min_len} to {max_len}" if max_len is not None else f"at least {min_len}")
        raise fail(path, f"has {arr.size} values", None, f"{want} values")
    bad = np.flatnonzero(~np.isfinite(arr))
    if bad.size:
        raise fail(f"{path}[{bad[0]}]", "must be a finite number", float(arr[bad[0]]))
    return arr


def exponents(values: Sequence[float], path: str, *, count: int | None = None) -> np.ndarray:
    """Exponents of an even power series in |theta/half_period|.

    Each must be 2 or at least 3: a smaller one makes velocity (< 1), acceleration (< 2) or jerk
    (between 2 and 3) infinite at the nose. They must also be distinct, or the series is not a
    set of independent terms (and the polydyne coefficients divide by zero).
    """
    r = vector(values, path, min_len=count or 1, max_len=count)
    for i, e in enumerate(r):
        if not (e == 2.0 or e >= 3.0):
            raise fail(f"{path}[{i}]", "is an impossible exponent", float(e),
                       "2 or a value >= 3",
                       "smaller exponents give infinite velocity, acceleration or jerk at the nose")
    if len(set(r.tolist())) != r.size:         # not np.unique: in numpy 2.4 it imports numpy.ma (~10 ms)
        raise fail(path, "contains a repeated exponent", [float(e) for e in r],
                   "distinct exponents")
    return r
