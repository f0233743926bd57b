r"""Matrix-free Newton directions of one transient EHL step (:mod:`.ehl_transient_system`).

The Jacobian of :meth:`StepSystem.jacobian` is never formed. Its product with a vector costs
one FFT deflection (:mod:`.ehl_elastic`) and a few band products, O(n log n); the Newton
system is solved by restarted GMRES with right preconditioning (:func:`gmres_right`: the true
residual is the one minimised and tested) and a two-level preconditioner:

1. **coarse correction**: the dense Jacobian of the same step on a grid ``COARSENING`` times
   coarser (the fine iterate interpolated; its own row scale), factorised once per Newton
   iterate; the fine residual is taken back to unscaled Reynolds rows, interpolated, solved,
   and the correction interpolated back (the load row and H0 go through it);
2. **band smoothing**: the residual left by the coarse correction is solved exactly in the
   band of the fine Jacobian: the local Reynolds terms and the elastic influence of the
   ``BAND`` nearest nodes on each side (LAPACK banded LU, O(n BAND^2), factorised once
   per Newton iterate).

The coarse grid removes the smooth, long-range (logarithmic kernel) part of the error that a
band cannot see; the band removes the oscillatory and transport (cavitated rows) part that
the coarse grid cannot resolve (a two-grid cycle after Venner & Lubrecht 2000, ch. 3, with an
exact band solve as the smoother). The cost per Newton iterate is O(n log n) times the GMRES
iterations plus the coarse LU, (n/4)^3 / 3 flops: 1/64 of the dense fine LU.
"""
from __future__ import annotations

import math
from dataclasses import replace
from functools import lru_cache

import numpy as np
import scipy.linalg as sla
from scipy.linalg import lapack, toeplitz

from .ehl_elastic import ElasticKernel, influence_row

#: the coarse grid of the preconditioner has (n + COARSENING - 1) // COARSENING nodes
COARSENING = 4
#: elastic influence kept in the band smoother: this many nodes on each side of the diagonal
BAND = 24
#: GMRES: relative tolerance of the Newton direction (2-norm), restart length, restarts
RTOL, RESTART, RESTARTS = 1e-4, 30, 4
#: a kept preconditioner is rebuilt once GMRES needs more than this many iterations with it
REUSE_ITERATIONS = 12


@lru_cache(maxsize=8)
def _unit_kernel(n: int):
    """Kernel and dense influence of n nodes at unit spacing (a spacing dx scales both)."""
    return ElasticKernel.of_grid(n, 1.0), -toeplitz(influence_row(n, 1.0)) / np.pi


