"""Compiled look-ups in tables the physics kernels build once (the roller's traction and pin
torque against sliding speed, by angle or load level)."""
from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, inline="always")
def held_linear(grid, values, x):
    """Linear interpolation of ``values`` on the increasing ``grid`` at x, held at the ends."""
    n = grid.size
    if x <= grid[0]:
        return values[0]
    if x >= grid[n - 1]:
        return values[n - 1]
    k = np.searchsorted(grid, x) - 1
    t = (x - grid[k]) / (grid[k + 1] - grid[k])
    return (1.0 - t) * values[k] + t * values[k + 1]


__all__ = ["held_linear"]
