"""Shared helpers for the formula layer: input checks and overflow-safe exponentials.

Every check raises :func:`camtrain.errors.field_error` naming the argument, the first offending
value and (for arrays) its flat index, so a caller sweeping a cam cycle can map it to an angle.

The checks are the public entry's guard for people calling a formula directly. The analysis
chain validates its inputs once, at the deck boundary, and filters the angles it passes
(contact, Hertzian geometry); it runs the formulas inside :func:`trusted_inputs`, where the
checks only convert their argument (they cost a third of a 720-angle run otherwise).
"""
from __future__ import annotations

from contextvars import ContextVar

import numpy as np

from camtrain.errors import field_error

#: Largest x for which exp(x) is finite in IEEE double precision.
LOG_FLOAT_MAX = float(np.log(np.finfo(float).max))
#: Smallest x for which exp(x) is still a normal (not subnormal) double; below it we return 0.
LOG_FLOAT_TINY = float(np.log(np.finfo(float).tiny))


_FLOAT = np.dtype(float)
_ndarray = np.ndarray
_min, _max = np.minimum.reduce, np.maximum.reduce   # (ndarray.min/max add a Python wrapper)


def arr(x) -> np.ndarray:
    """Return ``x`` as a float ndarray (0-d for scalars); no copy when already float."""
    if type(x) is _ndarray and x.dtype is _FLOAT:   # the chain's case: nothing to convert
        return x
    return np.asarray(x, dtype=float)


def out(x):
    """Return a Python float for 0-d results, the array otherwise (fluids-style scalar in, scalar out)."""
    if type(x) is not _ndarray:
        x = np.asarray(x)
    return float(x) if x.ndim == 0 else x


def _first_bad(x: np.ndarray, bad: np.ndarray) -> tuple[int, float]:
    flat = np.flatnonzero(np.broadcast_to(bad, x.shape))
    i = int(flat[0])
    return i, float(x.reshape(-1)[i])


_TRUSTED: ContextVar[bool] = ContextVar("camtrain_trusted_inputs", default=False)
_trusted = _TRUSTED.get


class trusted_inputs:   # (lower case: used as a function, ``with trusted_inputs():``)
    """Skip the formula argument checks inside (per thread / task: a context variable).

    For callers whose inputs were validated before (the analysis chain); a user calling a
    formula outside this block always gets the checked entry. (A class rather than a
    generator-based context manager: it is entered once per run.)"""

    __slots__ = ("_token",)

    def __enter__(self) -> None:
        self._token = _TRUSTED.set(True)

    def __exit__(self, *exc) -> None:
        _TRUSTED.reset(self._token)


def checking() -> bool:
    """False inside :func:`trusted_inputs` (the chain's inputs were validated at the deck)."""
    return not _TRUSTED.get()


def check(name: str, x, ok, expected: str, hint: str = "") -> np.ndarray:
    """Raise a field error if any element of ``x`` fails ``ok`` (a boolean array or callable);
    inside :func:`trusted_inputs` only convert ``x``."""
    x = arr(x)
    if _trusted():
        return x
    good = ok(x) if callable(ok) else np.asarray(ok)
    good = good & ~np.isnan(x)
    if not np.all(good):
        i, v = _first_bad(x, ~good)
        where = f" at index {i}" if x.ndim else ""
        raise field_error(name, f"out of range{where}", v, expected, hint)
    return x


def positive(name: str, x, hint: str = "") -> np.ndarray:
    """Finite and strictly positive."""
    if _trusted():   # the chain's inputs: converted, not checked (see check)
        return arr(x)
    return check(name, x, lambda v: np.isfinite(v) & (v > 0), "a finite value > 0", hint)


def non_negative(name: str, x, hint: str = "") -> np.ndarray:
    """Finite and >= 0."""
    if _trusted():
        return arr(x)
    return check(name, x, lambda v: np.isfinite(v) & (v >= 0), "a finite value >= 0", hint)


def finite(name: str, x, hint: str = "") -> np.ndarray:
    if _trusted():
        return arr(x)
    return check(name, x, np.isfinite, "a finite number", hint)


_RADIUS_HINT = ("a conformal or concave contact (curvature sum 1/R <= 0) is outside Hertz/EHL "
                "theory; large finite R is fine")


def radius(name: str, x) -> np.ndarray:
    """Equivalent (reduced) radius of a non-conformal contact: 0 < R < inf."""
    return positive(name, x, _RADIUS_HINT)


def _broadcast(*arrays: np.ndarray) -> tuple[np.ndarray, ...]:
    """np.broadcast_arrays, skipped when the shapes already agree (the chain's common case)."""
    shape = arrays[0].shape
    for a in arrays[1:]:
        if a.shape != shape:
            return tuple(np.broadcast_arrays(*arrays))
    return arrays


def safe_exp(x) -> np.ndarray:
    """exp(x) returning +inf above the float range and 0 below the normal range, silently.

    Over- and underflow are decided by comparison, never by evaluating an overflowing exp, so the
    function is quiet under ``np.errstate(all="raise")``.
    """
    x = arr(x)
    if x.ndim and x.size and (LOG_FLOAT_TINY <= _min(x, axis=None)
                              and _max(x, axis=None) <= LOG_FLOAT_MAX):
        return np.exp(x)   # all in range (no NaN): the clip and the selections change nothing
    res = np.exp(np.minimum(np.maximum(x, LOG_FLOAT_TINY), LOG_FLOAT_MAX))   # clip, NaN kept
    return np.where(x > LOG_FLOAT_MAX, np.inf, np.where(x < LOG_FLOAT_TINY, 0.0, res))


def capped_exp_product(prefactor, log_factor, cap) -> np.ndarray:
    """min(prefactor * exp(log_factor), cap) without overflow.

    ``prefactor`` >= 0 may be +inf (e.g. a zero film), ``cap`` >= 0 may be +inf (no cap). The
    product is formed in log space only where both sides are positive and finite; the result is
    inf-free whenever ``cap`` is finite.
    """
    prefactor, log_factor, cap = _broadcast(arr(prefactor), arr(log_factor), arr(cap))
    pos = (prefactor > 0) & np.isfinite(prefactor)
    if np.count_nonzero(pos) == pos.size:   # every prefactor positive and finite: no selection
        return np.minimum(safe_exp(np.log(prefactor) + log_factor), cap)
    logp = np.log(np.where(pos, prefactor, 1.0)) + log_factor
    uncapped = np.where(pos, safe_exp(logp), np.where(prefactor > 0, np.inf, 0.0))
    return np.minimum(uncapped, cap)


def safe_divide(num, den, zero_den=np.inf) -> np.ndarray:
    """num/den, with ``zero_den`` where den == 0 and num != 0, and 0 where both are 0."""
    num, den = _broadcast(arr(num), arr(den))
    nz = den != 0
    if nz.ndim and np.count_nonzero(nz) == nz.size:   # no zero denominator: plain division
        return np.divide(num, den)
    res = np.divide(num, np.where(nz, den, 1.0))
    return np.where(nz, res, np.where(num == 0, 0.0, zero_den))
