r"""Implicit periodic march of one positive state y(t) fixed by an algebraic balance per step.

The kernel behind the level-2 film (the minimum film of the cam contact) and reusable for any
"load balance decides the film" problem (a piston ring's minimum film is the same structure):
at each node t_i the caller's ``balance(i, y, ydot)`` must vanish, where ydot is the scheme's
difference formula in y. The caller makes the balance *decreasing* in y (a thicker film carries
less load); each step is then one bracketed scalar root, solved in ln y (Brent), so y stays
positive and the stiff thin-film branch costs no more than the thick one.

Schemes (uniform or not in t):

* ``implicit_euler`` (backward Euler, first order): ydot = (y - y_n)/dt;
* ``bdf2`` (second order, L-stable; variable-step form, the very first step of a run is Euler):
  ydot = [(1+2r)/(1+r) y - (1+r) y_n + r^2/(1+r) y_{n-1}]/dt, r = dt/dt_prev;
* ``quasi_steady``: ydot = 0 (each node on its own: the steady limit).

Nodes the caller marks inactive (e.g. a lost contact) keep the previous value with ydot = 0.
Cycles repeat (the first node of a cycle follows the last of the previous one) until the largest
relative change of y between two successive cycles is below ``period_tol``.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

import numpy as np
from scipy.optimize import brentq

__all__ = ["MARCH_SCHEMES", "MarchResult", "implicit_march", "solve_positive_root"]

MARCH_SCHEMES = ("implicit_euler", "bdf2", "quasi_steady")


class MarchResult(NamedTuple):
    y: np.ndarray            #: state at each node (last cycle)
    ydot: np.ndarray         #: its rate from the scheme's difference formula
    residual: np.ndarray     #: balance at the solution (nan at inactive nodes)
    met: np.ndarray          #: False where the balance could not be met above ``y_min``
    cycles: int              #: cycles marched
    period_error: float      #: largest relative change of y over the last cycle
    evaluations: int         #: balance evaluations in total


def solve_positive_root(f: Callable[[float], float], guess: float, xtol: float = 1e-12,
                        y_min: float = 0.0, max_expand: int = 400) -> tuple[float, int, bool]:
    """Root y > 0 of a decreasing f, bracketed by expanding from ``guess`` in ln y (Brent).

    Returns (y, evaluations, met). If f is still negative at ``y_min`` (> 0: a floor below
    which the model does not apply) the balance cannot be met: (y_min, evaluations, False).
    Raises ValueError if no sign change is found within ``max_expand`` factor-2 expansions.
    """
    calls = 0

    def g(s: float) -> float:
        nonlocal calls
        calls += 1
        return f(math.exp(s))

    floor = math.log(y_min) if y_min > 0.0 else -math.inf
    s0 = max(math.log(guess), floor)
    r0 = g(s0)
    if r0 == 0.0:
        return math.exp(s0), calls, True
    step = math.log(2.0) * (1.0 if r0 > 0.0 else -1.0)
    s1 = s0
    for _ in range(max_expand):
        s1 = max(s1 + step, floor)
        r1 = g(s1)
        if (r1 <= 0.0) == (r0 > 0.0):
            break
        if s1 == floor:
            return y_min, calls, False
        s0, r0 = s1, r1
    else:
        raise ValueError(f"no root of the balance near {guess:.6g} (residual {r0:.6g})")
    lo, hi = (s0, s1) if s0 < s1 else (s1, s0)
    s = brentq(g, lo, hi, xtol=xtol, rtol=4.0 * np.finfo(float).eps, maxiter=200)
    return math.exp(s), calls, True


def implicit_march(balance: Callable[[int, float, float], float], t, y_start: float,
                   scheme: str = "implicit_euler", period: float | None = None,
                   active=None, cycles_max: int = 5, period_tol: float = 1e-6,
                   xtol: float = 1e-12, y_min: float = 0.0) -> MarchResult:
    """March y over the nodes t (one period of length ``period``, end point excluded).

    Args:
        balance: residual(i, y, ydot), decreasing in y at fixed scheme coupling; 0 at the
            solution (normalise it, e.g. by the applied load, so ``xtol`` means something).
        t: ascending node times [s] over one period.
        y_start: y at the node before t[0] (the starting guess of the first cycle).
        scheme: one of :data:`MARCH_SCHEMES`.
        period: cycle length [s] (default: t[-1] - t[0] + the last step, i.e. uniform).
        active: boolean per node (default all); inactive nodes hold y with ydot = 0.
        cycles_max, period_tol: periodic convergence (at least two cycles are run).
        xtol: root tolerance in ln y (relative in y).
        y_min: floor of y; a node whose balance stays negative there holds y_min and is
            reported in ``met`` (e.g. a load the film model cannot carry at any positive film).
    """
    if scheme not in MARCH_SCHEMES:
        raise ValueError(f"march {scheme!r}: expected one of {MARCH_SCHEMES}")
    t = np.asarray(t, dtype=float)
    n = t.size
    if period is None:
        period = t[-1] - t[0] + (t[-1] - t[-2])
    dt = np.diff(t, prepend=t[-1] - period)          # step arriving at node i
    if np.any(dt <= 0.0):
        raise ValueError("node times must ascend within one period")
    act = np.ones(n, bool) if active is None else np.asarray(active, bool)
    y = np.empty(n)
    ydot = np.zeros(n)
    res = np.full(n, np.nan)
    met = np.ones(n, bool)
    y_n, y_nm1, dt_prev = float(y_start), math.nan, math.nan
    calls, cycles, error, previous = 0, 0, math.inf, None
    while cycles < cycles_max and (cycles < 2 or error > period_tol):
        for i in range(n):
            h = float(dt[i])
            if not act[i]:
                y[i], ydot[i] = y_n, 0.0
            else:
                rate = _rate(scheme, h, dt_prev, y_n, y_nm1)
                yi, c, met[i] = solve_positive_root(
                    lambda v, i=i, rate=rate: balance(i, v, rate(v)), y_n, xtol, y_min)
                calls += c
                y[i], ydot[i] = yi, rate(yi)
                res[i] = balance(i, yi, ydot[i])
            y_nm1, y_n, dt_prev = y_n, float(y[i]), h
        cycles += 1
        if previous is not None:
            error = float(np.max(np.abs(y - previous) / previous))
        previous = y.copy()
    return MarchResult(y, ydot, res, met, cycles, error, calls)


def _rate(scheme: str, dt: float, dt_prev: float, y_n: float, y_nm1: float):
    """ydot as a function of the new y for the scheme (Euler where BDF2 has no history yet)."""
    if scheme == "quasi_steady":
        return lambda v: 0.0
    if scheme == "bdf2" and math.isfinite(y_nm1):
        r = dt / dt_prev
        a0, a1, a2 = (1.0 + 2.0 * r) / (1.0 + r), -(1.0 + r), r * r / (1.0 + r)
        rest = a1 * y_n + a2 * y_nm1
        return lambda v: (a0 * v + rest) / dt
    return lambda v: (v - y_n) / dt
