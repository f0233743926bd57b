"""Illinois regula falsi, the bracketing root finder of the compiled kernels (numba, cached).

A kernel evaluates its own residual inline (numba passes no closures) and hands the bracket to
these helpers: the false-position point of the bracket, then :func:`illinois_update`, which keeps
the root bracketed and halves the value at an end retained twice in a row (Dowell & Jarratt 1971,
BIT 11, the Illinois modification), so the convergence is superlinear instead of one-sided.

The two point formulas are the same line through (lo, f_lo) and (hi, f_hi) rounded differently;
each kernel keeps the one it was built with, so its numbers do not move by an ulp.
"""
from __future__ import annotations

from numba import njit


@njit(cache=True, inline="always")
def false_position(lo, f_lo, hi, f_hi):
    """Zero of the secant through (lo, f_lo), (hi, f_hi), as a step from lo."""
    return lo + (hi - lo) * f_lo / (f_lo - f_hi)


@njit(cache=True, inline="always")
def false_position_mean(lo, f_lo, hi, f_hi):
    """Zero of the secant through (lo, f_lo), (hi, f_hi), as the weighted mean of the ends."""
    return (lo * f_hi - hi * f_lo) / (f_hi - f_lo)


@njit(cache=True, inline="always")
def illinois_update(lo, f_lo, hi, f_hi, x, fx, side):
    """The bracket after the trial (x, fx): -> (lo, f_lo, hi, f_hi, side).

    x replaces the end whose value has fx's sign (``fx > 0`` against ``f_lo > 0``); ``side`` is
    -1 when lo moved, +1 when hi moved (0 before the first trial). An end kept twice in a row has
    its value halved, which pulls the next point towards it."""
    if (fx > 0.0) == (f_lo > 0.0):
        lo, f_lo = x, fx
        if side == -1:
            f_hi *= 0.5
        side = -1
    else:
        hi, f_hi = x, fx
        if side == 1:
            f_lo *= 0.5
        side = 1
    return lo, f_lo, hi, f_hi, side
