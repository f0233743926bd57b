"""The band of an EHL Jacobian and its exact solve: the smoother of the multilevel
preconditioners (:mod:`.ehl_krylov` for the steady contact, :mod:`.ehl_step_krylov` for a
transient step).

The interior rows of a line-contact Jacobian (steady or transient) are

    J[i, j] = scale_i ( local_{j-i}[i] + sum_o t_H[o][i] dH_{i+o}/dP_j ) column_j,

with ``local`` the direct Reynolds terms on the unknowns (offsets -2..1), ``t_H`` the terms on
the film, dH_k/dP_j = -(1/pi) K(|k - j|) the elastic influence (:mod:`.ehl_elastic`) and
``column`` dP/du of the unknown u (1 for the pressure itself; dP/ds of the Elrod-Adams
variable). The band keeps the elastic influence of the ``width`` nearest nodes on each side;
rows on the P = 0 branch of min(P, sG) (``active``) are unit rows. Factorised by LAPACK's
banded LU (dgbtrf, O(n width^2)), it removes the oscillatory error of the logarithmic kernel
and the transport of the cavitated rows, which a coarser grid cannot resolve (Venner &
Lubrecht 2000, ch. 3: the smoother of a two-grid cycle, here an exact band solve).
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np
from scipy.linalg import lapack

#: elastic influence kept in the band: this many nodes on each side of the diagonal
BAND = 24


def band_values(kernel_row, t_H: dict, local: dict, scale, active, width: int,
                column=None) -> np.ndarray:
    """The band as value[k, i] = J[i, i + k - width] over the interior rows i (arrays of the
    full grid in, interior rows out; ``scale``/``active`` over the interior rows)."""
    m = width
    offsets = sorted(t_H)
    kr = kernel_row * (-1.0 / np.pi)
    d = np.arange(-m, m + 1)
    weights = kr[np.abs(np.subtract.outer(offsets, d)).T]            # (2m + 1, offsets)
    value = weights @ np.array([t_H[o][1:-1] for o in offsets])      # [d, i]
    n = kernel_row.size
    if column is not None:
        cols = np.arange(1, n - 1)[None, :] + d[:, None]             # node of column i + d
        value *= column[np.clip(cols, 0, n - 1)]
    for o, c in local.items():
        value[o + m] += c[1:-1]
    value *= scale
    if active is not None:
        value[:, active] = 0.0
        value[m, active] = 1.0
    return value


def coarse_solve(rhs: np.ndarray, below, below_matvec, lu, sweeps: int) -> np.ndarray:
    """The coarse grid's correction for ``rhs``: on the coarsest grid its dense LU (``lu``,
    LAPACK's factors), otherwise the next level's preconditioner ``below`` applied ``sweeps``
    times, each on the residual the earlier ones leave (``below_matvec`` the coarse operator;
    2 sweeps: a W-cycle, Venner & Lubrecht 2000 ch. 3)."""
    if below is None:
        return lapack.dgetrs(*lu, rhs)[0]     # sla.lu_solve without its wrappers' checks
    d = below.apply(rhs)
    for _ in range(sweeps - 1):
        d += below.apply(rhs - below_matvec(d))
    return d


@lru_cache(maxsize=6)     # ~1.6 kB per point each: a few sizes only
def _band_storage(m: int, n: int):
    """Where the band's values value[k, i] (row i, column i + d[k], d = -m..m) go in LAPACK
    band storage ab[m - d[k], i + d[k]], for the columns inside the matrix: (to, at) flat
    index pairs, computed once per size (one scatter instead of a loop over diagonals)."""
    d = np.arange(-m, m + 1)[:, None]
    i = np.arange(n)[None, :]
    inside = (i + d >= 0) & (i + d < n)
    rows, cols = np.broadcast_to(m - d, inside.shape), i + d
    to = np.ravel_multi_index((rows[inside], cols[inside]), (2 * m + 1, n))
    at = np.flatnonzero(inside.ravel())
    return np.unravel_index(to, (2 * m + 1, n)), np.unravel_index(at, inside.shape)


class BandSolve:
    """The banded LU of ``band_values``' band (None-safe: a singular band solves to zero
    change, and ``ok`` says so)."""

    def __init__(self, value: np.ndarray, width: int):
        m, n = width, value.shape[1]
        stored = np.zeros((3 * m + 1, n))        # m extra rows for the LU's fill
        to, at = _band_storage(m, n)
        stored[m:][to] = value[at]
        self.width = m
        self.lu, self.pivots, info = lapack.dgbtrf(stored, m, m)
        self.ok = info == 0 and bool(np.all(np.isfinite(self.lu)))

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        return lapack.dgbtrs(self.lu, self.width, self.width, rhs, self.pivots)[0]
