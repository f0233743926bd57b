"""Finite-length journal bearing at steady load: eccentricity, attitude, minimum film, friction
and side flow from the Reynolds solution over the whole bearing (:mod:`.reynolds`).

The performance variables are Raimondi & Boyd's (1958): Sommerfeld number
``S = (R/c)^2 eta N L D / W`` (N in rev/s), attitude angle, friction variable ``(R/c) f``
(journal friction with the clearance full of oil everywhere, so that eps -> 0 gives Petroff's
``2 pi^2 S``), flow variable ``Q / (R c N L)`` (circumferential flow entering the film at the
feed line) and side-flow ratio ``Q_s / Q``.

Units: SI throughout. The load is the load the journal puts on the film; a bearing with a full
circumferential central groove is two finite lands of ``bearing.land`` each carrying half of it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camtrain.errors import field_error

from .geometry import JournalBearing
from .reynolds import CAVITATION, FilmField, FilmGrid, solve_film

__all__ = ["FEEDS", "FinitePerformance", "FiniteSteady", "finite_performance", "finite_steady",
           "film_grid"]

#: Oil feed of a steady solve: "none" (no groove: free Swift-Stieber boundaries both ends of the
#: film) or "max_film" (an axial line at ambient pressure at the thickest film, Raimondi & Boyd).
FEEDS = ("none", "max_film")
DEFAULT_MESH = (120, 12)


def film_grid(b_over_d: float, n_theta: int = DEFAULT_MESH[0], n_z: int = DEFAULT_MESH[1]):
    """Mesh over one half of a bearing of ratio b/d (land length over diameter)."""
    return FilmGrid(float(b_over_d), int(n_theta), int(n_z))


def _feed(feed: str):
    if feed not in FEEDS:
        raise field_error("feed", "unknown oil feed", feed, " or ".join(FEEDS))
    return (0.0, 0.0, 1.0) if feed == "max_film" else None


@dataclass(frozen=True)
class FinitePerformance:
    """Dimensionless steady performance at one eccentricity (Raimondi & Boyd variables).

    Attributes:
        b_over_d, eps: land length / diameter and eccentricity ratio.
        sommerfeld: S = (R/c)^2 eta N L D / W.
        attitude: angle from the load to the line of centres [rad] (in the sense of rotation).
        friction_variable: (R/c) f, journal friction, clearance full of oil.
        friction_variable_fraction: the same with Couette shear only where the JFO film
            fraction carries oil (equal to friction_variable unless cavitation = "jfo").
        flow_variable: Q/(R c N L), flow entering the film at the feed line (theta = 0).
        side_flow_ratio: Q_s / Q, leakage out of both ends over the inflow.
        pressure_ratio: mean pressure W/(L D) over the peak film pressure.
        load: dimensionless load W c^2 / (12 eta wbar R^4) (with wbar = omega_j/2).
        field: the film solution.
    """

    b_over_d: float
    eps: float
    sommerfeld: float
    attitude: float
    friction_variable: float
    friction_variable_fraction: float
    flow_variable: float
    side_flow_ratio: float
    pressure_ratio: float
    load: float
    field: FilmField


def _integrals(field: FilmField):
    """Full-length integrals over the film: Couette shear factors and end/inlet flows."""
    g = field.grid
    th, wz = g.theta, g.z_simpson
    h = 1.0 + field.eps * np.cos(th)
    wt = 2.0 * wz[:, None] * g.d_theta  # both halves
    shear_full = float(np.sum(wt / h[None, :]))
    shear_frac = float(np.sum(wt * field.fraction / h[None, :]))
    P = field.pressure
    # inflow at theta = 0+ (one-sided second-order derivative, P(0) held by the feed)
    dp = (-3.0 * P[:, 0] + 4.0 * P[:, 1] - P[:, 2]) / (2.0 * g.d_theta)
    q_in = 2.0 * float(np.sum(wz * (h[0] - h[0] ** 3 * dp)))
    # leakage out of both ends
    dz = (3.0 * P[-1] - 4.0 * P[-2] + P[-3]) / (2.0 * g.d_z)
    q_side = -2.0 * float(np.sum(h ** 3 * dz) * g.d_theta)
    return shear_full, shear_frac, q_in, q_side


def finite_performance(b_over_d: float, eps: float, *, cavitation: str = "reynolds",
                       feed: str = "max_film", n_theta: int = DEFAULT_MESH[0],
                       n_z: int = DEFAULT_MESH[1], start=None) -> FinitePerformance:
    """Raimondi & Boyd's steady variables of a finite bearing (fixed bush, load steady).

    Scale: omega_ref = wbar = omega_j/2, so S = (b/d) / (3 pi F) with F the dimensionless
    load, and (R/c) f = (2 I_shear + 6 eps I_sin) / (12 F) where I_sin = int P sin(theta) is
    the pressure part of the journal friction (it equals W e sin(phi) / R).
    """
    grid = film_grid(b_over_d, n_theta, n_z)
    field = solve_film(grid, float(eps), cavitation=cavitation, feed=_feed(feed), start=start)
    load = math.hypot(field.force_r, field.force_t)
    if load <= 0.0:
        raise field_error("eps", "no load carried (eccentricity zero)", eps, "eps > 0")
    att = math.atan2(-field.force_t, field.force_r)
    s_full, s_frac, q_in, q_side = _integrals(field)
    i_sin = -field.force_t
    ld = float(b_over_d)
    pmax = float(np.max(field.pressure))
    flow = math.pi * q_in / (2.0 * ld)
    return FinitePerformance(
        b_over_d=ld, eps=float(eps), sommerfeld=ld / (3.0 * math.pi * load), attitude=att,
        friction_variable=(2.0 * s_full + 6.0 * eps * i_sin) / (12.0 * load),
        friction_variable_fraction=(2.0 * s_frac + 6.0 * eps * i_sin) / (12.0 * load),
        flow_variable=flow, side_flow_ratio=(math.pi * q_side / (2.0 * ld)) / flow,
        pressure_ratio=load / (4.0 * ld * pmax) if pmax > 0 else math.inf, load=load,
        field=field)


@dataclass(frozen=True)
class FiniteSteady:
    """Steady-load operating point of a finite bearing (SI).

    Attributes:
        eccentricity: eps [-]; h_min = c (1 - eps) [m].
        attitude: angle from the load to the line of centres [rad], in the sense of wbar.
        h_min: minimum film thickness [m].
        friction_force: journal friction force [N] (clearance full of oil for the Couette part,
            Raimondi & Boyd's convention); friction_coefficient = friction_force / load.
        friction_torque: journal friction torque [N m].
        power: film dissipation [W]: Couette (clearance full) plus Poiseuille.
        side_flow: leakage out of the land ends [m^3/s]; inflow: flow entering the film at the
            thickest film [m^3/s] (meaningful with feed = "max_film").
        max_pressure: peak film pressure [Pa].
        sommerfeld: (R/c)^2 eta N L D / W with N = |wbar|/pi (rev/s of a fixed-bush journal).
        solves: Reynolds solutions used by the eccentricity search; mesh: (n_theta, n_z).
        cavitation, feed: the options used.
    """

    eccentricity: float
    attitude: float
    h_min: float
    friction_force: float
    friction_coefficient: float
    friction_torque: float
    power: float
    side_flow: float
    inflow: float
    max_pressure: float
    sommerfeld: float
    solves: int
    mesh: tuple[int, int]
    cavitation: str
    feed: str


def finite_steady(bearing: JournalBearing, load: float, omega_journal: float,
                  omega_bearing: float = 0.0, *, cavitation: str = "reynolds",
                  feed: str = "none", n_theta: int = DEFAULT_MESH[0],
                  n_z: int = DEFAULT_MESH[1], eps_tol: float = 1e-9) -> FiniteSteady:
    """Eccentricity, attitude, minimum film, friction and flow of a finite bearing under a
    steady load ``load`` [N] (the eccentricity-from-load problem).

    The eccentricity is the root of ``F(eps) = W c^2 / (12 eta |wbar| R^4)`` (one land, half the
    load when centrally grooved), bracketed on (0, 1) because the film force grows
    monotonically to infinity. Started from Ocvirk's eccentricity and refined by false
    position in logit(eps) on log F (5-8 Reynolds solutions, each warm started from the
    last). A journal turning against the load direction (wbar < 0) is the mirror image: the
    attitude changes sign.
    """
    if cavitation not in CAVITATION:
        raise field_error("cavitation", "unknown cavitation condition", cavitation,
                          " or ".join(CAVITATION))
    load = abs(float(load))
    wbar = 0.5 * (float(omega_journal) + float(omega_bearing))
    rel = float(omega_journal) - float(omega_bearing)
    if not math.isfinite(load):
        raise field_error("load", "must be finite", load)
    if wbar == 0.0:
        raise field_error("omega", "a steady load needs (omega_j + omega_b)/2 != 0", 0.0,
                          hint="at half-speed whirl only squeeze carries load; use an orbit")
    share = 0.5 if bearing.grooved else 1.0
    r, c, eta, land = bearing.radius, bearing.clearance, bearing.viscosity, bearing.land
    unit_force = 12.0 * eta * abs(wbar) * r ** 4 / c ** 2
    target = share * load / unit_force
    b_over_d = land / bearing.diameter
    fd = _feed(feed)
    grid = film_grid(b_over_d, n_theta, n_z)
    state = {"start": None, "n": 0, "field": None}

    def solve(e):
        f = solve_film(grid, e, cavitation=cavitation, feed=fd, start=state["start"])
        state["start"], state["field"] = f.pressure, f
        state["n"] += 1
        return f

    def gap(e):
        f = solve(e)
        return math.log(max(math.hypot(f.force_r, f.force_t), 1e-300)) - math.log(target)

    if target == 0.0:
        eps = 0.0
        field = solve(0.0)
    else:
        from camtrain.formulas.bearings import ocvirk_eccentricity

        # Ocvirk's eccentricity (short bearing, same load) is a close first guess; the root is
        # then refined by the Illinois false-position method in x = logit(eps), bracketing
        # outward from it, so a typical solve takes 5-7 Reynolds solutions.
        e0 = float(ocvirk_eccentricity(share * load, eta, 2.0 * abs(wbar), r, land, c))
        eps = _root_logit(gap, min(max(e0, 1e-4), 0.999), eps_tol, load)
        field = solve(eps)
    fr, ft = field.force_r, field.force_t
    att = math.atan2(-ft, fr) if target > 0 else 0.5 * math.pi
    att = math.copysign(att, wbar)
    s_full, _, q_in, q_side = _integrals(field)
    couette = eta * rel ** 2 * r ** 4 / c * s_full
    A_energy = _poiseuille(field)
    poiseuille = 12.0 * eta * wbar ** 2 * r ** 4 / c * A_energy
    # friction on the journal: Couette shear plus the pressure part W e sin(phi) / (2 R)
    f_couette = eta * abs(rel) * r ** 3 / c * s_full
    f_pressure = 0.5 * c * eps * share * load * abs(math.sin(att)) / r
    n_lands = 2 if bearing.grooved else 1
    friction = n_lands * (f_couette + f_pressure)
    flow_unit = c * r ** 2 * abs(wbar)
    n_rev = abs(wbar) / math.pi
    return FiniteSteady(
        eccentricity=float(eps), attitude=att, h_min=c * (1.0 - eps),
        friction_force=friction, friction_coefficient=friction / load if load else math.inf,
        friction_torque=friction * r, power=n_lands * (couette + poiseuille),
        side_flow=n_lands * flow_unit * q_side, inflow=n_lands * flow_unit * q_in,
        max_pressure=float(np.max(field.pressure)) * 12.0 * eta * abs(wbar) * r ** 2 / c ** 2,
        sommerfeld=(r / c) ** 2 * eta * n_rev * land * bearing.diameter / (share * load)
        if load else math.inf,
        solves=state["n"], mesh=(grid.n_theta, grid.n_z), cavitation=cavitation, feed=feed)


def _root_logit(gap, e0: float, tol: float, load: float) -> float:
    """Root of the increasing ``gap(eps)`` on (0, 1): bracket outward from ``e0`` in
    x = log(eps / (1 - eps)), then Illinois false position until the bracket is < tol in eps."""
    from camtrain.numerics.roots import false_position, illinois_update  # numba: load on use

    def ex(x):
        return 1.0 / (1.0 + math.exp(-x))

    lo_lim, hi_lim = math.log(1e-6 / (1 - 1e-6)), math.log((1 - 1e-6) / 1e-6)
    x0 = math.log(e0 / (1.0 - e0))
    g0 = gap(ex(x0))
    step = 0.5 if g0 < 0.0 else -0.5
    x1, g1 = x0, g0
    while g1 * g0 > 0.0:
        x0, g0 = x1, g1
        x1 = min(max(x1 + step, lo_lim), hi_lim)
        g1 = gap(ex(x1))
        if g1 * g0 > 0.0 and x1 in (lo_lim, hi_lim):
            if x1 == hi_lim:
                raise field_error("load", "too large for the bearing: the film would need "
                                  "eps > 1 - 1e-6", load, hint="check the load units")
            return ex(lo_lim)
        step *= 2.0
    (a, ga), (b, gb) = sorted(((x0, g0), (x1, g1)))
    side = 0
    for _ in range(100):
        x = false_position(b, gb, a, ga)
        g = gap(ex(x))
        if g == 0.0:
            return ex(x)
        a, ga, b, gb, side = illinois_update(a, ga, b, gb, x, g, side)
        if ex(b) - ex(a) < tol or abs(g) < 1e-13:
            break
    return ex(false_position(a, ga, b, gb))


def _poiseuille(field: FilmField) -> float:
    """int H^3 |grad P|^2 over the whole bearing (= 2 P.A.P on the half mesh)."""
    from .reynolds import _diffusion, _film

    _, h, hf = _film(field.grid, field.eps)
    p = field.pressure.ravel()
    return 2.0 * float(p @ (_diffusion(field.grid, h, hf) @ p))
