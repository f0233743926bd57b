"""Finite-length Reynolds equation over the unwrapped journal bearing (finite volumes).

Dimensionless form (isoviscous, incompressible, aligned journal). Angle ``theta`` is measured
from the thickest film in the sense of rotation, ``Z = z/R`` from the mid-plane, the film is
``H = h/c = 1 + eps cos(theta)`` and the pressure ``P = p c^2 / (12 eta R^2 omega_ref)``:

    -div(H^3 grad P) + Lambda d(theta_f H)/d theta + d(theta_f H)/d tau = 0,  tau = omega_ref t

(Reynolds 1886; Dowson & Taylor 1979 for the JFO form). ``theta_f`` is the film fraction (1 in
the full film). For a squeezing journal whose centre moves with velocity ``w`` (clearance units,
seen from the frame turning at wbar = (omega_j + omega_b)/2) the Couette and squeeze terms of
the full film combine into one source, ``dH/dtau + Lambda dH/dtheta = w_r cos(theta) + w_t
sin(theta)`` with ``w_r`` along the line of centres and ``w_t`` 90 deg ahead of it; pure
rotation at wbar is ``w = (0, -eps)`` (Booker 1965: the film only sees ``w``).

Discretisation: vertex-centred finite volumes on a uniform periodic grid in theta and a uniform
grid in Z over one half of the bearing (mirror symmetry about the mid-plane: zero flux there);
``H^3`` at the faces from the exact film; source terms integrated exactly over each volume, so
the discrete scheme is second order and discretely conservative. Boundaries: ``P = 0`` at the
bearing end; an optional axial feed groove (nodes held at the supply pressure, full film).

Cavitation conditions (a named option, see ``CAVITATION``):

* ``"half_sommerfeld"``: the full-film (Sommerfeld) solution with negative pressures set to
  zero (Guembel): the condition of Ocvirk's short bearing.
* ``"reynolds"``: the Swift-Stieber condition as a linear complementarity problem,
  ``P >= 0``, ``A P - f >= 0``, ``P (A P - f) = 0``; solved exactly by a primal-dual active set
  (finite, monotone for the M-matrix of this scheme). The condition of Raimondi & Boyd (1958).
* ``"jfo"``: mass-conserving Jakobsson-Floberg-Olsson cavitation in the complementarity form of
  Giacopini et al. (2010): ``P >= 0``, ``r = 1 - theta_f >= 0``, ``P r = 0``, Couette flux
  upwinded in ``theta_f``; solved by a semismooth Newton method on the Fischer-Burmeister
  function with a line search (Woloszynski et al. 2015). Needs a feed (groove) for steady
  operation.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from camtrain.errors import ConvergenceError, field_error

__all__ = ["CAVITATION", "FilmGrid", "FilmField", "solve_film"]

CAVITATION = ("half_sommerfeld", "reynolds", "jfo")


@dataclass(frozen=True)
class FilmGrid:
    """Uniform vertex grid on the unwrapped half bearing.

    Attributes:
        half_length: L/D = b/(2R), the Z extent from the mid-plane to the end [-].
        n_theta: nodes around the circumference (periodic).
        n_z: intervals from the mid-plane to the end (n_z + 1 node rows; the last is P = 0).
    """

    half_length: float
    n_theta: int = 120
    n_z: int = 12

    def __post_init__(self):
        if not (self.half_length > 0 and math.isfinite(self.half_length)):
            raise field_error("b_over_d", "must be a finite number > 0", self.half_length)
        if int(self.n_theta) < 16 or int(self.n_z) < 2:
            raise field_error("mesh", "too coarse", (self.n_theta, self.n_z),
                              "n_theta >= 16 and n_z >= 2")

    @property
    def d_theta(self) -> float:
        return 2.0 * math.pi / self.n_theta

    @property
    def d_z(self) -> float:
        return self.half_length / self.n_z

    @property
    def theta(self) -> np.ndarray:
        return np.arange(self.n_theta) * self.d_theta

    @property
    def z(self) -> np.ndarray:
        return np.arange(self.n_z + 1) * self.d_z

    @property
    def z_weight(self) -> np.ndarray:
        """Axial width of each node row's volume (half at the mid-plane and at the end)."""
        w = np.full(self.n_z + 1, self.d_z)
        w[0] = w[-1] = 0.5 * self.d_z
        return w

    @property
    def z_simpson(self) -> np.ndarray:
        """Simpson weights over the node rows (n_z even; trapezoid on the last interval if
        odd): integrals of the smooth pressure in Z are then exact for the short bearing's
        parabola, so the mesh error is that of the discrete pressure alone."""
        n, h = self.n_z, self.d_z
        w = np.zeros(n + 1)
        m = n - (n % 2)
        w[0:m + 1:2] += 2.0 * h / 3.0
        w[1:m:2] += 4.0 * h / 3.0
        w[0] -= h / 3.0
        w[m] -= h / 3.0
        if n % 2:
            w[m] += 0.5 * h
            w[n] += 0.5 * h
        return w

    @property
    def size(self) -> int:
        return self.n_theta * (self.n_z + 1)


