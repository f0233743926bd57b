"""Steady isothermal elastohydrodynamic line contact (cylinder on plane), full numerical solution.

The problem, in Hertzian units (X = x/b, P = p/p_h, H = h R/b^2, rho/rho0, eta/eta0; b and p_h
of the dry Hertz contact at the same load):

* Reynolds (Venner & Lubrecht 2000, ch. 2, the line-contact equations), with the **mean** entrainment speed
  u_m = (u1 + u2)/2 and lambda = 12 eta0 u_m R^2 / (b^3 p_h)::

      d/dX( eps dP/dX ) - d(rho H)/dX = 0,   eps = rho H^3 / (eta lambda)

* film: H = H0 + X^2/2 + V(X), V the elastic deflection of :mod:`.ehl_elastic`;
* load balance: integral P dX = pi/2 (the Hertz load), with the rigid approach H0 as unknown;
* cavitation ``reynolds`` (default; the Reynolds exit condition as a complementarity problem,
  Kinderlehrer & Stampacchia's obstacle form): P >= 0, G = d(rho H)/dX - d/dX(eps dP/dX) >= 0,
  P G = 0; the iterate is projected on P >= 0 after each step. (The mass-conserving Elrod-Adams
  condition is the cycle march's, :mod:`.ehl_transient_system`.)
  ``half_sommerfeld`` (Hamrock, Schmid & Jacobson 2004, *Fundamentals of Fluid Film
  Lubrication*, 2nd ed., the half-Sommerfeld condition; Dowson & Higginson 1977): G = 0
  everywhere with P unconstrained (the full Sommerfeld solution, theta = 1), and max(P, 0) in
  the load balance, the deflection and the friction. A bound and a link to the older
  literature: it neither conserves mass nor places the outlet constriction faithfully
  (docs/ehl.md). Its default outlet mirrors the inlet: the full Sommerfeld pressure of a rigid
  cylinder is antisymmetric, and a short outlet would cut its negative half and shift the rest.

Discretisation: uniform grid of n nodes on [inlet, outlet] b (P = 0 at both ends); conservative
second-order differences for the Poiseuille term with eps at the half nodes (arithmetic mean);
the wedge term by first-order upwind differences (``scheme = "upwind1"``, robust at any load; the
observed order is measured in the tests) or second-order upwind (``"upwind2"``).

Solver (the choice, measured in docs/ehl.md): semismooth Newton on the coupled system
[min(P_i, s_i G_i) = 0 ; load balance] in (P, H0) with the exact Jacobian, whose elastic part is
the dense influence matrix (the residual itself uses the FFT deflection), on grids up to
``dense_nodes``; a factorised Jacobian is reused while it keeps halving the residual. Finer grids
take matrix-free GMRES steps (:mod:`.ehl_krylov`, O(n log n) products) preconditioned by a
multilevel W-cycle (coarse grids four times coarser each, a band solve on each, the dense LU
only on a coarsest grid of at most 256 nodes), so that the cost grows as n log n. Steps are
damped by backtracking on the residual norm. Nested grids (128, 256, ... nodes) give each level
the previous solution as its guess; the first starts from the Hertz pressure with Moes' film; a
level too coarse to converge is skipped.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np
import scipy.linalg as sla

from camtrain.formulas.film_line import moes_1992
from camtrain.formulas.hertz import hertz_line_half_width, hertz_line_max_pressure
from camtrain.numerics.blas_threads import one_blas_thread

from .ehl_elastic import ElasticKernel
from .ehl_krylov import coarse_grids, krylov_step
from .ehl_newton import DiscreteEHL
from .ehl_oil import Oil, ScaledOil

__all__ = ["LineContact", "EHLResolution", "EHLSolution", "SCHEMES", "CAVITATION",
           "solve_ehl_line", "NotConverged"]

SCHEMES = ("upwind1", "upwind2")
CAVITATION = ("reynolds", "half_sommerfeld")
#: a reused (chord) Jacobian is kept while each step divides the residual by at least 1/0.5
CHORD_CONTRACTION = 0.5


class NotConverged(RuntimeError):
    """The Newton iteration did not reach the tolerance (message says how far it got)."""


@dataclass(frozen=True)
class LineContact:
    """A steady line contact: load per unit length w [N/m], reduced radius R [m], reduced
    modulus E_r [Pa], surface speeds u1, u2 [m/s] (entrainment u_m = (u1 + u2)/2 > 0), oil."""

    w: float
    R: float
    E_r: float
    u1: float
    u2: float
    oil: Oil

    @property
    def u_mean(self) -> float:
        return 0.5 * (self.u1 + self.u2)

    @property
    def half_width(self) -> float:
        return float(hertz_line_half_width(self.w, self.R, self.E_r))

    @property
    def hertz_pressure(self) -> float:
        return float(hertz_line_max_pressure(self.w, self.R, self.E_r))

    def moes_film(self) -> float:
        """Moes' central film [m] (mean-speed convention): the initial guess."""
        return float(moes_1992(self.w, self.R, self.u_mean, self.oil.eta0, self.oil.alpha,
                               self.E_r))


