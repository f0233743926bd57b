"""The roller's compiled step in the elastic train's march (backward Euler; see the package)."""
from __future__ import annotations

import numpy as np
from numba import njit

from camtrain.numerics.roots import false_position, illinois_update
from camtrain.numerics.tables import held_linear

#: most evaluations of the backward-Euler residual per step, and the bracket or last move
#: (relative to the speeds bracketed) at which the speed counts as found
ITERATIONS = 80
TOLERANCE = 1e-13
#: the load levels are uniform in W^(1/LEVEL_POWER), finer at light load (spin_tables)
LEVEL_POWER = 3.0


@njit(cache=True)
def _level(loads, load):
    """Load level below ``load`` (the levels are uniform in W^(1/LEVEL_POWER):
    :func:`camtrain.assemble.roller.spin_tables`), the blend to the next in that abscissa and
    in W (held at the last level)."""
    top = loads.size - 2
    x = (load / loads[loads.size - 1]) ** (1.0 / LEVEL_POWER) * (loads.size - 1)
    if x <= 0.0:
        return 0, 0.0, 0.0
    lev = min(int(x), top)
    return lev, min(x - lev, 1.0), min((load - loads[lev]) / (loads[lev + 1] - loads[lev]), 1.0)


@njit(cache=True)
def _traction(sp, a, lev, tl, u):
    """The traction table of grid angle ``a`` at sliding speed u, between two load levels
    geometrically at the blend ``tl`` in the levels' abscissa W^(1/3) (the Barus shear grows
    exponentially with the Hertz pressure; see the package), linearly where a level carries
    none."""
    x = u / sp.sliding_scale[a]
    f0 = held_linear(sp.grid, sp.traction[a, lev], x)
    f1 = held_linear(sp.grid, sp.traction[a, lev + 1], x)
    if f0 * f1 > 0.0:
        return np.sign(f0) * np.exp((1.0 - tl) * np.log(abs(f0)) + tl * np.log(abs(f1)))
    return (1.0 - tl) * f0 + tl * f1


@njit(cache=True)
def _balance(sp, i, j, ta, lev, tl, v0, w0, w1, h):
    """J (w1 - w0)/h - r F_t(u_s) + T_pin(w1) at angle blend ``ta`` between grid angles i, j
    and load level ``lev`` with blends ``tl`` = (in W^(1/3), in W) (h = 0: the quasi-static
    balance). The pin torque is linear in W between levels (exact for the needle's M_0 + M_1)."""
    u = v0 - sp.radius * w1
    ts, tw = tl
    f = (1.0 - ta) * _traction(sp, i, lev, ts, u) + ta * _traction(sp, j, lev, ts, u)
    x = w1 / sp.speed_scale
    tp = (1.0 - tw) * held_linear(sp.grid, sp.pin[lev], x) + tw * held_linear(sp.grid, sp.pin[lev + 1], x)
    inertial = sp.inertia * (w1 - w0) / h if h > 0.0 else 0.0
    return inertial - sp.radius * f + tp, u, f


@njit(cache=True)
def _nodes(sp, i, j, ta, lev, tl, v0, w0, h, br, a, b):
    """Narrow the bracket ``br`` = (lo, g_lo, hi, g_hi) by bisection over the table nodes that
    fall inside it, the node k at speed w = a + b grid[k] (a traction table: a = V_s0/r,
    b = -scale/r; the pin's: a = 0, b = its speed scale)."""
    x1, x2 = (br[0] - a) / b, (br[2] - a) / b
    k1 = np.searchsorted(sp.grid, min(x1, x2), side="right")
    k2 = np.searchsorted(sp.grid, max(x1, x2), side="left") - 1
    while k1 <= k2 and br[1] != 0.0 and br[3] != 0.0:
        km = (k1 + k2) // 2
        wm = a + b * sp.grid[km]
        if not br[0] < wm < br[2]:
            return
        gm = _balance(sp, i, j, ta, lev, tl, v0, w0, wm, h)[0]
        if gm <= 0.0:
            br[0], br[1] = wm, gm
        else:
            br[2], br[3] = wm, gm
        if (gm <= 0.0) == (b > 0.0):   # the root at larger node indices
            k1 = km + 1
        else:
            k2 = km - 1