@dataclass(frozen=True)
class FilmField:
    """Dimensionless solution of one film problem (arrays shaped (n_z + 1, n_theta)).

    Forces are for the whole bearing (both halves), per unit ``12 eta R^4 omega_ref / c^2``,
    along the line of centres (``force_r``, towards the thinnest film) and 90 deg ahead of it
    (``force_t``): the load the journal puts on the film. ``reaction`` is each node's net
    outflow (zero at solved nodes up to the solver tolerance, the supply or leakage at held
    nodes, the Swift-Stieber multiplier at "reynolds" cavitated nodes) per unit
    ``c R^2 omega_ref``.
    """

    grid: FilmGrid
    eps: float
    pressure: np.ndarray
    fraction: np.ndarray
    reaction: np.ndarray
    force_r: float
    force_t: float
    cavitation: str
    iterations: int


def _film(grid: FilmGrid, eps: float):
    th = grid.theta
    h = 1.0 + eps * np.cos(th)
    hf = 1.0 + eps * np.cos(th + 0.5 * grid.d_theta)  # face j + 1/2
    return th, h, hf


def _diffusion(grid: FilmGrid, h, hf) -> sp.csr_matrix:
    """-div(H^3 grad .) integrated over every volume (symmetric, all nodes, no boundary rows)."""
    nt, nz = grid.n_theta, grid.n_z + 1
    idx = np.arange(nt * nz).reshape(nz, nt)
    zw = grid.z_weight
    # circumferential faces j -> j+1 (periodic)
    a = (hf ** 3)[None, :] * zw[:, None] / grid.d_theta
    i0, i1 = idx.ravel(), np.roll(idx, -1, axis=1).ravel()
    # axial faces k -> k+1
    c = np.broadcast_to((h ** 3 * grid.d_theta / grid.d_z)[None, :], (nz - 1, nt))
    k0, k1 = idx[:-1].ravel(), idx[1:].ravel()
    coef = np.concatenate([a.ravel(), c.ravel()])
    r0 = np.concatenate([i0, k0])
    r1 = np.concatenate([i1, k1])
    rows = np.concatenate([r0, r1, r0, r1])
    cols = np.concatenate([r0, r1, r1, r0])
    vals = np.concatenate([coef, coef, -coef, -coef])
    n = nt * nz
    return sp.csr_matrix((vals, (rows, cols)), shape=(n, n))


def _couette(grid: FilmGrid, hf, lam: float) -> sp.csr_matrix:
    """Net Couette outflow lam * [H theta_f]_faces for a unit field, upwinded in theta_f."""
    nt, nz = grid.n_theta, grid.n_z + 1
    idx = np.arange(nt * nz).reshape(nz, nt)
    zw = grid.z_weight
    q = lam * hf[None, :] * zw[:, None]  # flux factor at face j+1/2
    left, right = idx.ravel(), np.roll(idx, -1, axis=1).ravel()
    up = left if lam >= 0 else right
    qv = q.ravel()
    rows = np.concatenate([left, right])
    cols = np.concatenate([up, up])
    vals = np.concatenate([qv, -qv])
    n = nt * nz
    return sp.csr_matrix((vals, (rows, cols)), shape=(n, n))


