"""Tables of the monolithic march (:mod:`camtrain.coupled.march`): the friction
coefficient's load levels, how the march reads them, and the grid's angle frames."""
from __future__ import annotations

import math

import numpy as np


def periodic(values, theta_grid):
    """Periodic linear interpolant of grid values (for the ratio and friction coefficient)."""
    values = np.asarray(values, dtype=float) * np.ones_like(theta_grid)

    def at(theta):
        return np.interp(theta, theta_grid, values, period=2.0 * math.pi)

    return at


#: valve-referred load levels [N] of the friction tables (ratio 10^(1/8): the coefficient
#: between levels is linear in ln W)
FRICTION_LEVELS = np.geomspace(0.1, 1.0e5, 49)


def table_at(table, levels, w, cols):
    """The tabulated coefficient (``table`` (levels, grid)) at loads ``w`` and grid columns
    ``cols`` (same shape), linear in ln W as the kernel reads it, held beyond the levels."""
    x = np.clip(np.log(np.maximum(w, levels[0]) / levels[0]) / math.log(levels[1] / levels[0]),
                0.0, levels.size - 1.0)
    i = np.minimum(x.astype(int), levels.size - 2)
    t = x - i
    return (1.0 - t) * table[i, cols] + t * table[i + 1, cols]


def own_columns(theta_grid, phases):
    """Grid column, in each lobe's own angle frame, of every grid angle of the shaft."""
    step = 2.0 * math.pi / theta_grid.size
    local = theta_grid[None, :] - np.asarray(phases, dtype=float)[:, None]
    return np.rint((local - theta_grid[0]) / step).astype(int) % theta_grid.size
