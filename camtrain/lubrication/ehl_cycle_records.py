"""Records of the transient EHL march (:mod:`.ehl_transient`): the contact over the steps, the
knobs, the marched cycle, and the state a step hands to the next."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .ehl_oil import Oil
from .ehl_transient_system import CAVITATION

MARCHES = ("bdf2", "implicit_euler")
LINEAR_SOLVERS = ("auto", "krylov", "dense")
#: ``auto`` takes the matrix-free directions from this many nodes on (measured on the Goecmen
#: cam, 80 steps through a flank and a reversal: dense 1.2-1.9 s against 3.0-3.4 s at 128-256
#: nodes, where a dense LU costs about a millisecond; 4.7-7.2 s against 4.2-5.5 s at 512)
KRYLOV_NODES = 384


@dataclass(frozen=True)
class CycleContact:
    """The cam contact over the march: per-step arrays (time t [s], load per unit length w
    [N/m], radius R [m], signed mean entrainment u [m/s], sliding u_s [m/s]) and constants
    (E_r [Pa], width [m], oil, roughness sigma [m] (0: smooth), Greenwood-Tripp zeta beta
    sigma and sigma/beta, Eyring stress tau_0 [Pa], boundary shear coefficient m)."""

    t: np.ndarray
    w: np.ndarray
    R: np.ndarray
    u: np.ndarray
    u_s: np.ndarray
    E_r: float
    width: float
    oil: Oil
    sigma: float = 0.0
    zeta_beta_sigma: float = 0.04
    sigma_over_beta: float = 1e-3
    eyring_stress: float = 2e6
    boundary_shear: float = 0.17


@dataclass(frozen=True)
class CycleResolution:
    """Knobs: nodes, inlet (half domain in Hertz half-widths), Newton tolerance (max scaled
    residual), march (``bdf2`` or ``implicit_euler``), cavitation, wedge scheme, map_nodes
    (positions kept per angle in the film map), linear_solver (the Newton direction:
    ``krylov``, matrix-free GMRES with a two-level preconditioner, O(n log n) per product
    (:mod:`.ehl_step_krylov`); ``dense``, the dense Jacobian's LU, kept across iterations and
    steps while its chord steps halve the residual, O(n^3) per factorisation; ``auto``,
    ``krylov`` from ``KRYLOV_NODES`` nodes on). Both solve the same equations to the same
    tolerance."""

    nodes: int = 512
    inlet: float = 4.5
    tolerance: float = 1e-6
    march: str = "bdf2"
    cavitation: str = "elrod_adams"
    scheme: str = "upwind2"
    max_iterations: int = 40
    map_nodes: int = 64
    linear_solver: str = "auto"

    def __post_init__(self):
        if self.march not in MARCHES:
            raise ValueError(f"march {self.march!r}: expected one of {MARCHES}")
        if self.cavitation not in CAVITATION:
            raise ValueError(f"cavitation {self.cavitation!r}: expected one of {CAVITATION}")
        if self.linear_solver not in LINEAR_SOLVERS:
            raise ValueError(f"linear_solver {self.linear_solver!r}: expected one of "
                             f"{LINEAR_SOLVERS}")
        if self.nodes < 32:
            raise ValueError(f"nodes = {self.nodes}: expected at least 32")

    @property
    def krylov(self) -> bool:
        """Whether the Newton directions are matrix-free (``linear_solver``)."""
        return self.linear_solver == "krylov" or (self.linear_solver == "auto"
                                                   and self.nodes >= KRYLOV_NODES)


@dataclass
class EHLCycle:
    """The marched cycle, per step (NaN where unloaded): central and minimum film [m], peak
    pressure [Pa], Hertz pressure [Pa], friction [N] (fluid and asperity parts), asperity
    share of the load [-], peak asperity pressure [Pa], mass-balance error [-], Newton
    iterations, the film map (x [m], h [m], p [Pa] at ``map_nodes`` positions per step); LU
    factorisations (with ``krylov``: preconditioners built), period
    error, split steps, steps restarted from the steady solution, GMRES iterations."""

    h_central: np.ndarray
    h_min: np.ndarray
    p_max: np.ndarray
    p_hertz: np.ndarray
    fluid_friction: np.ndarray
    asperity_friction: np.ndarray
    asperity_share: np.ndarray
    asperity_pressure_max: np.ndarray
    mass_error: np.ndarray
    iterations: np.ndarray
    map_x: np.ndarray
    map_h: np.ndarray
    map_p: np.ndarray
    factorisations: int = 0
    period_error: float = math.nan
    split_steps: int = 0
    restarts: list = field(default_factory=list)   #: steps restarted from the steady solution
    krylov_iterations: int = 0     #: GMRES iterations of the matrix-free Newton directions

    @property
    def friction(self) -> np.ndarray:
        return self.fluid_friction + self.asperity_friction


@dataclass
class _State:
    """What a step hands to the next (physical units, unmirrored)."""

    x: np.ndarray
    s: np.ndarray
    q: np.ndarray          #: film content rho theta h [m]
    R: float
    p_h: float
    h_c: float
    q_old: np.ndarray | None = None
    x_old: np.ndarray | None = None
    R_old: float = math.nan
    a: np.ndarray | None = None     #: asperity pressure [Pa] on x (the next step's first lag)


def _content_on(x, x_from, q_from, R_from):
    """q (film content [m]) of grid x_from taken to x; the flooded rigid gap continues it."""
    q = np.interp(x, x_from, q_from)
    lo, hi = x < x_from[0], x > x_from[-1]
    q[lo] = q_from[0] + (x[lo] ** 2 - x_from[0] ** 2) / (2 * R_from)
    q[hi] = q_from[-1] + (x[hi] ** 2 - x_from[-1] ** 2) / (2 * R_from)
    return q
