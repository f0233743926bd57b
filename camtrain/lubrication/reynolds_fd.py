r"""Finite-volume averaged Reynolds solver with Reynolds cavitation as a complementarity problem.

The same equation as :mod:`.reynolds`, discretised by finite volumes on the caller's nodes
(second order: central fluxes, node-centred control volumes):

.. math:: -\frac{d}{dx}\Big(k\frac{dp}{dx}\Big) + \frac{dS}{dx} + \phi_c\partial_t h = 0,\qquad
          k = \frac{\phi_x h^3}{12\eta},\; S = u_e\bar h_T + \tfrac{u_s}{2}\sigma\Phi_s

with p = 0 at both edges. Reynolds (Swift-Stieber) cavitation is the linear complementarity
problem p >= 0, A p - b >= 0, p (A p - b) = 0 (Christopherson's projected form), whose 1-D
solution has p = dp/dx = 0 at every boundary of a cavitated region, however many there are. It is
solved by a primal-dual active-set iteration (finite for this tridiagonal M-matrix) started from
the positive part of the unconstrained solution; each pass is one tridiagonal solve (LAPACK
``gtsv``). ``half_sommerfeld`` is the plain solve with negative pressures dropped.

Used where the semi-analytic solver's single-zone assumption fails (a film that cannot build
pressure at its inlet, or one that would re-pressurise downstream of its rupture, e.g. edges
opening faster than the centre approaches near a reversal) and as the independent cross-check
of the semi-analytic pressures.
"""
from __future__ import annotations

import numpy as np
from scipy.linalg.lapack import dgtsv

from .flow_factors import contact_factor, mean_gap, pressure_flow_factor, shear_flow_factor
from .pressure_solution import CAVITATION_MODELS, PressureSolution

__all__ = ["fd_reynolds_pressure"]


def _system(x, h, u_e, dhdt, eta, sigma, u_s, shear_weight, flow_factors):
    """Interior tridiagonal system (sub, diag, sup, rhs) for the nodes 1..n-2 (p = 0 at ends)."""
    if flow_factors and sigma > 0.0:
        H = h / sigma
        phi_x, phi_c = pressure_flow_factor(H), contact_factor(H)
        S = u_e * sigma * mean_gap(H)
        if u_s:
            S = S + 0.5 * u_s * sigma * shear_weight * shear_flow_factor(H)
    else:
        phi_x, phi_c, S = 1.0, 1.0, u_e * h
    k = phi_x * h**3 / (12.0 * eta)
    dx = np.diff(x)
    kf = 0.5 * (k[1:] + k[:-1]) / dx                     # face conductances
    Sf = 0.5 * (S[1:] + S[:-1])                          # face convective fluxes
    vol = 0.5 * (x[2:] - x[:-2])
    src = (phi_c * np.broadcast_to(dhdt, x.shape))[1:-1]
    diag = kf[:-1] + kf[1:]
    off = -kf[1:-1]
    rhs = -(Sf[1:] - Sf[:-1]) - src * vol
    return off, diag, rhs


def _solve(off, diag, rhs, free):
    """Solve with rows outside ``free`` replaced by p = 0."""
    d = np.where(free, diag, 1.0)
    up = np.where(free[:-1], off, 0.0)
    lo = np.where(free[1:], off, 0.0)
    _, _, _, p, info = dgtsv(lo, d, up, np.where(free, rhs, 0.0))
    if info != 0:
        raise ValueError(f"singular Reynolds system (LAPACK gtsv info {info})")
    return p


def fd_reynolds_pressure(x, h, u_e, dhdt, eta, sigma: float = 0.0, u_s: float = 0.0,
                         shear_weight: float = 1.0, cavitation: str = "reynolds",
                         flow_factors: bool = True, max_passes: int = 200) -> PressureSolution:
    """Pressure on the nodes x for the gap h (arguments as :func:`.reynolds_pressure`)."""
    if cavitation not in CAVITATION_MODELS:
        raise ValueError(f"cavitation {cavitation!r}: expected one of {CAVITATION_MODELS}")
    x = np.asarray(x, dtype=float)
    h = np.asarray(h, dtype=float)
    off, diag, rhs = _system(x, h, u_e, dhdt, eta, sigma, u_s, shear_weight, flow_factors)
    m = diag.size
    free = np.ones(m, bool)
    p = _solve(off, diag, rhs, free)
    if cavitation == "reynolds":
        for _ in range(max_passes):
            # multiplier A p - b (>= 0 where the film is cavitated)
            mult = diag * p - rhs
            mult[:-1] += off * p[1:]
            mult[1:] += off * p[:-1]
            new = (free & (p > 0.0)) | (~free & (mult < 0.0))
            if np.array_equal(new, free):
                break
            free = new
            p = _solve(off, diag, rhs, free)
        p = np.where(free, p, 0.0)
    p = np.concatenate(([0.0], np.maximum(p, 0.0), [0.0]))
    n = x.size
    last = np.flatnonzero(p > 0.0)
    rupture = float(x[last[-1] + 1]) if last.size and last[-1] + 1 < n - 1 else np.nan
    flooded = cavitation == "reynolds" and bool(np.isnan(rupture))
    return PressureSolution(p, _trap(p, x), rupture, flooded, np.ones(n))


def _trap(y, x) -> float:
    return float(np.dot(0.5 * (y[1:] + y[:-1]), np.diff(x)))
