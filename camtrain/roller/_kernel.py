"""Compiled periodic march of the roller's speed (numba, cached on disk).

J dw/dt = r F_t(u_s) - T_pin(w), u_s = V_s0 - r w, marched by implicit (backward) Euler in time
on the cycle grid subdivided ``substeps`` times, each step's w solved by bisection (the residual
is increasing in w: traction falls and pin torque rises with w). Traction and pin torque come
from per-angle tables on one clustered normalised grid (fine near zero sliding and zero speed),
linear in between and held at the table ends (the traction saturates there at mu_b W or the
limiting shear); between grid angles both tables are blended linearly. Revolutions are repeated
until the speed at the start of a revolution changes by less than ``tolerance`` x the largest
rolling speed. The records are named tuples (docs/architecture.md, "Compiled kernels take typed
records").
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from camtrain.numerics.compile_notice import announce
from camtrain.numerics.tables import held_linear

BISECTIONS = 60


class Tables(NamedTuple):
    """Per-angle tables: ``grid`` normalised abscissae in [-1, 1]; ``traction`` [N] at sliding
    speeds ``sliding_scale[i] * grid``; ``pin`` [N m] at roller speeds ``speed_scale * grid``;
    ``v_s0`` the non-rotating sliding speed [m/s] per angle."""

    grid: np.ndarray
    traction: np.ndarray
    sliding_scale: np.ndarray
    pin: np.ndarray
    speed_scale: float
    v_s0: np.ndarray


class Scheme(NamedTuple):
    """Roller radius [m], inertia [kg m^2], grid time step [s], substeps per grid step, periodic
    tolerance [-] (relative to ``speed_ref`` [rad/s]) and most revolutions."""

    radius: float
    inertia: float
    dt: float
    substeps: int
    tolerance: float
    revolutions: int
    speed_ref: float


@njit(cache=True, inline="always")
def _blend(grid, row_i, row_j, t, x_i, x_j):
    """(1 - t) row_i(x_i) + t row_j(x_j), each row interpolated on ``grid``."""
    return (1.0 - t) * held_linear(grid, row_i, x_i) + t * held_linear(grid, row_j, x_j)


@njit(cache=True, inline="always")
def _step(tab, sch, i, j, t, w0):
    """w at the end of one implicit step (bisection on the increasing residual
    J (w1 - w0)/h - r F_t + T_pin at the blend t between grid angles i and j). The rows and
    scales of the two angles are read once per step, not once per bisection."""
    v0 = (1.0 - t) * tab.v_s0[i] + t * tab.v_s0[j]
    ws = v0 / sch.radius
    lo = min(w0, 0.0, ws) - 1e-9 * sch.speed_ref
    hi = max(w0, 0.0, ws) + 1e-9 * sch.speed_ref
    grid, trac_i, trac_j = tab.grid, tab.traction[i], tab.traction[j]
    pin_i, pin_j = tab.pin[i], tab.pin[j]
    scale_i, scale_j, speed_scale = tab.sliding_scale[i], tab.sliding_scale[j], tab.speed_scale
    radius, inertia, h = sch.radius, sch.inertia, sch.dt / sch.substeps
    for _ in range(BISECTIONS):
        mid = 0.5 * (lo + hi)
        u = v0 - radius * mid
        f = _blend(grid, trac_i, trac_j, t, u / scale_i, u / scale_j)
        x = mid / speed_scale
        tp = _blend(grid, pin_i, pin_j, t, x, x)
        if inertia * (mid - w0) / h - radius * f + tp > 0.0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


@njit(cache=True)
def march(tab, sch, w_start):
    """Speeds at the grid angles over the periodic revolution, revolutions marched and the last
    change of the start speed (relative)."""
    n = tab.v_s0.size
    out = np.empty(n)
    w = w_start
    change = np.inf
    revs = 0
    for rev in range(sch.revolutions):
        start = w
        for i in range(n):
            j = (i + 1) % n
            for s in range(sch.substeps):
                w = _step(tab, sch, i, j, (s + 1.0) / sch.substeps, w)
            out[j] = w
        revs = rev + 1
        change = abs(w - start) / sch.speed_ref
        if change <= sch.tolerance:
            break
    return out, revs, change


announce("roller", (march,))