def _source(grid: FilmGrid, w_r: float, w_t: float) -> np.ndarray:
    """Volume integral of w_r cos(theta) + w_t sin(theta) (exact in theta)."""
    th = grid.theta
    s = 2.0 * math.sin(0.5 * grid.d_theta) * (w_r * np.cos(th) + w_t * np.sin(th))
    return (grid.z_weight[:, None] * s[None, :]).ravel()


def _held(grid: FilmGrid, feed) -> np.ndarray:
    """Mask of nodes held at a given pressure: the end row and the feed groove nodes."""
    nt, nz = grid.n_theta, grid.n_z + 1
    held = np.zeros((nz, nt), dtype=bool)
    held[-1] = True
    if feed is not None:
        start, width, extent = feed
        th = grid.theta
        d = np.mod(th - start + 0.5 * grid.d_theta, 2.0 * math.pi)
        cols = d < max(width, 1e-12) + 0.5 * grid.d_theta
        if not cols.any():
            cols[int(round(start / grid.d_theta)) % nt] = True
        rows = grid.z <= extent * grid.half_length + 1e-12 * grid.half_length
        held |= rows[:, None] & cols[None, :]
    return held.ravel()


def _solve_linear(A, rhs, fixed, values):
    """Solve A x = rhs on the free nodes with x = values on the fixed ones: the fixed rows are
    replaced by identity rows in place of a copy of A's data (the pattern holds the diagonal),
    then one sparse LU with a symmetric fill-reducing order."""
    A = A.tocsr()
    rows = np.repeat(np.arange(A.shape[0]), np.diff(A.indptr))
    keep = ~fixed[rows]
    data = np.where(keep, A.data, np.where(A.indices == rows, 1.0, 0.0))
    M = sp.csc_matrix(sp.csr_matrix((data, A.indices, A.indptr), shape=A.shape))
    b = np.where(fixed, values, rhs)
    lu = spla.splu(M, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                   options={"SymmetricMode": True})
    return lu.solve(b)


def _reynolds_lcp(A, f, fixed, values, p0, max_iter):
    """Primal-dual active set for P >= 0, A P - f >= 0, P (A P - f) = 0 on the free nodes."""
    free = ~fixed
    active = (p0 <= 0.0) & free
    p = p0
    for it in range(1, max_iter + 1):
        hold = fixed | active
        x = _solve_linear(A, f, hold, np.where(fixed, values, 0.0))
        lam = A @ x - f
        new_active = free & ((active & (lam > 0.0)) | (~active & (x < 0.0)))
        # nodes that were active but whose multiplier went negative are freed
        p = x
        if np.array_equal(new_active, active):
            return np.maximum(p, 0.0), it
        active = new_active
    raise ConvergenceError(f"Reynolds cavitation: active set not settled in {max_iter} steps")


def _fb(a, b):
    """Fischer-Burmeister function and its (generalised) partial derivatives."""
    r = np.hypot(a, b)
    safe = np.where(r > 0.0, r, 1.0)
    da = np.where(r > 0.0, 1.0 - a / safe, 1.0 - 1.0 / math.sqrt(2.0))
    db = np.where(r > 0.0, 1.0 - b / safe, 1.0 - 1.0 / math.sqrt(2.0))
    return a + b - r, da, db


def _jfo_switch(A, C, f, fixed, values, p0, max_iter):
    """Elrod's switch solved as a piecewise-linear Newton method: each node carries either
    its pressure (full film, r = 0) or its void fraction r (cavitated, P = 0); a node whose
    pressure comes out negative cavitates, a cavitated node whose r comes out negative fills.
    Exact in a finite number of steps when it settles; returns None if it cycles."""
    free = ~fixed
    u = np.flatnonzero(free)
    Auu, Cuu = A[u][:, u].tocsc(), C[u][:, u].tocsc()
    rhs = f[u] - A[u][:, fixed] @ values[fixed]
    full = p0[u] > 0.0
    seen = set()
    for it in range(1, max_iter + 1):
        M = Auu @ sp.diags(full.astype(float)) - Cuu @ sp.diags((~full).astype(float))
        x = spla.splu(M.tocsc(), permc_spec="MMD_AT_PLUS_A").solve(rhs)
        new = np.where(full, x >= 0.0, x < 0.0)
        if np.array_equal(new, full):
            P = values.copy()
            P[u] = np.where(full, x, 0.0)
            R = np.zeros_like(values)
            R[u] = np.where(full, 0.0, np.clip(x, 0.0, 1.0))
            return P, R, it
        key = np.packbits(new).tobytes()
        if key in seen:
            return None
        seen.add(key)
        full = new
    return None