@dataclass(frozen=True)
class EHLResolution:
    """Accuracy knobs. nodes: grid points; inlet/outlet: domain ends in Hertz half-widths
    (None: automatic, -4.5 / 1.5 b or wider where the rigid film sqrt(2 R h) exceeds b);
    tolerance: on max |residual| of the scaled system and the relative change of H0;
    scheme: wedge-term differences; cavitation: exit condition; dense_nodes: largest grid
    solved with the dense Jacobian (finer grids: matrix-free GMRES steps with the multilevel
    preconditioner of :mod:`.ehl_krylov`, with the dense Jacobian as fallback)."""

    nodes: int = 1024
    inlet: float | None = None
    outlet: float | None = None
    tolerance: float = 1e-8
    max_iterations: int = 60
    scheme: str = "upwind2"
    cavitation: str = "reynolds"
    dense_nodes: int = 256

    def __post_init__(self):
        if self.nodes < 16:
            raise ValueError(f"nodes = {self.nodes}: expected at least 16")
        if self.scheme not in SCHEMES:
            raise ValueError(f"scheme {self.scheme!r}: expected one of {SCHEMES}")
        if self.cavitation not in CAVITATION:
            raise ValueError(f"cavitation {self.cavitation!r}: expected one of {CAVITATION}")

    def domain(self, H_guess: float) -> tuple[float, float]:
        """Domain ends in b: the rigid (Martin) pressure decays slowly upstream over lengths of
        sqrt(2 R h), so a light contact gets an inlet of 20 and an outlet of 2 such lengths
        (measured: the rigid-isoviscous h_min is 5-6 % low with 6 lengths, 0.5 % with 20);
        ``half_sommerfeld``: the outlet mirrors the inlet (module docstring)."""
        rigid = np.sqrt(2.0 * H_guess)
        inlet = -max(4.5, 20.0 * rigid) if self.inlet is None else self.inlet
        short = -inlet if self.cavitation == "half_sommerfeld" else max(1.5, 2.0 * rigid)
        outlet = short if self.outlet is None else self.outlet
        return float(inlet), float(outlet)


@dataclass(frozen=True)
class EHLSolution:
    """A converged steady line contact, SI unless named dimensionless.

    x [m], p [Pa] (the pressure that carries load: max of the solved one and 0), h [m] on the
    grid; p_sommerfeld [Pa]: with ``half_sommerfeld`` the solved full-Sommerfeld pressure,
    negative where the film would be in tension (None otherwise); h_central (at x = 0) and
    h_min [m]; spike: outlet pressure maximum (x_spike [m], p_spike [Pa]; None when the
    pressure has a single maximum, i.e. no spike); p_max [Pa]; h0 rigid approach in Hertzian
    units; iterations; residual;
    b, p_h the Hertz half-width and pressure; eta [Pa s] on the grid (for the friction)."""

    contact: LineContact
    resolution: EHLResolution
    x: np.ndarray
    p: np.ndarray
    h: np.ndarray
    eta: np.ndarray
    h_central: float
    h_min: float
    x_min: float
    p_max: float
    x_spike: float | None
    p_spike: float | None
    H0: float
    iterations: int
    residual: float
    b: float
    p_h: float
    notes: tuple[str, ...] = field(default_factory=tuple)
    p_sommerfeld: np.ndarray | None = None


