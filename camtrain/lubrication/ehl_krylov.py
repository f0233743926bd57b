"""Matrix-free Newton steps of the steady EHL system on fine grids (see :mod:`.ehl_line`).

The Jacobian-vector product costs one FFT deflection and a few band products, O(n log n); the
linear system of each Newton step is solved by GMRES, preconditioned by the dense LU of the same
system on a coarse grid (interpolated correction; pressure rows on the P = 0 branch passed
through) followed by one damped Jacobi sweep on the fine grid. No n x n matrix is formed.
"""
from __future__ import annotations

import numpy as np
import scipy.linalg as sla
from scipy.sparse.linalg import LinearOperator, gmres

from .ehl_newton import DiscreteEHL


def _band_product(bands: dict, v: np.ndarray) -> np.ndarray:
    """sum_o bands[o][i] v[i + o] over the interior rows i = 1..n-2 (v full length)."""
    n = v.size
    out = np.zeros(n - 2)
    for o, c in bands.items():
        lo, hi = max(1, -o), min(n - 1, n - o)
        out[lo - 1:hi - 1] += c[lo:hi] * v[lo + o:hi + o]
    return out


class FineOperator:
    """J of :meth:`DiscreteEHL.system` at one iterate, as products (and its diagonal)."""

    def __init__(self, problem: DiscreteEHL, pieces):
        self.problem = problem
        _, _, self.s, self.active, self.local, self.t_H = pieces
        self.n = problem.X.size
        row = problem.kernel.row
        diag = self.local[0] + sum(t * (-row[abs(o)] / np.pi) for o, t in self.t_H.items())
        d = self.s * diag
        self.diagonal = np.where(self.active, 1.0, d[1:-1])

    def matvec(self, v: np.ndarray) -> np.ndarray:
        full = np.zeros(self.n)
        full[1:-1] = v[:-1]
        dH = self.problem.kernel.deflection(full) + v[-1]
        rows = self.s[1:-1] * (_band_product(self.local, full) + _band_product(self.t_H, dH))
        rows = np.where(self.active, v[:-1], rows)
        return np.concatenate((rows, [self.problem.dx * v[:-1].sum()]))


class CoarseCorrection:
    """Preconditioner: coarse-grid LU correction, then one Jacobi sweep (weight 2/3)."""

    def __init__(self, fine: FineOperator, coarse: DiscreteEHL, P: np.ndarray, H0: float):
        self.fine, self.coarse = fine, coarse
        Xf, Xc = fine.problem.X, coarse.X
        Pc = np.interp(Xc, Xf, P)
        Pc[[0, -1]] = 0.0
        _, fc, Jc = coarse.system(Pc, H0)
        self.lu = sla.lu_factor(Jc, check_finite=False)
        self.scale_c = coarse.row_scale(fc)[1:-1]

    def _coarse(self, r: np.ndarray) -> np.ndarray:
        f, c = self.fine, self.coarse
        Xf, Xc = f.problem.X[1:-1], c.X[1:-1]
        g = np.where(f.active, 0.0, r[:-1] / f.s[1:-1])      # back to Reynolds units
        rhs = np.concatenate((np.interp(Xc, Xf, g) * self.scale_c, [r[-1]]))
        d = sla.lu_solve(self.lu, rhs, check_finite=False)
        z = np.interp(Xf, c.X, np.concatenate(([0.0], d[:-1], [0.0])))
        z = np.where(f.active, r[:-1], z)
        return np.concatenate((z, [d[-1]]))

    def apply(self, r: np.ndarray) -> np.ndarray:
        z = self._coarse(r)
        resid = r - self.fine.matvec(z)
        z[:-1] += (2.0 / 3.0) * resid[:-1] / self.fine.diagonal
        return z


def krylov_step(problem: DiscreteEHL, coarse: DiscreteEHL, P: np.ndarray, H0: float,
                rtol: float = 1e-4, restart: int = 40):
    """(F, Newton step, GMRES iterations) at (P, H0) without forming the Jacobian."""
    pieces = problem.linearisation(P, H0)
    op = FineOperator(problem, pieces)
    pre = CoarseCorrection(op, coarse, P, H0)
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
