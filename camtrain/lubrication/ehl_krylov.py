"""Matrix-free Newton steps of the steady EHL system on fine grids (see :mod:`.ehl_line`).

The Jacobian-vector product costs one FFT deflection and a few band products, O(n log n); the
linear system of each Newton step is solved by GMRES with a multilevel preconditioner, a
W-cycle over grids each ``COARSENING`` times coarser than the last (after Venner & Lubrecht
2000, ch. 3, with the Jacobian itself on every grid):

1. **coarse correction**: the residual, taken back to unscaled Reynolds rows, is interpolated
   to the coarser grid, where the same system linearised at the interpolated iterate is solved
   by the next level's preconditioner (``COARSE_SWEEPS`` = 2 applications, a W-cycle, the
   second on the first one's residual; a fixed number, not an inner iteration to a tolerance:
   the preconditioner stays a fixed linear map, as GMRES needs); only the coarsest grid, of at
   most ``COARSEST`` nodes, is solved by the dense LU of its Jacobian; the correction is
   interpolated back (the load row and H0 go through it);
2. **band smoothing**: the residual the coarse correction leaves is solved exactly in the band
   of this grid's Jacobian (:mod:`.ehl_band`), pressure rows on the P = 0 branch passed
   through.

No n x n matrix is formed and no dense factorisation grows with n: a preconditioner costs the
band LUs, O(n BAND^2) summed over the levels, and the coarsest LU, a fixed (COARSEST^3)/3
flops; a GMRES iteration costs FFT products on every level, the grid n/4^k visited 2^k times:
a geometric sum, O(n log n) in all.
"""
from __future__ import annotations

import numpy as np
import scipy.linalg as sla
from scipy.sparse.linalg import LinearOperator, gmres

from .ehl_band import BAND, BandSolve, band_values, coarse_solve
from .ehl_elastic import ElasticKernel
from .ehl_newton import DiscreteEHL

#: each coarser grid of the preconditioner has (n + COARSENING - 1) // COARSENING nodes
COARSENING = 4
#: the coarsest grid, solved by its dense LU, has at most this many nodes
COARSEST = 256
#: applications of the next level's preconditioner per coarse solve (1: V-cycle, 2: W-cycle,
#: the second on the residual of the first). W: 4-11 GMRES iterations per Newton step at case
#: A on 1,024-65,536 points, V: 4-20 (measured; the W-cycle's extra coarse work costs less)
COARSE_SWEEPS = 2


def _band_product(bands: dict, v: np.ndarray) -> np.ndarray:
    """sum_o bands[o][i] v[i + o] over the interior rows i = 1..n-2 (v full length)."""
    n = v.size
    out = np.zeros(n - 2)
    for o, c in bands.items():
        lo, hi = max(1, -o), min(n - 1, n - o)
        out[lo - 1:hi - 1] += c[lo:hi] * v[lo + o:hi + o]
    return out


class FineOperator:
    """J of :meth:`DiscreteEHL.system` at one iterate, as products (and its band)."""

    def __init__(self, problem: DiscreteEHL, pieces):
        self.problem = problem
        _, _, self.s, self.active, self.local, self.t_H, self.carried = pieces
        self.n = problem.X.size

    def matvec(self, v: np.ndarray) -> np.ndarray:
        full = np.zeros(self.n)
        full[1:-1] = v[:-1]
        load = full * self.carried        # the change of the pressure that carries load
        dH = self.problem.kernel.deflection(load) + v[-1]
        rows = self.s[1:-1] * (_band_product(self.local, full) + _band_product(self.t_H, dH))
        rows = np.where(self.active, v[:-1], rows)
        return np.concatenate((rows, [self.problem.dx * load.sum()]))

    def band(self, width: int) -> BandSolve:
        """The banded LU of the interior block's band of half width ``width``."""
        column = self.carried if self.problem.sommerfeld else None
        value = band_values(self.problem.kernel.row, self.t_H, self.local, self.s[1:-1],
                            self.active, width, column=column)
        return BandSolve(value, width)


def coarse_grids(problem: DiscreteEHL, coarsest: int | None = None) -> list[DiscreteEHL]:
    """The preconditioner's grids below ``problem``, fine to coarse, each ``COARSENING``
    times coarser over the same domain, down to the first of at most ``coarsest`` nodes
    (default ``COARSEST``)."""
    coarsest = COARSEST if coarsest is None else coarsest
    grids, n = [], problem.X.size
    while True:
        n = (n + COARSENING - 1) // COARSENING
        X = np.linspace(problem.X[0], problem.X[-1], n)
        kernel = ElasticKernel.of_grid(n, X[1] - X[0])
        grids.append(DiscreteEHL(X, kernel, problem.oil, problem.lam, problem.scheme,
                                 problem.cavitation))
        if n <= coarsest:
            return grids


class Multilevel:
    """The preconditioner of the module docstring on one grid at one iterate; ``coarser``:
    the grids below, fine to coarse (the last one is solved by its dense LU)."""

    def __init__(self, fine: FineOperator, coarser: list[DiscreteEHL], P: np.ndarray,
                 H0: float):
        self.fine = fine
        coarse = self.coarse = coarser[0]
        Pc = np.interp(coarse.X, fine.problem.X, P)
        Pc[[0, -1]] = 0.0
        self.below = self.lu = None
        if len(coarser) == 1:
            _, fc, Jc = coarse.system(Pc, H0)
            self.lu = sla.lu_factor(Jc, check_finite=False)
            self.scale_c = coarse.row_scale(fc)[1:-1]
        else:
            op = FineOperator(coarse, coarse.linearisation(Pc, H0))
            self.below = Multilevel(op, coarser[1:], Pc, H0)
            self.scale_c = op.s[1:-1]
        self.band = fine.band(BAND)

    def _coarse(self, r: np.ndarray) -> np.ndarray:
        f, c = self.fine, self.coarse
        Xf, Xc = f.problem.X[1:-1], c.X[1:-1]
        g = np.where(f.active, 0.0, r[:-1] / f.s[1:-1])      # back to Reynolds units
        rhs = np.concatenate((np.interp(Xc, Xf, g) * self.scale_c, [r[-1]]))
        below = self.below
        d = coarse_solve(rhs, below, below and below.fine.matvec, self.lu,
                         COARSE_SWEEPS)
        z = np.interp(Xf, c.X, np.concatenate(([0.0], d[:-1], [0.0])))
        z = np.where(f.active, r[:-1], z)
        return np.concatenate((z, [d[-1]]))

    def apply(self, r: np.ndarray) -> np.ndarray:
        z = self._coarse(r)
        if not self.band.ok:
            return z
        resid = r - self.fine.matvec(z)
        z[:-1] += self.band.solve(resid[:-1])
        return z


def krylov_step(problem: DiscreteEHL, coarser: list[DiscreteEHL], P: np.ndarray, H0: float,
                rtol: float = 1e-4, restart: int = 40):
    """(F, Newton step, GMRES iterations) at (P, H0) without forming the Jacobian;
    ``coarser``: :func:`coarse_grids` of ``problem``."""
    pieces = problem.linearisation(P, H0)
    op = FineOperator(problem, pieces)
    pre = Multilevel(op, coarser, P, H0)
    size = P.size - 1
    A = LinearOperator((size, size), matvec=op.matvec)
    M = LinearOperator((size, size), matvec=pre.apply)
    count = [0]

    def tick(_):
        count[0] += 1
    F = pieces[0]
    step, _ = gmres(A, -F, M=M, rtol=rtol, atol=0.0, restart=restart, maxiter=5,
                    callback=tick, callback_type="pr_norm")
    return F, step, count[0]
