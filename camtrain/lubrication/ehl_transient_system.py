r"""One implicit time step of the transient line-contact EHL problem, in the step's Hertzian units.

Each step is written in the Hertz units of its own load and radius (X = x/b, P = p/p_h,
H = h R/b^2), so the load balance is integral (P + A) dX = pi/2 at every step and the film is
H = H0 + X^2/2 + V(P + A) with the deflection V of :mod:`.ehl_elastic`. The Reynolds equation
with the squeeze term (dimensional: d/dx(rho h^3/(12 eta) dp/dx) = u_m d(rho theta h)/dx +
d(rho theta h)/dt), divided by u_ref b/R with u_ref = 1 m/s, reads per node

.. math:: G = |u_m|\,\partial_X Q + c_t\,(a_0 Q - Q_{hist}) - \partial_X(\varepsilon\,\partial_X P) = 0,
          \quad Q = \bar\rho\,\theta H,\quad \varepsilon = \bar\rho H^3/(\bar\eta\lambda),
          \quad \lambda = 12\eta_0 u_{ref} R^2/(b^3 p_h),\quad c_t = b/\Delta t

(Venner & Lubrecht 2000, ch. 2 and 9, the time-dependent line contact, here in flux form).
The entrainment is made non-negative by mirroring the symmetric grid (X -> -X) when u_m < 0,
so the wedge term is always upwinded from the left (``upwind1``, or ``upwind2`` as in the
steady solver). a_0 and Q_hist are the time scheme's: backward Euler (1, Q_n), BDF2 (3/2,
2 Q_n - Q_{n-1}/2), or steady (c_t = 0).

Cavitation (``elrod_adams``, default): one unknown s per node, P = max(s, 0) and the film
fraction theta = 1 + min(s, 0) (Elrod & Adams 1974, the universal variable of Elrod 1981; as
a complementarity problem P >= 0, 1 - theta >= 0, P (1 - theta) = 0 in Giacopini et al. 2010).
The cavitated rows transport the partial film: mass is conserved through rupture and
re-formation. The kink at s = 0 is smoothed so that Newton converges where nodes cross it
(without, the iteration cycles at the rupture): P = (s + r - delta)/2, theta = 1 - (r - s -
delta)/2, r = sqrt(s^2 + delta^2), exact at s = 0 and within delta/2 of the sharp law
elsewhere; delta = 2 sqrt(tolerance) times the pressure scale (2e-3 at the default).
``reynolds``: theta = 1, and the rows are min(P, s G) = 0 (the steady solver's
Reynolds exit condition), which does not conserve mass in the cavitated zone.
``half_sommerfeld`` (Hamrock, Schmid & Jacobson 2004, *Fundamentals of Fluid Film
Lubrication*, 2nd ed., the half-Sommerfeld condition): theta = 1 and the rows are the full-film
G = 0 with s = P unconstrained; the load row and the deflection take max(P, 0) (``load`` of
:class:`StepFields`), the oil's laws see max(P, 0) (eta0, rho0 below it) and the friction counts
no shear where P < 0. Neither mass-conserving nor faithful at the outlet: a bound (docs/ehl.md).

Asperities (Greenwood & Tripp 1970-71, :mod:`.asperity`): their nominal pressure A(H) carries
load (load row, with its derivative in the Jacobian) and deforms the surfaces (in the
deflection, lagged by one Newton iterate: the step converges when A stops changing).
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .ehl_elastic import ElasticKernel
from .ehl_newton import WEDGE, flow_bands
from .ehl_oil import ScaledOil

CAVITATION = ("elrod_adams", "reynolds", "half_sommerfeld")


@dataclass
class StepFields:
    """Film, oil and the derived arrays of one iterate (all on the full grid)."""

    P: np.ndarray
    theta: np.ndarray
    dP: np.ndarray        #: dP/ds
    dtheta: np.ndarray    #: dtheta/ds
    H: np.ndarray
    rho: np.ndarray
    drho: np.ndarray
    dlog_eta: np.ndarray
    eps: np.ndarray
    Q: np.ndarray
    A: np.ndarray         #: asperity pressure from this H [-]
    dA: np.ndarray        #: dA/dH [-]
    load: np.ndarray      #: the pressure that carries load (P; half_sommerfeld: max(P, 0))
    dload: np.ndarray     #: dload/ds


@dataclass
class StepSystem:
    """The discrete equations of one step (module docstring)."""

    X: np.ndarray
    kernel: ElasticKernel
    #: dense dV/dP of this grid, or a callable building it on the first dense Jacobian (the
    #: matrix-free directions never form it: O(n^2) numbers)
    influence: object
    oil: ScaledOil
    lam: float
    speed: float              #: |u_m| [m/s]
    c_t: float                #: b / dt [m/s] (0: steady)
    a0: float
    Q_hist: np.ndarray
    scheme: str = "upwind2"
    cavitation: str = "elrod_adams"
    asperity: object = None   #: callable H -> (A, dA/dH), or None (smooth)
    scale: np.ndarray | None = None   #: row scale held fixed (None: from each iterate)
    smoothing: float = 2e-4   #: delta of the smoothed complementarity (module docstring)
    pressure_scale: float = 1.0   #: the solution's pressure scale [p_h] (tolerances)

    @property
    def dx(self) -> float:
        return self.kernel.dx

    def split(self, s: np.ndarray):
        """(P, theta, dP/ds, dtheta/ds) of s (module docstring)."""
        if self.cavitation == "reynolds":       # s is the pressure, projected on s >= 0
            return np.maximum(s, 0.0), np.ones_like(s), np.ones_like(s), np.zeros_like(s)
        if self.cavitation == "half_sommerfeld":        # s is the pressure, unconstrained
            return s.copy(), np.ones_like(s), np.ones_like(s), np.zeros_like(s)
        d = self.smoothing
        r = np.sqrt(s * s + d * d)
        return (0.5 * (s + r - d), 1.0 - 0.5 * (r - s - d), 0.5 * (1.0 + s / r),
                0.5 * (1.0 - s / r))

    def poiseuille_over_transport(self, f: StepFields) -> np.ndarray:
        """K = D / T per node (ends 0): D the Poiseuille coefficient of the row on the pressure,
        (eps_{i-1/2} + eps_{i+1/2}) / dX^2, T its transport coefficient on the film fraction,
        (|u|/dX + c_t a0) rho H. K grows as 1/dX in a thick film (8e4 at 512 points in the
        Goecmen outlet, 4e5 at 2,048)."""
        e_half = 0.5 * (f.eps[1:] + f.eps[:-1])
        K = np.zeros_like(f.eps)
        transport = (self.speed / self.dx + self.c_t * self.a0) * f.rho[1:-1] * f.H[1:-1]
        transport = np.maximum(transport, 1e-300)
        K[1:-1] = (e_half[1:] + e_half[:-1]) / self.dx**2 / transport
        return K

    def updated(self, s: np.ndarray, ds: np.ndarray, K: np.ndarray | None) -> np.ndarray:
        """s + ds, except at film-fraction nodes (s < 0) whose row the smoothed pressure leads
        (K dP/ds > dtheta/ds, with K of :meth:`poiseuille_over_transport`): there the new s
        is the one whose pressure is the linear model's, P(s) + dP/ds ds (the smoothed law
        inverted: s = (a^2 - delta^2) / 2a, a = 2P + delta), or s + ds where that pressure is
        below the law's floor -delta/2. On that branch P = delta^2/(4|s|) - delta/2 + ...:
        the row is nearly linear in P and far from linear in s, and Newton in s only doubles
        |s| per iterate toward a film-fraction node's solution (measured: 9 iterates per step
        at 4,096 points on the Goecmen flank, each halving the residual). A change of the
        variable of the update, not of the equations: the fixed point is the same."""
        s_new = s + ds
        if K is None or self.cavitation != "elrod_adams":
            return s_new
        P, _, dP, dtheta = self.split(s)
        led = (s < 0.0) & (K * dP > dtheta)
        if not led.any():
            return s_new
        d = self.smoothing
        a = 2.0 * (P + dP * ds) + d
        ok = led & (a > 0.0)
        a = np.where(ok, a, 1.0)
        return np.where(ok, (a * a - d * d) / (2.0 * a), s_new)

    def fields(self, s: np.ndarray, H0: float, A_lag: np.ndarray) -> StepFields:
        P, theta, dP, dtheta = self.split(s)
        load, dload = P, dP
        log_eta, dlog_eta = self.oil.log_viscosity(P)
        rho, drho = self.oil.density(P)
        if self.cavitation == "half_sommerfeld":      # negative pressures dropped
            kept = P > 0.0
            load, dload = np.maximum(P, 0.0), kept.astype(float)
            dlog_eta, drho = dlog_eta * (P >= 0.0), drho * (P >= 0.0)
        H = H0 + 0.5 * self.X**2 + self.kernel.deflection(load + A_lag)
        Hp = np.maximum(H, 0.0)
        eps = rho * Hp**3 * np.exp(-log_eta) / self.lam
        if self.asperity is None:
            A, dA = np.zeros_like(P), np.zeros_like(P)
        else:
            A, dA = self.asperity(H)
        return StepFields(P, theta, dP, dtheta, H, rho, drho, dlog_eta, eps, rho * theta * H,
                          A, dA, load, dload)

    def _wedge(self, n: int) -> list[np.ndarray]:
        """The wedge and time weights of Q_i, Q_{i-1}, Q_{i-2} per node: fixed for the step,
        built on the first call (read only: the callers copy before changing them)."""
        key = (n, self.speed, self.c_t, self.a0, self.dx, self.scheme)
        kept = self.__dict__.get("_wedge_kept")
        if kept is not None and kept[0] == key:
            return kept[1]
        weights = [np.full(n, self.speed * c / self.dx) for c in WEDGE[self.scheme]]
        for k, c in enumerate(WEDGE["upwind1"]):
            weights[k][:2] = self.speed * c / self.dx
        weights[0] = weights[0] + self.c_t * self.a0
        self.__dict__["_wedge_kept"] = (key, weights)
        return weights

    def reynolds(self, f: StepFields) -> np.ndarray:
        """G at every node (ends 0)."""
        e_half = 0.5 * (f.eps[1:] + f.eps[:-1])
        flux = e_half * np.diff(f.P) / self.dx**2
        w0, w1, w2 = self._wedge(f.P.size)
        G = np.zeros_like(f.P)
        Q = f.Q
        G[1:-1] = (w0[1:-1] * Q[1:-1] + w1[1:-1] * Q[:-2] - self.c_t * self.Q_hist[1:-1]
                   - (flux[1:] - flux[:-1]))
        G[2:-1] += w2[2:-1] * Q[:-3]
        return G

    def row_scale(self, f: StepFields) -> np.ndarray:
        e_half = 0.5 * (f.eps[1:] + f.eps[:-1])
        d = np.full(f.eps.size, (self.speed / self.dx + self.c_t * self.a0)) * f.rho * \
            np.maximum(f.H, 1e-300)
        d[1:-1] += (e_half[1:] + e_half[:-1]) / self.dx**2
        return 1.0 / np.maximum(d, 1e-300)

    def _scale(self, f: StepFields) -> np.ndarray:
        return self.row_scale(f) if self.scale is None else self.scale

    def residual(self, s, H0, A_lag):
        """(F, fields): the scaled rows at the interior nodes, then the load row."""
        f = self.fields(s, H0, A_lag)
        sG = self._scale(f) * self.reynolds(f)
        rows = sG[1:-1]
        if self.cavitation == "reynolds":
            rows = np.minimum(f.P[1:-1], rows)
        load = self.dx * (f.load.sum() + f.A.sum()) - 0.5 * np.pi
        return np.concatenate((rows, [load])), f

    def jacobian(self, s, f: StepFields) -> np.ndarray:
        """dF/d(s_interior, H0) (module docstring; the asperity pressure's own deflection is
        left out, as the lag leaves it out of the residual)."""
        n = s.size
        sc = self._scale(f)
        local, t_H = self._bands(s, f)
        pressed = f.dload
        if callable(self.influence):                     # built once, on first use
            self.influence = self.influence()
        Kd = self.influence * pressed[None, :]          # dH_k/ds_j
        J = np.zeros((n - 1, n - 1))
        D = J[:-1, :-1]
        for o, t in t_H.items():
            lo, hi = max(1, -o), n - 1
            rows = slice(lo - 1, hi - 1)
            D[rows] += (sc * t)[lo:hi, None] * Kd[lo + o:hi + o, 1:n - 1]
            J[rows, -1] += (sc * t)[lo:hi]
        for o, c in local.items():
            i = np.arange(max(1, 1 - o), min(n - 1, n - 1 - o))
            D[i - 1, i + o - 1] += sc[i] * c[i]
        if self.cavitation == "reynolds":
            idx = np.flatnonzero(f.P[1:-1] <= sc[1:-1] * self.reynolds(f)[1:-1])
            J[idx, :] = 0.0
            J[idx, idx] = 1.0
        J[-1, :-1] = self.dx * (pressed[1:-1] + f.dA @ Kd[:, 1:-1])
        J[-1, -1] = self.dx * f.dA.sum()
        return J

    def _bands(self, s, f: StepFields):
        """Coefficients of dG_i on s_{i+o} (local) and on H_{i+o} (t_H), o = -2..1."""
        n, dx2 = s.size, self.dx**2
        P = f.P
        e_half = 0.5 * (f.eps[1:] + f.eps[:-1])
        dP = np.diff(P)
        zero = np.zeros(n)
        c_eps = flow_bands(dP, n, dx2)
        w0, w1, w2 = self._wedge(n)
        w2 = w2.copy()
        w2[:2] = 0.0
        c_q = {0: w0, -1: w1, -2: w2, 1: zero}
        Hs = np.where(f.H > 0, f.H, np.inf)
        deps_dH = 3.0 * f.eps / Hs
        deps_ds = f.eps * (f.drho / f.rho - f.dlog_eta) * f.dP
        dq_dH = f.rho * f.theta
        dq_ds = f.drho * f.dP * f.theta * f.H + f.rho * f.H * f.dtheta
        local, t_H = {}, {}
        for o in (-2, -1, 0, 1):
            shifted = slice(max(0, o), n + min(0, o))
            rows = slice(max(0, -o), n - max(0, o))
            t, c = np.zeros(n), np.zeros(n)
            t[rows] = c_eps[o][rows] * deps_dH[shifted] + c_q[o][rows] * dq_dH[shifted]
            c[rows] = c_eps[o][rows] * deps_ds[shifted] + c_q[o][rows] * dq_ds[shifted]
            t_H[o], local[o] = t, c
        press = f.dP
        local[1][1:-1] -= e_half[1:] / dx2 * press[2:]
        local[-1][1:-1] -= e_half[:-1] / dx2 * press[:-2]
        local[0][1:-1] += (e_half[1:] + e_half[:-1]) / dx2 * press[1:-1]
        return local, t_H

    def mass_error(self, f: StepFields) -> float:
        """The step's discrete mass balance, |sum of the unscaled rows| dX over the inflow
        scale |u| max Q + c_t max Q: the rows telescope (flux form), so this is the change of
        the film content against what crossed the domain's ends, to the solver's tolerance.
        ``half_sommerfeld``: the rows of the pressure it keeps, max(P, 0) (the full-film rows
        it solves telescope to zero whatever becomes of the dropped negative pressures: they
        would read a balance the kept film does not have)."""
        if self.cavitation == "half_sommerfeld":
            f = replace(f, P=f.load)
        G = self.reynolds(f)
        scale = (self.speed + self.c_t * self.a0 * (self.X[-1] - self.X[0])) * np.abs(f.Q).max()
        return float(abs(G[1:-1].sum() * self.dx) / max(scale, 1e-300))
