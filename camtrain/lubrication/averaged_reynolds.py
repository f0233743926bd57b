r"""Level 2 transient film: Göçmen's averaged Reynolds contact with asperity load sharing.

Per cam angle (Göçmen 2013 Sec. 2.2): the rigid parabolic gap of a cam of radius rho on a flat
tappet, h(x) = h_min + x^2/(2 rho) (inferred: the thesis shows no gap formula), over a zone
-b/2 <= x <= b/2; the averaged Reynolds pressure (eqs. 2.5-2.7,
:func:`~camtrain.lubrication.reynolds.reynolds_pressure`); the Greenwood-Tripp asperity pressure
integrated over the zone (:mod:`~camtrain.lubrication.asperity`); and the load balance
W_T = W_P(h_min, dh_min/dt) + W_A(h_min) (eq. 2.8), solved for h_min at every angle by the
implicit march of :mod:`~camtrain.lubrication.march` (Göçmen marches explicitly, eq. 2.30; the
implicit form is unconditionally stable where the asperity load is stiff).

Squeeze terms (``squeeze_terms``): ``full`` (default) uses the exact local rate of the gap,
dh/dt = dh_min/dt - x^2 drho/dt / (2 rho^2); ``min_only`` keeps dh_min/dt alone (Göçmen).

Friction from the same solution (per unit width, times the width): viscous Couette shear
eta |u_s| / h over the liquid part of the zone (the full film, and the liquid fraction of the
cavitated film) outside the real contact area, plus the asperity boundary shear
tau_0 a_a + m p_a (Teodorescu et al. 2005 eq. 8 in per-area form, Greenwood-Tripp a_a, p_a).
The Poiseuille part of the surface shear is left out (flagged in the docs).

Regime per angle from the asperity share of the load: ``hydrodynamic`` (W_A/W_T <= 1 %),
``mixed``, ``boundary`` (>= 90 %, or a load the model cannot carry at any film above
:data:`FILM_FLOOR`: those angles hold the floor and are listed in ``unbalanced``), ``separated``
(W_T <= 0: the film is held, no balance).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .asperity import asperity_area_fraction, asperity_pressure, asperity_pressure_coefficient
from .march import MARCH_SCHEMES, implicit_march
from .reynolds import CAVITATION_MODELS, contact_grid, reynolds_pressure

__all__ = ["FilmProperties", "FilmResolution", "ContactSolution", "TransientFilm",
           "SQUEEZE_TERMS", "REGIMES", "contact_solution", "contact_load", "transient_film",
           "hertz_zone_half_width", "regime_labels"]

SQUEEZE_TERMS = ("full", "min_only")
REGIMES = ("hydrodynamic", "mixed", "boundary", "separated")
#: asperity share of the load bounding the hydrodynamic and boundary regimes
HYDRODYNAMIC_SHARE, BOUNDARY_SHARE = 0.01, 0.90
#: smallest minimum film, in units of sigma (1 um if smooth): below it the nominal separation
#: would be negative in all but name, where the rigid averaged model no longer applies
FILM_FLOOR = 1e-3


@dataclass(frozen=True, kw_only=True)
class FilmProperties:
    """Lubricant, surfaces and model options of the contact (SI)."""

    viscosity: float                  #: eta [Pa s] (isoviscous inside Reynolds, as Göçmen)
    width: float                      #: contact (cam) width L [m]
    modulus: float                    #: reduced modulus E' [Pa]
    roughness: float = 0.0            #: composite rms sigma [m]; 0: smooth (no asperities)
    zeta_beta_sigma: float = 0.04     #: Greenwood-Tripp zeta beta sigma [-] (EXT default)
    sigma_over_beta: float = 1e-3     #: Greenwood-Tripp sigma/beta [-] (EXT default)
    shear_weight: float = 0.0         #: Vr1 - Vr2 of the shear-flow term [-] (0: alike surfaces)
    flow_factors: bool = True         #: Patir-Cheng / Wu-Zheng factors (False: all 1)
    cavitation: str = "reynolds"      #: ``reynolds`` or ``half_sommerfeld``
    squeeze_terms: str = "full"       #: ``full`` or ``min_only``
    eyring_stress: float = 2e6        #: tau_0 of the boundary film [Pa]
    boundary_shear: float = 0.17      #: m, pressure coefficient of boundary shear [-]

    def __post_init__(self):
        if self.cavitation not in CAVITATION_MODELS:
            raise ValueError(f"cavitation {self.cavitation!r}: expected {CAVITATION_MODELS}")
        if self.squeeze_terms not in SQUEEZE_TERMS:
            raise ValueError(f"squeeze_terms {self.squeeze_terms!r}: expected {SQUEEZE_TERMS}")
        for name in ("viscosity", "width", "modulus"):
            if not getattr(self, name) > 0.0:
                raise ValueError(f"{name} must be > 0, got {getattr(self, name)}")

    @property
    def rough(self) -> bool:
        return self.roughness > 0.0

    @property
    def asperity_coefficient(self) -> float:
        return asperity_pressure_coefficient(self.modulus, self.zeta_beta_sigma,
                                             self.sigma_over_beta)


@dataclass(frozen=True, kw_only=True)
class FilmResolution:
    """Resolution knobs of the level-2 film (each appears in ``camtrain accuracy``)."""

    nodes: int = 401                  #: nodes across the zone
    clustering: float = 0.0           #: 0 uniform; > 0 sinh-clustered at the centre
    march: str = "implicit_euler"     #: ``implicit_euler``, ``bdf2`` or ``quasi_steady``
    tolerance: float = 1e-6           #: load-balance tolerance |W_T - W_P - W_A| / W_T
    cycles_max: int = 6               #: most cam revolutions marched
    period_tol: float = 1e-5          #: cycle-to-cycle change of h_min that ends the march

    def __post_init__(self):
        if self.march not in MARCH_SCHEMES:
            raise ValueError(f"march {self.march!r}: expected one of {MARCH_SCHEMES}")

    def grid(self) -> np.ndarray:
        return contact_grid(self.nodes, self.clustering)


class ContactSolution(NamedTuple):
    x: np.ndarray                #: nodes [m]
    gap: np.ndarray              #: h(x) [m]
    pressure: np.ndarray         #: fluid pressure [Pa]
    asperity_pressure: np.ndarray  #: Greenwood-Tripp pressure [Pa]
    fluid_load: float            #: W_P [N]
    asperity_load: float         #: W_A [N]
    rupture: float               #: film rupture x_c [m] (nan: none)
    flooded: bool                #: no rupture inside the zone
    viscous_friction: float      #: [N]
    asperity_friction: float     #: [N]
    clamped_nodes: int           #: nodes below the Patir-Cheng fit (h/sigma < 0.5)


def _gap(props, xi, half_width, h_min, h_dot, rho, rho_dot):
    x = half_width * xi
    x2 = x * x
    h = h_min + x2 / (2.0 * rho)
    if props.squeeze_terms == "full" and rho_dot:
        dhdt = h_dot - x2 * rho_dot / (2.0 * rho * rho)
    else:
        dhdt = h_dot
    return x, h, dhdt


def contact_load(props: FilmProperties, xi, half_width, h_min, h_dot, rho, rho_dot, u_e,
                 u_s=0.0) -> float:
    """W_P + W_A [N] at minimum film h_min [m] moving at h_dot [m/s] (the balance's load)."""
    x, h, dhdt = _gap(props, xi, half_width, h_min, h_dot, rho, rho_dot)
    sol = reynolds_pressure(x, h, u_e, dhdt, props.viscosity, props.roughness, u_s,
                            props.shear_weight, props.cavitation, props.flow_factors)
    load = sol.load
    if props.rough:
        pa = asperity_pressure(h, props.roughness, props.asperity_coefficient)
        load += float(np.dot(0.5 * (pa[1:] + pa[:-1]), np.diff(x)))
    return props.width * load


def contact_solution(props: FilmProperties, xi, half_width, h_min, h_dot, rho, rho_dot, u_e,
                     u_s=0.0) -> ContactSolution:
    """The full contact state (pressures, loads, friction) at one angle."""
    x, h, dhdt = _gap(props, xi, half_width, h_min, h_dot, rho, rho_dot)
    sol = reynolds_pressure(x, h, u_e, dhdt, props.viscosity, props.roughness, u_s,
                            props.shear_weight, props.cavitation, props.flow_factors)
    L = props.width
    if props.rough:
        pa = asperity_pressure(h, props.roughness, props.asperity_coefficient)
        aa = asperity_area_fraction(h, props.roughness, props.zeta_beta_sigma)
        clamped = int(np.count_nonzero(h < 0.5 * props.roughness)) if props.flow_factors else 0
    else:
        pa, aa, clamped = np.zeros_like(x), np.zeros_like(x), 0
    shear = props.viscosity * abs(u_s) / h * sol.liquid_fraction * (1.0 - aa)
    boundary = props.eyring_stress * aa + props.boundary_shear * pa
    return ContactSolution(x, h, sol.pressure, pa, L * sol.load, L * _trap(pa, x),
                           sol.rupture, sol.flooded, L * _trap(shear, x), L * _trap(boundary, x),
                           clamped)


def _trap(y, x) -> float:
    return float(np.dot(0.5 * (y[1:] + y[:-1]), np.diff(x)))


def hertz_zone_half_width(load, width, radius, modulus, factor: float = 4.0,
                          floor_load: float | None = None):
    """Half width b/2 of the solution zone: ``factor`` x the Hertz half width a [m].

    a = sqrt(8 w R / (pi E')), w = W/L, at max(W, floor_load) so the zone does not vanish where
    the load does (default floor: 10 % of the mean positive load).
    """
    W = np.asarray(load, dtype=float)
    if floor_load is None:
        pos = W[W > 0.0]
        floor_load = 0.1 * float(pos.mean()) if pos.size else 1.0
    w = np.maximum(W, floor_load) / width
    return factor * np.sqrt(8.0 * w * np.asarray(radius, dtype=float) / (np.pi * modulus))


def regime_labels(fluid_load, asperity_load, load, met=True) -> np.ndarray:
    """Regime per angle from the asperity share of the load (see module); an angle whose load
    the film cannot carry at any film above the floor is ``boundary``."""
    load = np.asarray(load, dtype=float)
    share = np.where(load > 0.0, np.asarray(asperity_load) / np.where(load > 0, load, 1.0), 0.0)
    lab = np.where((share <= HYDRODYNAMIC_SHARE) & met, "hydrodynamic",
                   np.where((share >= BOUNDARY_SHARE) | ~np.asarray(met), "boundary", "mixed"))
    return np.where(load > 0.0, lab, "separated").astype(object)


class TransientFilm(NamedTuple):
    film: np.ndarray             #: h_min [m]
    film_rate: np.ndarray        #: dh_min/dt [m/s]
    fluid_load: np.ndarray       #: W_P [N]
    asperity_load: np.ndarray    #: W_A [N]
    balance_error: np.ndarray    #: |W_T - W_P - W_A| / W_T (nan where separated)
    rupture: np.ndarray          #: x_c [m] (nan: none)
    flooded: np.ndarray          #: bool
    viscous_friction: np.ndarray  #: [N]
    asperity_friction: np.ndarray  #: [N]
    regime: np.ndarray           #: labels (:data:`REGIMES`)
    clamped_nodes: np.ndarray    #: nodes below the Patir-Cheng fit, per angle
    unbalanced: np.ndarray       #: loaded angles whose load the film cannot carry above the floor
    cycles: int
    period_error: float
    evaluations: int
    pressure_max: np.ndarray | None = None           #: peak fluid pressure [Pa] per angle
    asperity_pressure_max: np.ndarray | None = None  #: peak asperity pressure [Pa] per angle

    @property
    def friction(self) -> np.ndarray:
        return self.viscous_friction + self.asperity_friction


def _periodic_derivative(values, theta):
    """d(values)/d(theta), central differences on a periodic grid (one period, no end point)."""
    v = np.asarray(values, dtype=float)
    th = np.asarray(theta, dtype=float)
    span = th[-1] - th[0] + (th[-1] - th[-2])
    ahead = np.roll(th, -1)
    ahead[-1] += span
    behind = np.roll(th, 1)
    behind[0] -= span
    return (np.roll(v, -1) - np.roll(v, 1)) / (ahead - behind)


def transient_film(theta, omega: float, rho, u_e, load, half_width, props: FilmProperties,
                   resolution: FilmResolution = FilmResolution(), u_s=None,
                   squeeze: bool = True, h_start: float | None = None,
                   strict: bool = True) -> TransientFilm:
    r"""March the level-2 minimum film around a periodic cam cycle.

    Args:
        theta: ascending cam angles over one period [rad] (no end point); omega [rad/s] > 0.
        rho: radius of the cam at the contact [m] (> 0); u_e: mean entrainment [m/s] (signed:
            its sign chooses the inlet side); load: contact load W_T [N] (<= 0: separated);
        half_width: zone half width b/2 per angle [m] (e.g. :func:`hertz_zone_half_width`).
        props, resolution: :class:`FilmProperties`, :class:`FilmResolution`.
        u_s: sliding speed [m/s] (shear-flow term and friction; default 0).
        squeeze: False forces dh/dt = 0 (the per-angle steady solution).
        h_start: film before the first angle (default: a steady solve at theta[0]).
        strict: raise where the balance misses the tolerance (False: report it in
            ``balance_error`` and go on; the root can sit on the small jump in load between the
            single-zone and the multi-zone pressure solvers, which shrinks as the nodes grow).

    Returns:
        :class:`TransientFilm`. The balance at every loaded angle is met to the resolution's
        tolerance (``balance_error``); a failure raises ValueError naming the angle.
    """
    theta = np.asarray(theta, dtype=float)
    n = theta.size
    rho, u_e, W, b2 = (np.broadcast_to(np.asarray(v, dtype=float), (n,)) for v in
                       (rho, u_e, load, half_width))
    u_s = np.zeros(n) if u_s is None else np.broadcast_to(np.asarray(u_s, float), (n,))
    if not omega > 0.0:
        raise ValueError(f"omega must be > 0 rad/s, got {omega}")
    if np.any(rho <= 0.0) or not np.all(np.isfinite(rho)):
        raise ValueError("rho must be finite and > 0 at every angle")
    xi = resolution.grid()
    rho_dot = omega * _periodic_derivative(rho, theta) if squeeze else np.zeros(n)
    rl, ul, sl, Wl, bl, rdl = (a.tolist() for a in (rho, u_e, u_s, W, b2, rho_dot))

    def balance(i, h, hdot):
        got = contact_load(props, xi, bl[i], h, hdot, rl[i], rdl[i], ul[i], sl[i])
        return got / Wl[i] - 1.0

    active = W > 0.0
    if h_start is None:
        h_start = _steady_guess(props, rho, u_e, W, active)
    scheme = resolution.march if squeeze else "quasi_steady"
    xtol = min(1e-10, 1e-3 * resolution.tolerance)
    floor = FILM_FLOOR * (props.roughness if props.rough else 1e-6)
    m = implicit_march(balance, theta / omega, h_start, scheme, period=2.0 * np.pi / omega,
                       active=active, cycles_max=resolution.cycles_max,
                       period_tol=resolution.period_tol, xtol=xtol, y_min=floor)
    err = np.abs(m.residual)
    bad = active & m.met & ~(err <= resolution.tolerance)
    if strict and np.any(bad):
        i = int(np.flatnonzero(bad)[0])
        raise ValueError(f"load balance not met at cam angle {math.degrees(theta[i]):.2f} deg "
                         f"(error {err[i]:.3g} > tolerance {resolution.tolerance:g})")
    parts = [contact_solution(props, xi, bl[i], m.y[i], m.ydot[i], rl[i], rdl[i], ul[i], sl[i])
             for i in range(n)]
    col = {f: np.array([getattr(p, f) for p in parts]) for f in
           ("fluid_load", "asperity_load", "rupture", "flooded", "viscous_friction",
            "asperity_friction", "clamped_nodes")}
    return TransientFilm(m.y, m.ydot, col["fluid_load"], col["asperity_load"], err,
                         col["rupture"], col["flooded"].astype(bool), col["viscous_friction"],
                         col["asperity_friction"],
                         regime_labels(col["fluid_load"], col["asperity_load"], W, m.met),
                         col["clamped_nodes"], ~m.met & active, m.cycles, m.period_error,
                         m.evaluations, np.array([float(p.pressure.max()) for p in parts]),
                         np.array([float(p.asperity_pressure.max()) for p in parts]))


def _steady_guess(props, rho, u_e, W, active) -> float:
    """A positive starting film: Martin's rigid film at the first loaded angle, or sigma."""
    idx = np.flatnonzero(active)
    if idx.size == 0:
        raise ValueError("the contact carries no load at any angle")
    i = int(idx[0])
    h = 4.896 * props.viscosity * abs(u_e[i]) * rho[i] * props.width / W[i]
    return max(h, props.roughness, 1e-9)