def _discrete(contact: LineContact, resolution: EHLResolution) -> tuple[DiscreteEHL, float]:
    b, p_h = contact.half_width, contact.hertz_pressure
    H_guess = contact.moes_film() * contact.R / b**2
    inlet, outlet = resolution.domain(H_guess)
    X = np.linspace(inlet, outlet, resolution.nodes)
    lam = 12.0 * contact.oil.eta0 * contact.u_mean * contact.R**2 / (b**3 * p_h)
    kernel = ElasticKernel.of_grid(X.size, X[1] - X[0])
    return DiscreteEHL(X, kernel, ScaledOil(contact.oil, p_h), lam, resolution.scheme,
                       resolution.cavitation), H_guess


def _hertz_guess(problem: DiscreteEHL, H_central: float) -> tuple[np.ndarray, float]:
    """Hertz pressure and the approach that puts Moes' film at the centre."""
    width = max(1.0, 3.0 * problem.dx)      # a light contact's Hertz zone may be sub-cell
    P = np.sqrt(np.maximum(1.0 - (problem.X / width) ** 2, 0.0))
    P[[0, -1]] = 0.0
    P *= 0.5 * np.pi / (problem.dx * P.sum())
    V0 = np.interp(0.0, problem.X, problem.kernel.deflection(P))
    return P, H_central - V0


def _newton(problem: DiscreteEHL, P: np.ndarray, H0: float, tolerance: float,
            max_iterations: int):
    """Damped semismooth Newton with Jacobian reuse; returns (P, H0, iterations, residual,
    converged). A factorised Jacobian is kept while the full steps it gives shrink the residual
    by at least ``CHORD_CONTRACTION`` (a chord step costs one FFT residual and one triangular
    solve instead of the O(n^2) assembly and O(n^3) factorisation); otherwise it is rebuilt and
    the step damped by backtracking on the residual norm."""
    F, _ = problem.system(P, H0, jacobian=False)
    norm, lu = np.abs(F).max(), None
    for it in range(1, max_iterations + 1):
        fresh = lu is None
        if fresh:
            F, _, J = problem.system(P, H0)
            lu = sla.lu_factor(J, check_finite=False)
        step = sla.lu_solve(lu, -F, check_finite=False)
        P_new, H0_new, F_new, norm_new, t = _damped(problem, P, H0, step, norm, fresh)
        if not fresh and not norm_new < CHORD_CONTRACTION * norm:
            lu = None               # stale Jacobian: rebuild it and redo this step
            continue
        moved = abs(t * step[-1]) / max(abs(H0_new), 1e-300)
        P, H0, F, norm = P_new, H0_new, F_new, norm_new
        if norm < tolerance and moved < max(tolerance, 1e-12) ** 0.5:
            return P, H0, it, norm, True
        if t < 1.0:
            lu = None
    return P, H0, max_iterations, norm, False


def _newton_krylov(problem: DiscreteEHL, coarser: list[DiscreteEHL], P: np.ndarray,
                   H0: float, resolution: EHLResolution):
    """Damped semismooth Newton with matrix-free GMRES steps (:mod:`.ehl_krylov`)."""
    F, _ = problem.system(P, H0, jacobian=False)
    norm = np.abs(F).max()
    for it in range(1, resolution.max_iterations + 1):
        F, step, _ = krylov_step(problem, coarser, P, H0)
        P_new, H0_new, F_new, norm_new, t = _damped(problem, P, H0, step, norm, True)
        moved = abs(t * step[-1]) / max(abs(H0_new), 1e-300)
        P, H0, norm = P_new, H0_new, norm_new
        if norm < resolution.tolerance and moved < max(resolution.tolerance, 1e-12) ** 0.5:
            return P, H0, it, norm, True
    return P, H0, resolution.max_iterations, norm, False


def _damped(problem, P, H0, step, norm, backtrack):
    """The step scaled by t = 1, 1/2, ... (only t = 1 without ``backtrack``) until the film
    stays positive and the residual falls; P is projected on P >= 0 (not with
    ``half_sommerfeld``: there P is unconstrained)."""
    t = 1.0
    floor = -np.inf if problem.sommerfeld else 0.0
    while True:
        P_new = P.copy()
        P_new[1:-1] = np.maximum(P[1:-1] + t * step[:-1], floor)
        H0_new = H0 + t * step[-1]
        F_new, f_new = problem.system(P_new, H0_new, jacobian=False)
        norm_new = np.abs(F_new).max()
        good = f_new.H.min() > 0 and norm_new < (1.0 - 1e-4 * t) * norm
        if good or not backtrack or t < 1e-3:
            return P_new, H0_new, F_new, norm_new, t
        t *= 0.5


