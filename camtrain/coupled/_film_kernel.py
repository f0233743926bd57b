"""Compiled pieces of the level-1 squeeze film inside the monolithic march (numba, cached): one
implicit-Euler step of the film of every cam contact and the friction coefficient read from a
table over load, film ratio and cam angle (:mod:`.film` builds the
tables; :mod:`._revolution` calls these once per contact and time step).

Teodorescu et al. (2005) eqs. 5-6 written as a relaxation law (docs/transient_film.md,
:mod:`camtrain.lubrication.squeeze`): dh/dt = -(|u| / 96.775) ln(h / F). The step solves
h + k ln h = h_old + k ln F_new, k = |u| dt / 96.775, as
:func:`camtrain.lubrication.squeeze.relaxation_step` does with scipy's Wright omega; here by
Newton in ln h inside the bracket [ln h_old, ln F_new] (the residual is convex and increasing in
ln h), to round-off."""
from __future__ import annotations

import math

from numba import njit

from camtrain.lubrication.squeeze import SQUEEZE_COEFFICIENT


@njit(cache=True)
def film_step(h_old, F_new, speed, dt):
    """One implicit-Euler step of the level-1 film [m] (the contract of
    :func:`camtrain.lubrication.squeeze.relaxation_step`): no entrainment, no finite positive
    steady film (unloaded, non-convex or zero speed) traps the film at ``h_old``."""
    k = abs(speed) * dt / SQUEEZE_COEFFICIENT
    if k <= 1e-300 * h_old or not (0.0 < F_new < math.inf):
        return h_old
    c = h_old + k * math.log(F_new)         # h + k ln h = c
    lo, hi = math.log(h_old), math.log(F_new)
    if lo > hi:
        lo, hi = hi, lo
    y = hi                                  # Newton from the right end: monotone (convex)
    for _ in range(60):
        ey = math.exp(y)
        f = ey + k * y - c
        step = f / (ey + k)
        y_new = y - step
        if y_new < lo:
            y_new = 0.5 * (y + lo)
        if abs(y_new - y) <= 1e-15 * max(1.0, abs(y)):
            y = y_new
            break
        y = y_new
    return math.exp(y)


@njit(cache=True)
def table_coefficient(table, col, ln_w, ln_r, ln_w0, d_ln_w, ln_r0, d_ln_r):
    """Friction coefficient from ``table`` (film ratios, loads, grid angles): linear in the
    fractional grid column ``col`` (periodic), in ln W and in ln(h/F) between the levels, held
    beyond them."""
    nr, nw, grid = table.shape
    i0 = int(col)
    t = col - i0
    i0 = i0 % grid
    i1 = (i0 + 1) % grid
    x = (ln_w - ln_w0) / d_ln_w
    x = min(max(x, 0.0), nw - 1.0)
    iw = min(int(x), nw - 2) if nw > 1 else 0
    tw = x - iw if nw > 1 else 0.0
    y = (ln_r - ln_r0) / d_ln_r
    y = min(max(y, 0.0), nr - 1.0)
    ir = min(int(y), nr - 2) if nr > 1 else 0
    tr = y - ir if nr > 1 else 0.0
    iw1 = iw + 1 if nw > 1 else iw
    ir1 = ir + 1 if nr > 1 else ir
    total = 0.0
    for c, wc in ((i0, 1.0 - t), (i1, t)):
        v = ((1.0 - tr) * ((1.0 - tw) * table[ir, iw, c] + tw * table[ir, iw1, c])
             + tr * ((1.0 - tw) * table[ir1, iw, c] + tw * table[ir1, iw1, c]))
        total += wc * v
    return total