class StepOperator:
    """dF/d(s_interior, H0) of one iterate as products, and its band (module docstring)."""

    def __init__(self, sysm, s: np.ndarray, f):
        self.sysm, self.f, self.n = sysm, f, s.size
        self.scale = sysm._scale(f)
        self.local, self.t_H = sysm._bands(s, f)
        self.active = None
        if sysm.cavitation == "reynolds":      # rows on the P = 0 branch of min(P, sG)
            self.active = f.P[1:-1] <= self.scale[1:-1] * sysm.reynolds(f)[1:-1]
        # the scaled bands on the interior rows, for products with a vector padded by one
        # zero in front: row i (node i + 1) takes v[i + o] at padded index i + 2 + o
        sc = self.scale[1:-1]
        self._local = [(2 + o, sc * c[1:-1]) for o, c in self.local.items()]
        self._t_H = [(2 + o, sc * c[1:-1]) for o, c in self.t_H.items()]

    def matvec(self, v: np.ndarray) -> np.ndarray:
        f, sysm, n = self.f, self.sysm, self.n
        ds = np.zeros(n + 1)                 # [0, s_0 .. s_{n-1}] with s_0 = s_{n-1} = 0
        ds[2:-1] = v[:-1]
        dP = f.dP * ds[1:]
        dH = np.empty(n + 1)
        dH[0] = 0.0
        dH[1:] = sysm.kernel.deflection(dP) + v[-1]
        out = np.empty(n - 1)
        rows = out[:-1]
        rows[:] = 0.0
        for start, c in self._local:
            rows += c * ds[start:start + n - 2]
        for start, c in self._t_H:
            rows += c * dH[start:start + n - 2]
        if self.active is not None:
            rows[:] = np.where(self.active, v[:-1], rows)
        out[-1] = sysm.dx * (dP.sum() + f.dA @ dH[1:])
        return out

    def band(self, width: int) -> np.ndarray:
        """The interior block's band of half width ``width`` in LAPACK storage: ab[width + i
        - j, j] = J[i, j] (local terms, and the elastic influence within the band)."""
        m, n = width, self.n - 2
        offsets = sorted(self.t_H)
        kr = self.sysm.kernel.row * (-1.0 / np.pi)
        d = np.arange(-m, m + 1)
        weights = kr[np.abs(np.subtract.outer(offsets, d)).T]        # (2m + 1, offsets)
        value = weights @ np.array([self.t_H[o][1:-1] for o in offsets])   # [d, i]
        cols = np.arange(1, self.n - 1)[None, :] + d[:, None]        # node of column i + d
        value *= self.f.dP[np.clip(cols, 0, self.n - 1)]
        for o, c in self.local.items():
            value[o + m] += c[1:-1]
        value *= self.scale[1:-1]
        if self.active is not None:
            value[:, self.active] = 0.0
            value[m, self.active] = 1.0
        ab = np.zeros((2 * m + 1, n))
        to, at = _band_storage(m, n)        # row i, column i + d[k]: ab[m - d[k], i + d[k]]
        ab[to] = value[at]
        return ab


@lru_cache(maxsize=8)
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


class TwoLevel:
    """The preconditioner of the module docstring, built at one iterate."""

    def __init__(self, op: StepOperator, s: np.ndarray, H0: float, A_lag: np.ndarray):
        self.op = op
        sysm = op.sysm
        nc = (op.n + COARSENING - 1) // COARSENING
        Xc = np.linspace(sysm.X[0], sysm.X[-1], nc)
        unit, dense1 = _unit_kernel(nc)
        dxc = Xc[1] - Xc[0]
        kc = ElasticKernel(nc, dxc, dxc * unit.row, dxc * unit.spectrum, unit.length)
        self.coarse = replace(sysm, X=Xc, kernel=kc, influence=dxc * dense1,
                              Q_hist=np.interp(Xc, sysm.X, sysm.Q_hist), scale=None)
        sc_ = np.interp(Xc, sysm.X, s)
        sc_[[0, -1]] = s[[0, -1]]
        fc = self.coarse.fields(sc_, H0, np.interp(Xc, sysm.X, A_lag))
        self.lu = sla.lu_factor(self.coarse.jacobian(sc_, fc), check_finite=False)
        self.scale_c = self.coarse.row_scale(fc)[1:-1]
        stored = np.vstack((np.zeros((BAND, op.n - 2)), op.band(BAND)))   # room for the fill
        self.band_lu, self.pivots, info = lapack.dgbtrf(stored, BAND, BAND)
        if info != 0 or not np.all(np.isfinite(self.band_lu)):
            self.band_lu = None          # a singular band: the coarse correction alone

    def _coarse(self, r: np.ndarray) -> np.ndarray:
        op, c = self.op, self.coarse
        X = op.sysm.X
        g = r[:-1] / op.scale[1:-1]                      # back to unscaled Reynolds rows
        if op.active is not None:
            g = np.where(op.active, 0.0, g)
        rhs = np.concatenate((np.interp(c.X[1:-1], X[1:-1], g) * self.scale_c, [r[-1]]))
        d = lapack.dgetrs(*self.lu, rhs)[0]     # sla.lu_solve without its wrappers' checks
        z = np.interp(X[1:-1], c.X, np.concatenate(([0.0], d[:-1], [0.0])))
        return np.concatenate((z, [d[-1]]))

    def apply(self, r: np.ndarray) -> np.ndarray:
        z = self._coarse(r)
        if self.band_lu is None:
            return z
        left = r - self.op.matvec(z)
        z[:-1] += lapack.dgbtrs(self.band_lu, BAND, BAND, left[:-1], self.pivots)[0]
        return z


