r"""Matrix-free Newton directions of one transient EHL step (:mod:`.ehl_transient_system`).

The Jacobian of :meth:`StepSystem.jacobian` is never formed. Its product with a vector costs
one FFT deflection (:mod:`.ehl_elastic`) and a few band products, O(n log n); the Newton
system is solved by restarted GMRES with right preconditioning (:func:`gmres_right`: the true
residual is the one minimised and tested) and a multilevel preconditioner, a W-cycle over grids
each ``COARSENING`` times coarser than the last:

1. **coarse correction**: the same step on a grid ``COARSENING`` times coarser (the fine
   iterate interpolated; its own row scale); the fine residual is taken back to unscaled
   Reynolds rows, interpolated, solved, and the correction interpolated back (the load row
   and H0 go through it). The coarse system is solved by its dense LU when it has at most
   ``COARSEST`` nodes, otherwise by ``COARSE_SWEEPS`` applications of the same preconditioner
   built on it (recursively: no dense factorisation grows with n; a fixed number of
   applications, not an inner iteration to a tolerance, so the preconditioner stays a fixed
   linear map, as GMRES needs). The coarse kernel keeps the fine kernel's constant (the
   deflection is defined up to one), so that both grids see the same film at the same H0;
2. **band smoothing**: the residual left by the coarse correction is solved exactly in the
   band of this grid's Jacobian: the local Reynolds terms and the elastic influence of the
   ``BAND`` nearest nodes on each side (LAPACK banded LU, O(n BAND^2), :mod:`.ehl_band`).

The coarse grids remove the smooth, long-range (logarithmic kernel) part of the error that a
band cannot see; the band removes the oscillatory and transport (cavitated rows) part that
a coarse grid cannot resolve (a multigrid cycle after Venner & Lubrecht 2000, ch. 3, with an
exact band solve as the smoother). The cost per Newton iterate is O(n log n) times the GMRES
iterations, plus the band LUs, O(n BAND^2) over all levels, and the coarsest LU (at most
COARSEST^3 / 3 flops; at 512 and 1024 points the only coarse grid, of 128 and 256 nodes).
"""
from __future__ import annotations

import math
from dataclasses import replace
from functools import lru_cache

import numpy as np
import scipy.linalg as sla
from scipy.linalg import lapack, toeplitz

from .ehl_band import BAND, BandSolve, band_values, coarse_solve
from .ehl_elastic import ElasticKernel, influence_row

#: the coarse grid of the preconditioner has (n + COARSENING - 1) // COARSENING nodes
COARSENING = 4
#: the coarsest grid, solved by its dense LU, has at most this many nodes; finer coarse grids
#: are preconditioned by the next level in turn (no dense LU grows with n)
COARSEST = 256
#: applications of the next level's preconditioner per coarse solve (1: V-cycle, 2: W-cycle,
#: the second on the first one's residual). W: 18 % and 28 % fewer GMRES iterations than V on
#: 80 march steps at 2,048 and 4,096 points, for 0-4 % less CPU (measured; no coarse level
#: below the first at 512 and 1,024 points, where both are the same)
COARSE_SWEEPS = 2
#: GMRES: relative tolerance of the Newton direction (2-norm), restart length, restarts
RTOL, RESTART, RESTARTS = 1e-4, 30, 4
#: a kept preconditioner is rebuilt once GMRES needs more than this many iterations with it
REUSE_ITERATIONS = 12


@lru_cache(maxsize=8)
def _unit_kernel(n: int) -> tuple[ElasticKernel, np.ndarray]:
    """The kernel of n nodes at unit spacing, and the spectrum of a constant kernel (ones at
    every lag) on the same padded length: a spacing dx scales the first, and the constant the
    deflection is defined up to is the second's multiple (:func:`_coarse_kernel`)."""
    unit = ElasticKernel.of_grid(n, 1.0)
    ones = np.zeros(unit.length)
    ones[:n] = 1.0
    ones[unit.length - n + 1:] = 1.0
    return unit, np.fft.rfft(ones)


def _per_length_constant(kernel: ElasticKernel) -> float:
    """c of a kernel whose row is the exact cell integral plus c dx at every lag (the
    deflection is defined up to a constant, which H0 absorbs; a row scaled from unit spacing
    has c = -ln dx)."""
    exact = influence_row(1, kernel.dx)[0]
    return float((kernel.row[0] - exact) / kernel.dx)