@njit(cache=True)
def _root(sp, i, j, ta, lev, tl, v0, w0, h, lo, g_lo, hi, g_hi):
    """The speed where the balance (increasing, g_lo <= 0 <= g_hi) vanishes: Illinois regula
    falsi (:mod:`camtrain.numerics.roots`; the tables are piecewise linear, so the secant is
    exact on a piece) until the residual is TOLERANCE x the bracket's residuals, or the bracket
    or the last move TOLERANCE x the speeds' size; the end nearer the root when it stops."""
    width = TOLERANCE * (abs(lo) + abs(hi)) + 1e-300
    small = TOLERANCE * (abs(g_lo) + abs(g_hi))
    x = lo if abs(g_lo) < abs(g_hi) else hi
    side = 0
    for _ in range(ITERATIONS):
        if min(abs(g_lo), abs(g_hi)) <= small or hi - lo <= width:
            break
        last = x
        x = false_position(lo, g_lo, hi, g_hi)
        if not lo < x < hi:   # the secant lands on an end within round-off
            break
        gx = _balance(sp, i, j, ta, lev, tl, v0, w0, x, h)[0]
        if abs(gx) <= small or abs(x - last) <= width:
            return x
        lo, g_lo, hi, g_hi, side = illinois_update(lo, g_lo, hi, g_hi, x, gx, side)
        x = lo if abs(g_lo) < abs(g_hi) else hi
    return x


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
    lev, ts, tw = _level(sp.loads, load)
    tl = (ts, tw)
    v0 = (1.0 - ta) * sp.v_s0[i] + ta * sp.v_s0[j]
    w0 = wr[0]
    ws = v0 / sp.radius
    # the root lies between the last speed and rolling as a rule: bracket it there, else widen
    lo, hi = min(w0, ws), max(w0, ws)
    g_lo = _balance(sp, i, j, ta, lev, tl, v0, w0, lo, h)[0]
    g_hi = _balance(sp, i, j, ta, lev, tl, v0, w0, hi, h)[0]
    if g_lo == 0.0 and g_hi == 0.0:
        # nothing acts on a roller without inertia (unloaded, frictionless pin): it rolls
        wr[0], wr[1], wr[2] = (w0 if sp.inertia > 0.0 else ws), v0 - sp.radius * ws, 0.0
        return
    span = hi - lo + 1e-6 * (abs(w0) + abs(ws)) + 1e-12
    for _ in range(ITERATIONS):
        if g_lo <= 0.0:
            break
        hi, g_hi = lo, g_lo
        lo -= span
        span *= 2.0
        g_lo = _balance(sp, i, j, ta, lev, tl, v0, w0, lo, h)[0]
    for _ in range(ITERATIONS):
        if g_hi >= 0.0:
            break
        lo, g_lo = hi, g_hi
        hi += span
        span *= 2.0
        g_hi = _balance(sp, i, j, ta, lev, tl, v0, w0, hi, h)[0]
    br = np.array([lo, g_lo, hi, g_hi])
    # the residual is linear between the tables' nodes: narrow the bracket to one piece of each
    # table (a secant across the steep piece at zero sliding would crawl), then the secant
    _nodes(sp, i, j, ta, lev, tl, v0, w0, h, br, ws, -sp.sliding_scale[i] / sp.radius)
    _nodes(sp, i, j, ta, lev, tl, v0, w0, h, br, ws, -sp.sliding_scale[j] / sp.radius)
    _nodes(sp, i, j, ta, lev, tl, v0, w0, h, br, 0.0, sp.speed_scale)
    lo, g_lo, hi, g_hi = br[0], br[1], br[2], br[3]
    w1 = lo if g_lo == 0.0 else (hi if g_hi == 0.0 else
                                 _root(sp, i, j, ta, lev, tl, v0, w0, h, lo, g_lo, hi, g_hi))
    _, u, f = _balance(sp, i, j, ta, lev, tl, v0, w0, w1, h)
    wr[0], wr[1], wr[2] = w1, u, f
