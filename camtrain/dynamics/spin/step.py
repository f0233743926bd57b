"""The roller's compiled step in the elastic train's march (backward Euler; see the package)."""
from __future__ import annotations

import numpy as np
from numba import njit

#: bisections of the backward-Euler residual per step (the bracket shrinks 2^-50: below round-off
#: of the rolling speed)
BISECTIONS = 50


@njit(cache=True)
def _row(grid, values, x):
    """Linear interpolation of ``values`` on ``grid`` at x, held at the ends."""
    n = grid.size
    if x <= grid[0]:
        return values[0]
    if x >= grid[n - 1]:
        return values[n - 1]
    k = np.searchsorted(grid, x) - 1
    t = (x - grid[k]) / (grid[k + 1] - grid[k])
    return (1.0 - t) * values[k] + t * values[k + 1]


@njit(cache=True)
def _level(loads, load):
    """Load level below ``load`` and the blend to the next (held at the last level)."""
    top = loads.size - 2
    x = load / loads[loads.size - 1] * (loads.size - 1)
    if x <= 0.0:
        return 0, 0.0
    lev = min(int(x), top)
    return lev, min(x - lev, 1.0)


@njit(cache=True)
def _traction(sp, a, lev, tl, u):
    """The traction table of grid angle ``a`` at sliding speed u, blended between load levels."""
    x = u / sp.sliding_scale[a]
    return ((1.0 - tl) * _row(sp.grid, sp.traction[a, lev], x)
            + tl * _row(sp.grid, sp.traction[a, lev + 1], x))


@njit(cache=True)
def _balance(sp, i, j, ta, lev, tl, v0, w0, w1, h):
    """J (w1 - w0)/h - r F_t(u_s) + T_pin(w1) at angle blend ``ta`` between grid angles i, j
    and load blend ``tl`` above level ``lev`` (h = 0: the quasi-static balance)."""
    u = v0 - sp.radius * w1
    f = (1.0 - ta) * _traction(sp, i, lev, tl, u) + ta * _traction(sp, j, lev, tl, u)
    x = w1 / sp.speed_scale
    tp = (1.0 - tl) * _row(sp.grid, sp.pin[lev], x) + tl * _row(sp.grid, sp.pin[lev + 1], x)
    inertial = sp.inertia * (w1 - w0) / h if h > 0.0 else 0.0
    return inertial - sp.radius * f + tp, u, f


@njit(cache=True)
def spin_step(sp, wr, n, tau, dt, h, force):
    """The roller's state ``wr`` = (speed, sliding, traction) advanced in place over a (sub)step
    of length h ending at time tau into step n (dt the full step), under the valve-referred cam
    force ``force`` [N] at its end."""
    s = min(max(tau / dt, 0.0), 1.0)
    m = min(n + 1, sp.pos.size - 1)
    pos = sp.pos[n] + s * (sp.pos[m] - sp.pos[n])
    load = max(force, 0.0) * (sp.ratio[n] + s * (sp.ratio[m] - sp.ratio[n]))
    size = sp.v_s0.size
    base = np.floor(pos)
    ta = pos - base
    i = int(base) % size
    if i < 0:
        i += size
    j = (i + 1) % size
    lev, tl = _level(sp.loads, load)
    v0 = (1.0 - ta) * sp.v_s0[i] + ta * sp.v_s0[j]
    w0 = wr[0]
    ws = v0 / sp.radius
    lo = min(w0, 0.0, ws)
    hi = max(w0, 0.0, ws)
    span = hi - lo
    lo -= 1e-9 * span + 1e-300
    hi += 1e-9 * span + 1e-300
    g_lo = _balance(sp, i, j, ta, lev, tl, v0, w0, lo, h)[0]
    g_hi = _balance(sp, i, j, ta, lev, tl, v0, w0, hi, h)[0]
    if g_lo == 0.0 and g_hi == 0.0:
        # nothing acts on a roller without inertia (unloaded, frictionless pin): it rolls
        w1 = w0 if sp.inertia > 0.0 else ws
    else:
        for _ in range(BISECTIONS):
            mid = 0.5 * (lo + hi)
            if _balance(sp, i, j, ta, lev, tl, v0, w0, mid, h)[0] > 0.0:
                hi = mid
            else:
                lo = mid
        w1 = 0.5 * (lo + hi)
    _, u, f = _balance(sp, i, j, ta, lev, tl, v0, w0, w1, h)
    wr[0], wr[1], wr[2] = w1, u, f