def _coarse_kernel(fine: ElasticKernel, n: int, dx: float) -> tuple[ElasticKernel, float]:
    """The kernel of n nodes at spacing dx with the fine kernel's constant, so that the coarse
    film equals the fine one at the same H0 (a kernel merely scaled from unit spacing would
    add (ln dx_coarse - ln dx_fine) / 2 to H at the Hertz load: 0.69 at four times coarser,
    several times a heavy contact's film); and the row's constant shift over dx."""
    unit, ones = _unit_kernel(n)
    shift = math.log(dx) + _per_length_constant(fine)        # exact row: dx (K_1 + ln dx)
    kernel = ElasticKernel(n, dx, dx * (unit.row + shift),
                           dx * (unit.spectrum + shift * ones), unit.length)
    return kernel, shift


@lru_cache(maxsize=4)
def _unit_influence(n: int) -> np.ndarray:
    """The dense influence of n nodes at unit spacing (the coarsest grid's LU only)."""
    return -toeplitz(influence_row(n, 1.0)) / np.pi


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
        dP = f.dload * ds[1:]               # the change of the pressure that carries load
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

    def band(self, width: int) -> BandSolve:
        """The banded LU of the interior block's band of half width ``width`` (the local
        terms, and the elastic influence within the band; :mod:`.ehl_band`)."""
        value = band_values(self.sysm.kernel.row, self.t_H, self.local, self.scale[1:-1],
                            self.active, width, column=self.f.dload)
        return BandSolve(value, width)


class TwoLevel:
    """The preconditioner of the module docstring, built at one iterate."""

    def __init__(self, op: StepOperator, s: np.ndarray, H0: float, A_lag: np.ndarray):
        self.op = op
        sysm = op.sysm
        nc = (op.n + COARSENING - 1) // COARSENING
        Xc = np.linspace(sysm.X[0], sysm.X[-1], nc)
        dxc = Xc[1] - Xc[0]
        kc, shift = _coarse_kernel(sysm.kernel, nc, dxc)
        bottom = nc <= COARSEST
        influence = dxc * (_unit_influence(nc) - shift / np.pi) if bottom else None
        self.coarse = replace(sysm, X=Xc, kernel=kc, scale=None, influence=influence,
                              Q_hist=np.interp(Xc, sysm.X, sysm.Q_hist))
        sc_ = np.interp(Xc, sysm.X, s)
        sc_[[0, -1]] = s[[0, -1]]
        A_c = np.interp(Xc, sysm.X, A_lag)
        fc = self.coarse.fields(sc_, H0, A_c)
        self.lu = self.below = None
        if bottom:
            self.lu = sla.lu_factor(self.coarse.jacobian(sc_, fc), check_finite=False)
            self.scale_c = self.coarse.row_scale(fc)[1:-1]
        else:           # the next level: the same preconditioner of the coarse system
            op_c = StepOperator(self.coarse, sc_, fc)
            self.below = TwoLevel(op_c, sc_, H0, A_c)
            self.scale_c = op_c.scale[1:-1]
        self.band = op.band(BAND)

    def _coarse(self, r: np.ndarray) -> np.ndarray:
        op, c = self.op, self.coarse
        X = op.sysm.X
        g = r[:-1] / op.scale[1:-1]                      # back to unscaled Reynolds rows
        if op.active is not None:
            g = np.where(op.active, 0.0, g)
        rhs = np.concatenate((np.interp(c.X[1:-1], X[1:-1], g) * self.scale_c, [r[-1]]))
        below = self.below
        d = coarse_solve(rhs, below, below and below.op.matvec, self.lu,
                         COARSE_SWEEPS)
        z = np.interp(X[1:-1], c.X, np.concatenate(([0.0], d[:-1], [0.0])))
        return np.concatenate((z, [d[-1]]))

    def apply(self, r: np.ndarray) -> np.ndarray:
        z = self._coarse(r)
        if not self.band.ok:            # a singular band: the coarse correction alone
            return z
        left = r - self.op.matvec(z)
        z[:-1] += self.band.solve(left[:-1])
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