@one_blas_thread()   # small dense factorisations in a loop: see numerics.blas_threads
def solve_ehl_line(contact: LineContact,
                   resolution: EHLResolution = EHLResolution()) -> EHLSolution:
    """Solve the steady EHL line contact (module docstring); raises :class:`NotConverged`."""
    if not (contact.w > 0 and contact.R > 0 and contact.E_r > 0 and contact.u_mean > 0):
        raise ValueError("a steady line contact needs w, R, E_r and u_mean = (u1+u2)/2 > 0")
    its_total = 0
    P = H0 = problem = None
    for nodes in _levels(resolution.nodes):
        level = replace(resolution, nodes=nodes)
        fresh, H_guess = _discrete(contact, level)
        if problem is None:
            P, H0 = _hertz_guess(fresh, H_guess)
        else:        # nested iteration: the coarser solution is the guess
            P = np.interp(fresh.X, problem.X, P)
            P[[0, -1]] = 0.0
        problem = fresh
        if nodes > resolution.dense_nodes:
            P, H0, its, res, ok = _newton_krylov(problem, coarse_grids(problem), P, H0,
                                                 resolution)
            if not ok:      # the dense Jacobian is the robust fallback
                P, H0, more, res, ok = _newton(problem, P, H0, resolution.tolerance,
                                               resolution.max_iterations)
                its += more
        else:
            P, H0, its, res, ok = _newton(problem, P, H0, resolution.tolerance,
                                          resolution.max_iterations)
        its_total += its
        if not ok and nodes < resolution.nodes:
            problem = None       # too coarse for this contact: restart on the next grid
            continue
        if not ok:
            raise NotConverged(f"steady EHL line contact: residual {res:.3g} after {its} "
                               f"Newton iterations on {nodes} nodes (tolerance "
                               f"{resolution.tolerance:g})")
    its = its_total
    return _solution(contact, resolution, problem, P, H0, its, res)


def _levels(nodes: int, coarsest: int = 128) -> list[int]:
    """Grid sizes of the nested iteration, coarse to fine, each about half the next."""
    sizes = [nodes]
    while sizes[-1] // 2 >= coarsest:
        sizes.append((sizes[-1] + 1) // 2)
    return sizes[::-1]


def _spike(X: np.ndarray, P: np.ndarray) -> tuple[int | None, int]:
    """Index of the outlet spike (the last interior local maximum of P when there are two or
    more maxima, i.e. a dip between the plateau and the spike) and of the global maximum."""
    i_max = int(np.argmax(P))
    peaks = np.flatnonzero((P[1:-1] > P[:-2]) & (P[1:-1] >= P[2:]) & (P[1:-1] > 0)) + 1
    if peaks.size < 2:
        return None, i_max
    return int(peaks[-1]), i_max


def _solution(contact, resolution, problem, P, H0, its, res) -> EHLSolution:
    b, p_h, R = contact.half_width, contact.hertz_pressure, contact.R
    f = problem.fields(P, H0)
    X = problem.X
    h = f.H * b**2 / R
    log_eta, _ = problem.oil.log_viscosity(P)
    solved, P = P, problem.carried(P)
    i_spike, i_max = _spike(X, P)
    i_min = int(np.argmin(f.H))
    return EHLSolution(
        contact=contact, resolution=resolution, x=X * b, p=P * p_h, h=h,
        eta=contact.oil.eta0 * np.exp(log_eta),
        h_central=float(np.interp(0.0, X, h)), h_min=float(h[i_min]), x_min=float(X[i_min] * b),
        p_max=float(P[i_max] * p_h),
        x_spike=None if i_spike is None else float(X[i_spike] * b),
        p_spike=None if i_spike is None else float(P[i_spike] * p_h),
        H0=float(H0), iterations=its, residual=float(res), b=b, p_h=p_h,
        p_sommerfeld=solved * p_h if problem.sommerfeld else None)