def _jfo(A, C, f, fixed, values, p0, tol, max_iter):
    """Semismooth Newton (Fischer-Burmeister) for A P - C r = f, P >= 0, r >= 0, P r = 0."""
    free = ~fixed
    u = np.flatnonzero(free)
    n = u.size
    scale = max(float(np.max(np.abs(p0))), 1e-300)
    diag = A.diagonal()[u]
    Auu, Cuu = A[u][:, u], C[u][:, u]
    rhs = f[u] - A[u][:, fixed] @ values[fixed]
    p = np.maximum(p0[u], 0.0) / scale
    r = np.where(p > 0.0, 0.0, 0.5)

    def resid(p, r):
        g = (scale * (Auu @ p) - Cuu @ r - rhs) / diag
        phi, dp, dr = _fb(p, r)
        return g, phi, dp, dr

    g, phi, dp, dr = resid(p, r)
    merit = 0.5 * (g @ g + phi @ phi)
    dinv = sp.diags(1.0 / diag)
    it = 0
    while math.sqrt(2.0 * merit / n) >= tol and it < max_iter:
        it += 1
        J = sp.bmat([[dinv @ (scale * Auu), -(dinv @ Cuu)], [sp.diags(dp), sp.diags(dr)]],
                    format="csc")
        step = spla.spsolve(J, -np.concatenate([g, phi]))
        sp_, sr = step[:n], step[n:]
        t = 1.0
        while True:
            g2, phi2, dp2, dr2 = resid(p + t * sp_, r + t * sr)
            m2 = 0.5 * (g2 @ g2 + phi2 @ phi2)
            if m2 <= (1.0 - 1e-4 * t) * merit or t < 1e-6:
                break
            t *= 0.5
        p, r = p + t * sp_, r + t * sr
        g, phi, dp, dr, merit = g2, phi2, dp2, dr2, m2
    if math.sqrt(2.0 * merit / n) >= tol:
        raise ConvergenceError(f"JFO cavitation: Newton not converged in {max_iter} steps "
                               f"(residual {math.sqrt(2 * merit / n):.3g})")
    P = values.copy()
    P[u] = np.maximum(scale * p, 0.0)
    R = np.zeros_like(values)
    R[u] = np.clip(r, 0.0, 1.0)
    return P, R, it


def _prolong(pc: np.ndarray, grid: FilmGrid) -> np.ndarray:
    """Coarse-mesh pressure on the fine mesh (linear, periodic in theta); the fine mesh halves
    both spacings, so coarse nodes are fine nodes."""
    rows = np.empty((pc.shape[0], grid.n_theta))
    rows[:, 0::2] = pc
    rows[:, 1::2] = 0.5 * (pc + np.roll(pc, -1, axis=1))
    out = np.empty((grid.n_z + 1, grid.n_theta))
    out[0::2] = rows
    out[1::2] = 0.5 * (rows[:-1] + rows[1:])
    return out.ravel()