def krylov_direction(sysm, s: np.ndarray, H0: float, f, F: np.ndarray, A_lag: np.ndarray,
                     kept: TwoLevel | None = None):
    """(Newton direction in (s_interior, H0), GMRES iterations, the preconditioner, whether
    GMRES reached ``RTOL``) at the iterate (s, H0) with fields f and residual F, without
    forming the Jacobian. ``kept``: a preconditioner built at an earlier iterate on the same
    grid, used as it is (the products are always the current Jacobian's), for at most
    ``REUSE_ITERATIONS`` GMRES iterations."""
    op = StepOperator(sysm, s, f)
    if kept is None:
        pre = TwoLevel(op, s, H0, A_lag)
    else:
        pre = kept
        pre.op = op
    restart, restarts = (RESTART, RESTARTS) if kept is None else (REUSE_ITERATIONS, 1)
    step, iterations, converged = gmres_right(op.matvec, pre.apply, -F, RTOL, restart, restarts)
    return step, iterations, pre, converged


def _rotate(H: np.ndarray, cs: np.ndarray, sn: np.ndarray, g: np.ndarray, k: int) -> None:
    """Bring column k of the Hessenberg matrix H to triangular form: the earlier Givens
    rotations, then a new one (cs[k], sn[k]) applied to it and to the right-hand side g."""
    for i in range(k):
        a, c = H[i, k], H[i + 1, k]
        H[i, k], H[i + 1, k] = cs[i] * a + sn[i] * c, cs[i] * c - sn[i] * a
    d = math.hypot(H[k, k], H[k + 1, k])
    cs[k], sn[k] = (H[k, k] / d, H[k + 1, k] / d) if d > 0.0 else (1.0, 0.0)
    H[k, k], H[k + 1, k] = d, 0.0
    g[k + 1], g[k] = -sn[k] * g[k], cs[k] * g[k]


def gmres_right(matvec, precond, b: np.ndarray, rtol: float, restart: int, restarts: int):
    """Restarted GMRES with right preconditioning (Saad & Schultz 1986; Saad 2003, *Iterative
    Methods for Sparse Linear Systems*, alg. 9.5): x in the span of the preconditioned Krylov
    vectors minimising the true residual |b - A x|_2, classical Gram-Schmidt applied twice,
    Givens rotations. Returns (x, iterations, whether |b - A x| <= rtol |b|)."""
    x = np.zeros_like(b)
    target = rtol * float(np.linalg.norm(b))
    r, total = b, 0
    beta = float(np.linalg.norm(r))
    for _ in range(restarts):
        if beta <= target:
            return x, total, True
        V, Z = np.zeros((restart + 1, b.size)), np.zeros((restart, b.size))
        H, g = np.zeros((restart + 1, restart)), np.zeros(restart + 1)
        cs, sn = np.zeros(restart), np.zeros(restart)
        V[0], g[0] = r / beta, beta
        k = 0
        while k < restart:
            Z[k] = precond(V[k])
            w = matvec(Z[k])
            h = V[:k + 1] @ w
            w = w - h @ V[:k + 1]
            again = V[:k + 1] @ w
            w = w - again @ V[:k + 1]
            H[:k + 1, k], H[k + 1, k] = h + again, np.linalg.norm(w)
            if H[k + 1, k] > 0.0:
                V[k + 1] = w / H[k + 1, k]
            breakdown = H[k + 1, k] == 0.0
            _rotate(H, cs, sn, g, k)
            k += 1
            total += 1
            if abs(g[k]) <= target or breakdown:
                break
        # the upper triangle as sla.solve_triangular solves it, without its wrappers' checks
        y, info = lapack.dtrtrs(H[:k, :k].T, g[:k], lower=1, trans=1)
        if info > 0:
            raise np.linalg.LinAlgError(f"singular Hessenberg matrix: zero diagonal {info}")
        x = x + y @ Z[:k]
        r = b - matvec(x)
        beta = float(np.linalg.norm(r))
    return x, total, beta <= target
