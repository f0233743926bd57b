"""The discrete steady line-contact EHL system and its exact Jacobian (see :mod:`.ehl_line`).

Unknowns: the interior pressures P_1..P_{n-2} (P_0 = P_{n-1} = 0) and the rigid approach H0.
Rows: min(P_i, s_i G_i) = 0 (Reynolds with the Reynolds exit condition, s_i > 0 a row scale
that leaves the solution unchanged) and the load balance dX sum P - pi/2 = 0.

``half_sommerfeld`` (Hamrock, Schmid & Jacobson 2004, *Fundamentals of Fluid Film
Lubrication*, 2nd ed., ch. 8, the half-Sommerfeld condition; Dowson & Higginson 1977, ch. 5):
the rows are the full-film s_i G_i = 0 with P unconstrained (the full Sommerfeld solution,
negative where the gap diverges), and the load balance and the elastic deflection take
max(P, 0): the negative pressures are dropped, not solved away. The oil's laws see max(P, 0)
(:mod:`.ehl_oil`: eta0 and rho0 at P <= 0), so their slopes vanish there.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .ehl_elastic import ElasticKernel
from .ehl_oil import ScaledOil

#: Upwind weights of the wedge term d(rho H)/dX on offsets (0, -1, -2), times 1/dX.
WEDGE = {"upwind1": (1.0, -1.0, 0.0), "upwind2": (1.5, -2.0, 0.5)}


def flow_bands(dP: np.ndarray, n: int, dx2: float) -> dict[int, np.ndarray]:
    """Derivative of the central-difference Poiseuille term d/dx(eps dP/dx) at node i with
    respect to eps_{i+o}, o = 1, 0, -1 (-2: none), each an array over i (the end nodes 0):
    the Jacobian bands the steady and the transient line contact share."""
    zero = np.zeros(n)
    bands = {1: zero.copy(), 0: zero.copy(), -1: zero.copy(), -2: zero}
    bands[1][1:-1] = -dP[1:] / (2 * dx2)
    bands[0][1:-1] = -(dP[1:] - dP[:-1]) / (2 * dx2)
    bands[-1][1:-1] = dP[:-1] / (2 * dx2)
    return bands


@dataclass
class Fields:
    """Film and oil at the nodes for one iterate."""

    H: np.ndarray
    rho: np.ndarray
    drho: np.ndarray
    dlog_eta: np.ndarray
    eps: np.ndarray


@dataclass
class DiscreteEHL:
    """The grid, the deflection operator, the scaled oil and lambda of one contact."""

    X: np.ndarray
    kernel: ElasticKernel
    oil: ScaledOil
    lam: float
    scheme: str
    cavitation: str = "reynolds"

    @property
    def sommerfeld(self) -> bool:
        """True for ``half_sommerfeld``: P unconstrained, its positive part carries the load."""
        return self.cavitation == "half_sommerfeld"

    def carried(self, P: np.ndarray) -> np.ndarray:
        """The pressure that carries load and deflects the surfaces: max(P, 0)."""
        return np.maximum(P, 0.0)

    def carried_slope(self, P: np.ndarray) -> np.ndarray:
        """d carried / dP: 1 where P > 0, 0 where the negative pressure is dropped."""
        return (P > 0.0).astype(float) if self.sommerfeld else np.ones_like(P)

    @cached_property
    def influence(self) -> np.ndarray:
        """The dense dV/dP, built once per grid."""
        return self.kernel.dense()

    @property
    def dx(self) -> float:
        return self.kernel.dx

    def fields(self, P: np.ndarray, H0: float) -> Fields:
        H = H0 + 0.5 * self.X**2 + self.kernel.deflection(self.carried(P))
        log_eta, dlog_eta = self.oil.log_viscosity(P)
        rho, drho = self.oil.density(P)
        if self.sommerfeld:             # the laws are held at their P = 0 values below it
            dlog_eta, drho = dlog_eta * (P >= 0.0), drho * (P >= 0.0)
        eps = rho * np.maximum(H, 0.0) ** 3 * np.exp(-log_eta) / self.lam
        return Fields(H, rho, drho, dlog_eta, eps)

    def _wedge_weights(self, n: int) -> list[np.ndarray]:
        """Per-row weights on (rho H)_{i}, _{i-1}, _{i-2}; row 1 falls back to first order."""
        weights = [np.full(n, c / self.dx) for c in WEDGE[self.scheme]]
        first = WEDGE["upwind1"]
        for k in range(3):
            weights[k][:2] = first[k] / self.dx
        return weights

    def reynolds(self, P: np.ndarray, f: Fields) -> np.ndarray:
        """G_i = d(rho H)/dX - d/dX(eps dP/dX) at every node (ends set to 0)."""
        dx2 = self.dx**2
        e_half = 0.5 * (f.eps[1:] + f.eps[:-1])
        flux = e_half * np.diff(P) / dx2
        G = np.zeros_like(P)
        rh = f.rho * f.H
        w0, w1, w2 = self._wedge_weights(P.size)
        G[1:-1] = w0[1:-1] * rh[1:-1] + w1[1:-1] * rh[:-2] - (flux[1:] - flux[:-1])
        G[2:-1] += w2[2:-1] * rh[:-3]
        return G

    def row_scale(self, f: Fields) -> np.ndarray:
        """s_i = 1 / (the size of dG_i/dP_i): makes min(P, s G) well balanced."""
        e_half = 0.5 * (f.eps[1:] + f.eps[:-1])
        diag = np.full(f.eps.size, 1.0 / self.dx)
        diag[1:-1] += (e_half[1:] + e_half[:-1]) / self.dx**2
        return 1.0 / diag

    def system(self, P: np.ndarray, H0: float, jacobian: bool = True):
        """F (interior rows, then the load row), and its Jacobian in (P_interior, H0)."""
        f = self.fields(P, H0)
        G = self.reynolds(P, f)
        s = self.row_scale(f)
        F, active = self._rows(P, s * G)
        if not jacobian:
            return F, f
        local, t_H = self._reynolds_bands(P, f)
        return F, f, self._assemble(s, active, local, t_H, self.carried_slope(P))

    def _rows(self, P: np.ndarray, sG: np.ndarray):
        """(F, active): the interior rows min(P, sG) (``reynolds``; active where the min is on
        P, the cavitated nodes) or sG (``half_sommerfeld``; none active), then the load row."""
        if self.sommerfeld:
            active = np.zeros(P.size - 2, dtype=bool)
        else:
            active = P[1:-1] <= sG[1:-1]
        load = self.dx * self.carried(P).sum() - 0.5 * np.pi
        return np.concatenate((np.where(active, P[1:-1], sG[1:-1]), [load])), active

    def linearisation(self, P: np.ndarray, H0: float):
        """F, the fields and the Jacobian's pieces without the dense matrix: (F, f, s, active,
        local, t_H, carried) for matrix-free products (:mod:`.ehl_krylov`; ``carried`` = d
        max(P, 0)/dP, the columns of the deflection and of the load row)."""
        f = self.fields(P, H0)
        s = self.row_scale(f)
        F, active = self._rows(P, s * self.reynolds(P, f))
        local, t_H = self._reynolds_bands(P, f)
        return F, f, s, active, local, t_H, self.carried_slope(P)

    def _assemble(self, s, active, local, t_H, carried) -> np.ndarray:
        """J in (P_1..P_{n-2}, H0): the scaled Reynolds rows s_i dG_i (band of local terms plus
        the dense elastic part sum_o t_o[i] dH_{i+o}/dP, ``carried`` = d max(P, 0)/dP on its
        columns), unit rows where the min is on P, and the load row."""
        n = s.size
        J = np.zeros((n - 1, n - 1))
        D = J[:-1, :-1]                          # rows and columns 1..n-2
        buf = np.empty_like(D)
        Kd = self.influence
        if self.sommerfeld:
            Kd = Kd * carried[None, :]
        for o, t in t_H.items():
            lo = max(1, -o)
            rows = slice(lo - 1, n - 2)
            np.multiply((s * t)[lo:n - 1, None], Kd[lo + o:n - 1 + o, 1:n - 1], out=buf[rows])
            D[rows] += buf[rows]
            J[rows, -1] += (s * t)[lo:n - 1]
        for o, c in local.items():
            i = np.arange(max(1, 1 - o), min(n - 1, n - 1 - o))
            D[i - 1, i + o - 1] += s[i] * c[i]
        idx = np.flatnonzero(active)
        J[idx, :] = 0.0
        J[idx, idx] = 1.0
        J[-1, :-1] = self.dx * carried[1:-1]
        return J

    def _reynolds_bands(self, P: np.ndarray, f: Fields):
        """Coefficients of dG_i: on P_{i+o} directly (local, o = -2..1) and on H_{i+o} (t_H),
        each an array over i."""
        n, dx2 = P.size, self.dx**2
        e_half = 0.5 * (f.eps[1:] + f.eps[:-1])
        dP = np.diff(P)
        zero = np.zeros(n)
        c_eps = flow_bands(dP, n, dx2)
        w0, w1, w2 = self._wedge_weights(n)
        c_rh = {0: w0, -1: w1, -2: w2, 1: zero}
        c_rh[-2][:2] = 0.0
        deps_dH = 3.0 * f.eps / np.where(f.H > 0, f.H, np.inf)
        deps_dP = f.eps * (f.drho / f.rho - f.dlog_eta)
        drh_dH, drh_dP = f.rho, f.drho * f.H
        local, t_H = {}, {}
        for o in (-2, -1, 0, 1):
            shifted = slice(max(0, o), n + min(0, o))     # the i + o of i in ``rows``
            rows = slice(max(0, -o), n - max(0, o))
            t, c = np.zeros(n), np.zeros(n)
            t[rows] = c_eps[o][rows] * deps_dH[shifted] + c_rh[o][rows] * drh_dH[shifted]
            c[rows] = c_eps[o][rows] * deps_dP[shifted] + c_rh[o][rows] * drh_dP[shifted]
            t_H[o], local[o] = t, c
        local[1][1:-1] -= e_half[1:] / dx2           # direct Poiseuille terms on P
        local[-1][1:-1] -= e_half[:-1] / dx2
        local[0][1:-1] += (e_half[1:] + e_half[:-1]) / dx2
        return local, t_H