def solve_film(grid: FilmGrid, eps: float, w_r: float = 0.0, w_t: float | None = None, *,
               cavitation: str = "reynolds", rotation: float = 1.0, feed=None,
               supply_pressure: float = 0.0, tol: float = 1e-10, max_iter: int = 60,
               start: np.ndarray | None = None) -> FilmField:
    """Pressure field of the finite bearing for one eccentricity and journal-centre velocity.

    Args:
        grid: the mesh (:class:`FilmGrid`).
        eps: eccentricity ratio, 0 <= eps < 1.
        w_r, w_t: journal-centre velocity along and 90 deg ahead of the line of centres, in
            clearance units per unit of ``omega_ref`` time, seen from the frame turning at wbar.
            ``w_t=None`` means pure rotation: ``w_t = -eps * rotation`` with ``w_r`` as given.
        cavitation: one of :data:`CAVITATION`.
        rotation: wbar / omega_ref (the Couette number ``Lambda``; used by "jfo" only, whose
            flux is written with the film fraction; +1 or -1 for a steady film).
        feed: ``(start, width, extent)``: an axial groove from angle ``start`` over ``width``
            [rad, from the thickest film] and from the mid-plane to ``extent`` (fraction of the
            half length; 1 = the whole length). ``None`` = no groove.
        supply_pressure: dimensionless pressure held in the groove.
        start: warm start for the pressure (same shape as the field).
    """
    if cavitation not in CAVITATION:
        raise field_error("cavitation", "unknown cavitation condition", cavitation,
                          " or ".join(CAVITATION))
    if not (0.0 <= eps < 1.0):
        raise field_error("eps", "eccentricity ratio out of range", eps, "0 <= eps < 1")
    if w_t is None:
        w_t = -eps * rotation
    if cavitation == "jfo" and feed is None:
        raise field_error("feed", "the mass-conserving (jfo) film needs an oil feed groove",
                          None, "a feed groove", "use cavitation = reynolds without a groove")
    _, h, hf = _film(grid, eps)
    A = _diffusion(grid, h, hf)
    fixed = _held(grid, feed)
    values = np.where(fixed, 0.0, 0.0)
    if feed is not None:
        values = np.where(fixed, supply_pressure, 0.0)
        end = np.zeros(grid.size, dtype=bool)
        end[-grid.n_theta:] = True
        values[end] = 0.0
    f = -_source(grid, w_r, w_t)
    iters = 1
    if cavitation == "half_sommerfeld":
        p = _solve_linear(A, f, fixed, values)
        p = np.maximum(p, 0.0)
        frac = np.ones_like(p)
    else:
        if start is not None:
            p0 = np.asarray(start, dtype=float).ravel()
        elif grid.n_theta >= 64 and grid.n_theta % 2 == 0 and grid.n_z % 2 == 0:
            # grid sequencing: the half mesh's cavity is a close first guess, so the active
            # set here settles in a few steps instead of one node column per step
            coarse = FilmGrid(grid.half_length, grid.n_theta // 2, grid.n_z // 2)
            pc = solve_film(coarse, eps, w_r, w_t, cavitation="reynolds", feed=feed,
                            supply_pressure=supply_pressure, max_iter=max_iter).pressure
            p0 = _prolong(pc, grid)
        else:
            p0 = _solve_linear(A, f, fixed, values)
        p, iters = _reynolds_lcp(A, f, fixed, values, p0, max_iter)
        frac = np.ones_like(p)
        if cavitation == "jfo":
            lam = float(rotation)
            C = _couette(grid, hf, lam)
            # squeeze/rotation beyond the Couette flux: w_r cos + (w_t + lam eps) sin
            f_rest = -_source(grid, w_r, w_t + lam * eps)
            rhs = f_rest - C @ np.ones(grid.size)
            out = _jfo_switch(A, C, rhs, fixed, values, p, max_iter)
            if out is None:  # the switch cycled: globalised semismooth Newton instead
                out = _jfo(A, C, rhs, fixed, values, p, tol, 4 * max_iter)
            p, rfrac, it2 = out
            iters += it2
            frac = 1.0 - rfrac
    if cavitation == "jfo":
        lam = float(rotation)
        reaction = A @ p + _couette(grid, hf, lam) @ frac + _source(grid, w_r, w_t + lam * eps)
    else:
        reaction = A @ p - f
    nz1, nt = grid.n_z + 1, grid.n_theta
    P = p.reshape(nz1, nt)
    th = grid.theta
    area = grid.z_simpson[:, None] * grid.d_theta
    # load on the film: W = int p (direction to the wall); factor 2 for both halves
    force_r = -2.0 * float(np.sum(P * area * np.cos(th)[None, :]))
    force_t = -2.0 * float(np.sum(P * area * np.sin(th)[None, :]))
    return FilmField(grid=grid, eps=float(eps), pressure=P, fraction=frac.reshape(nz1, nt),
                     reaction=reaction.reshape(nz1, nt), force_r=force_r, force_t=force_t,
                     cavitation=cavitation, iterations=iters)
