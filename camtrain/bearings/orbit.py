"""Journal orbit under a periodic load diagram: one march-in-time kernel (Booker's mobility method).

Equation of motion (Yang 1992 eq. 1.12/1.14, Ball 1988 eq. 6.3, vector form, see the mobility
module): d(eps)/dt = w(eps, W) + wbar z x eps, where w is the mobility velocity for the load W.

Kernel: embedded Dormand-Prince 5(4) steps with absolute error control on eps. Between the
angles of the load diagram the load and speeds are a periodic piecewise cubic in time
(``load_interpolation``): linear (default, the diagram as given), the shape-preserving cubic
Hermite of Fritsch & Carlson (``"pchip"``) or the periodic cubic spline (``"spline"``). The
steps run free of the load grid (``steps="free"``, default): a step as long as the error
estimate allows ends on the last grid angle it reaches, a step shorter than a load interval
stays inside it (so it never crosses the kink of a linear load there), and the grid angles
inside a long step are sampled by the method's 4th-order continuous extension. From the third
cycle each cycle first replays the previous cycle's steps, so that a settled cycle is the same
map of its start every time and the cycle-to-cycle change falls geometrically (steps placed
afresh each cycle keep it at the march's error). ``steps="grid"`` ends every step on a grid
angle (the march of camtrain 0.1). A step whose stage or end point would reach |eps| >=
EPS_LIMIT is rejected and quartered before the mobility is evaluated there, so the eccentricity
never reaches 1 (Yang's program halved the step on overshoot, §2.2). Cycles repeat until the
grid samples of two successive cycles differ by no more than ``period_tol``.

Why linear stays the default (measured, docs/bearings.md): a long step across the kinks of a
linear load errs at order h^3 instead of h^5, but the error estimate sees it and the steps stay
long where the load is smooth (a quarter to a third of the grid's steps on the Zeta camshaft).
A smooth interpolant changes the diagram instead: a camshaft bearing's load jumps where a lobe
takes up its clearance and is zero while its lobes are on their base circles; the spline rings
across the jump (eps moves by 0.011 on decks/zeta_intake_camshaft.toml), and on the elastic
camshaft deck, whose 1440-angle diagram is not resolved (its films move 6.6 % at 720), the
shape-preserving cubic moves a bearing's smallest film by 1.6 % and the film at single angles by
up to 6 %: a change of the load, not of the march.

The march runs compiled (numba, :mod:`camtrain.bearings._orbit_march` with the mobility of
:mod:`camtrain.bearings._orbit_kernel`, cached on disk); numba is imported only when an orbit is
marched. The mobility is pluggable: the exact pi-film inversion,
Booker's closed form, or a tabulated :class:`~camtrain.bearings.mobility_map.MobilityMap` (e.g. a
finite-length bearing's).
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.errors import ConvergenceError, field_error

from .geometry import JournalBearing
from .mobility_map import MobilityMap
from .power import check_film, check_terms, shear_power
from .result import JournalOrbit

__all__ = ["journal_orbit", "bearing_orbit", "load_diagram", "EPS_LIMIT", "MOBILITIES"]

#: Largest eccentricity ratio a step may visit; the film is then c * 1e-12 thick.
EPS_LIMIT = 1.0 - 1e-12
MOBILITIES = ("exact", "booker")
LOAD_INTERPOLATIONS = ("linear", "pchip", "spline")
STEPS = ("free", "grid")
_NO_TABLE = (np.zeros(2), np.zeros((2, 1)), np.zeros((2, 1)))
for _a in _NO_TABLE:     # read-only as the mobility maps are: one compiled march, not two
    _a.setflags(write=False)
del _a


def diagram_rate(angle_rate, omega_journal) -> float:
    """Rate [rad/s] at which the load-diagram angle advances: given, or the journal speed when
    that is constant over the cycle."""
    if angle_rate is None:
        if np.ndim(omega_journal) != 0:
            raise field_error("angle_rate", "required when omega_journal varies over the cycle")
        angle_rate = abs(float(omega_journal))
    if not (angle_rate > 0 and math.isfinite(angle_rate)):
        raise field_error("angle_rate", "must be > 0 (the load diagram must advance)", angle_rate)
    return float(angle_rate)


def load_diagram(load_x, load_y, angle_grid, period: float, *speeds):
    """Validate a periodic load diagram; return float arrays (angles strictly increasing and
    spanning less than one ``period``) with the speeds broadcast to the grid."""
    th = np.asarray(angle_grid, dtype=float).ravel()
    fx = np.asarray(load_x, dtype=float).ravel()
    fy = np.asarray(load_y, dtype=float).ravel()
    if th.size < 2:
        raise field_error("angle_grid", "needs at least 2 points", th.size)
    if fx.shape != th.shape or fy.shape != th.shape:
        raise field_error("load_x", "load components must match angle_grid in length",
                          (fx.size, fy.size), f"{th.size} values each")
    for name, v in (("angle_grid", th), ("load_x", fx), ("load_y", fy)):
        if not np.all(np.isfinite(v)):
            raise field_error(name, "must be finite", v[~np.isfinite(v)][0])
    if not (period > 0 and math.isfinite(period)):
        raise field_error("period", "must be > 0", period)
    if np.any(np.diff(th) <= 0) or th[-1] - th[0] >= period:
        raise field_error("angle_grid", "must increase strictly and span less than one period",
                          (float(th[0]), float(th[-1])), f"a span < {period}")
    out = []
    for i, s in enumerate(speeds):
        s = np.broadcast_to(np.asarray(s, dtype=float), th.shape).copy()
        if not np.all(np.isfinite(s)):
            raise field_error(("omega_journal", "omega_bearing")[min(i, 1)], "must be finite")
        out.append(s)
    return th, fx, fy, out


def bearing_orbit(bearing: JournalBearing, load_x, load_y, angle_grid, omega_journal,
                  omega_bearing=0.0, *, angle_rate=None, period: float = 2.0 * math.pi,
                  film: str = "pi", terms: str = "shear", mobility: str | MobilityMap = "exact",
                  mobility_scale: float = 1.0, tol: float = 1e-7, period_tol: float = 1e-5,
                  max_cycles: int = 20, start: str = "steady",
                  max_steps_per_cycle: int = 200_000,
                  march_points: int | None = None,
                  load_interpolation: str = "linear", steps: str = "free") -> JournalOrbit:
    """Periodic journal orbit of ``bearing`` under a load diagram (Booker's mobility method).

    Args:
        load_x, load_y: load on the film in the bush frame [N], one value per grid angle.
        angle_grid: angles of the load diagram [rad], increasing, spanning < ``period``.
        omega_journal, omega_bearing: journal and bush speeds [rad/s] in the bush-fixed frame
            (scalars or arrays on the grid; a camshaft bush has omega_bearing = 0).
        angle_rate: d(angle)/dt [rad/s]; defaults to omega_journal when that is a scalar.
        period: angle of one load cycle [rad] (2 pi for a camshaft, 4 pi for a 4-stroke crank).
        film: shear film for power, "pi" (Yang eq. 1.21) or "2pi" (eq. 1.22).
        terms: "shear" or "all" (shear + translatory, Yang eq. 1.23).
        mobility: "exact" pi-film inversion (Ball's recipe), "booker" (Yang eqs 1.15/1.16) or a
            :class:`~camtrain.bearings.mobility_map.MobilityMap` (e.g. a finite-length map).
        mobility_scale: multiplies the mobility; 0.5 mimics Yang's program (reference note,
            Yang §4.6 reproduction), 1.0 is the physics.
        tol: absolute error per step on eps (resolution knob).
        period_tol: cycle-to-cycle change on eps that counts as periodic.
        max_cycles: give up (ConvergenceError) after this many cycles.
        start: "steady" (quasi-static eps at the first angle) or "centre" (eps = 0, Yang).
        march_points: march on the load diagram resampled (periodic linear) to this many equally
            spaced angles per period when the diagram has more (resolution knob: the orbit's own
            grid, independent of the grid the loads come on); the orbit is reported on the
            diagram's own grid (eps interpolated linearly, its squeeze velocity, film and power
            from the mobility under the diagram's load there). None or 0: march on the
            diagram's grid.
        load_interpolation: the load and speeds between the diagram's angles: "linear",
            "pchip" (periodic shape-preserving cubic Hermite, C1, no overshoot) or "spline"
            (periodic cubic spline, C2: 4th order on a smooth diagram, rings at a jump).
        steps: "free" (steps span load intervals where the error allows, the grid sampled by
            the continuous extension) or "grid" (every step ends on a grid angle).
    """
    film, terms = check_film(film), check_terms(terms)
    if not isinstance(mobility, MobilityMap) and mobility not in MOBILITIES:
        raise field_error("mobility", "unknown mobility", mobility,
                          " or ".join(MOBILITIES) + " or a MobilityMap")
    if load_interpolation not in LOAD_INTERPOLATIONS:
        raise field_error("load_interpolation", "unknown load interpolation", load_interpolation,
                          " or ".join(LOAD_INTERPOLATIONS))
    if steps not in STEPS:
        raise field_error("steps", "unknown step placement", steps, " or ".join(STEPS))
    if start not in ("steady", "centre"):
        raise field_error("start", "unknown start", start, "steady or centre")
    if not (mobility_scale > 0 and math.isfinite(mobility_scale)):
        raise field_error("mobility_scale", "must be > 0", mobility_scale)
    if not (tol > 0 and period_tol > 0):
        raise field_error("tol", "tolerances must be > 0", (tol, period_tol))
    if int(max_cycles) < 2:
        raise field_error("max_cycles", "must be >= 2 (periodicity needs two cycles)", max_cycles)
    th, fx, fy, (wj, wb) = load_diagram(load_x, load_y, angle_grid, period,
                                        omega_journal, omega_bearing)
    angle_rate = diagram_rate(angle_rate, omega_journal)
    if march_points and 2 <= march_points < th.size:
        return _resampled_orbit(bearing, th, fx, fy, wj, wb, int(march_points), period,
                                angle_rate=angle_rate, film=film, terms=terms, mobility=mobility,
                                mobility_scale=mobility_scale, tol=tol, period_tol=period_tol,
                                max_cycles=max_cycles, start=start,
                                max_steps_per_cycle=max_steps_per_cycle,
                                load_interpolation=load_interpolation, steps=steps)
    wbar = 0.5 * (wj + wb)
    t = (th - th[0]) / angle_rate
    T = period / angle_rate
    dts = np.append(np.diff(t), T - t[-1])
    from . import _orbit_kernel as K

    y = (0.0, 0.0)
    if start == "steady":  # a grooved bearing carries half the load on each land
        ocvirk_k = bearing.viscosity * bearing.radius * bearing.land ** 3 / (
            2.0 * bearing.clearance ** 2) * (2.0 if bearing.grooved else 1.0)
        y = K.steady_start(float(fx[0]), float(fy[0]), float(wbar[0]), ocvirk_k)

    if isinstance(mobility, MobilityMap):
        kind, gain, table, label = K.TABLE, mobility_scale * mobility.gain(bearing), \
            (mobility.eps, mobility.m_xi, mobility.m_mu), mobility.name
    else:
        kind = K.EXACT if mobility == "exact" else K.BOOKER
        gain = mobility_scale * (1.0 if mobility == "exact" else 2.0) / bearing.stiffness
        table, label = _NO_TABLE, mobility
    coef = load_coefficients(t, T, fx, fy, wbar, load_interpolation)
    from ._orbit_march import march_orbit

    cur, vel, cycles, change, status, t_fail, e_fail, _ = march_orbit(
        coef, t, dts, T, float(y[0]), float(y[1]), steps == "grid",
        K.Mobility(kind, float(gain), *table), float(tol), float(period_tol), int(max_cycles),
        int(max_steps_per_cycle), EPS_LIMIT)
    if status == K.BUDGET:
        raise ConvergenceError(
            f"journal orbit: step budget ({max_steps_per_cycle} per cycle) exhausted at "
            f"t = {t_fail:.6g} s, eps = {e_fail:.12f}; loosen tol or check the load units")
    if status == K.OFF_MAP:
        raise ConvergenceError(
            f"journal orbit left the mobility map at t = {t_fail:.6g} s: eps = {e_fail:.6f} "
            f"> {mobility.eps[-1]:.6f}, the largest eccentricity of the finite film's map; "
            "set the film model to short (closed-form mobility, no map) or check the load "
            "and its units")
    if status == K.NOT_PERIODIC and cycles < max_cycles:
        raise ConvergenceError(
            f"journal orbit not periodic: the cycle-to-cycle change stopped falling at "
            f"{change:.3g} after {cycles} cycles (the march's own error), above period_tol "
            f"{period_tol:.3g}; raise period_tol above it or loosen tol")
    if status == K.NOT_PERIODIC:
        raise ConvergenceError(
            f"journal orbit not periodic after {cycles} cycles: change {change:.3g} > "
            f"period_tol {period_tol:.3g}; raise max_cycles or period_tol")
    return assemble_orbit(bearing, th, t, T, fx, fy, cur[:, 0], cur[:, 1], vel, wj - wb, film, terms,
                   f"mobility-{label}", cycles, change, True)


def load_coefficients(t, period: float, fx, fy, wbar, interpolation: str) -> np.ndarray:
    """(n, 4, 3) cubic coefficients of the load x, y and wbar in each interval of the time grid
    ``t`` (cycle ``period``): linear (c2 = c3 = 0), the periodic cubic spline, or the periodic
    shape-preserving Hermite."""
    from ._orbit_march import linear_coefficients, periodic_spline

    if interpolation == "linear":
        return linear_coefficients(t, float(period), fx, fy, wbar)
    f = np.column_stack((fx, fy, wbar))
    if interpolation == "pchip":
        return periodic_pchip(t, period, f)
    return periodic_spline(t, float(period), f)


def periodic_pchip(t, period: float, f, groups=((0, 1), (2,))) -> np.ndarray:
    """Periodic shape-preserving cubic Hermite through the columns of f (n, m): coefficients
    (n, 4, m). The slopes are Fritsch & Butland's (1984) weighted harmonic mean of the
    neighbouring interval slopes a, b (Fritsch & Carlson 1980 shape preservation: 0 where they
    differ in sign or one is 0), written for vectors so that a load diagram's interpolant turns
    with its frame: d = (w1 + w2) (a.b) v / |v|^2, v = w1 b + w2 a, 0 where a.b <= 0; for one
    column it is the scalar formula. ``groups``: the columns that form one vector (the load's
    x and y; the speed alone)."""
    h = np.append(np.diff(t), period - t[-1])[:, None]
    delta = (np.roll(f, -1, axis=0) - f) / h
    hp, dp = np.roll(h, 1, axis=0), np.roll(delta, 1, axis=0)   # the interval before each point
    w1, w2 = 2.0 * h + hp, h + 2.0 * hp
    d = np.zeros_like(f)
    for cols in groups:
        a, b = dp[:, cols], delta[:, cols]
        v = w1 * b + w2 * a
        ab = np.sum(a * b, axis=1, keepdims=True)
        vv = np.sum(v * v, axis=1, keepdims=True)
        ok = (ab > 0.0) & (vv > 0.0)
        d[:, cols] = np.where(ok, (w1 + w2) * ab * v / np.where(ok, vv, 1.0), 0.0)
    d1 = np.roll(d, -1, axis=0)
    coef = np.empty((t.size, 4, f.shape[1]))
    coef[:, 0], coef[:, 1] = f, d
    coef[:, 2] = (3.0 * delta - 2.0 * d - d1) / h
    coef[:, 3] = (d + d1 - 2.0 * delta) / h ** 2
    return coef


def periodic_linear(x, xp, fp, period: float) -> np.ndarray:
    """fp (samples at increasing xp within one period) at x, linear and periodic."""
    return np.interp(x, xp, fp, period=period)


def _resampled_orbit(bearing, th, fx, fy, wj, wb, points, period, *, angle_rate, film, terms,
                     mobility, **march) -> JournalOrbit:
    """The orbit marched on ``points`` equally spaced angles (loads and speeds resampled,
    periodic linear), reported on the grid ``th`` (see :func:`bearing_orbit`)."""
    step = period / points
    grid = th[0] + step * np.arange(points)
    coarse = bearing_orbit(
        bearing, periodic_linear(grid, th, fx, period), periodic_linear(grid, th, fy, period),
        grid, periodic_linear(grid, th, wj, period), periodic_linear(grid, th, wb, period),
        angle_rate=angle_rate, period=period, film=film, terms=terms, mobility=mobility,
        **march)
    from . import _orbit_kernel as K

    # linear between the marched angles: no overshoot past them (a cubic overshoots where the
    # orbit turns sharply, e.g. onto a plateau of constant load), and inside the clearance
    ex = periodic_linear(th, grid, coarse.eps_x, period)
    ey = periodic_linear(th, grid, coarse.eps_y, period)
    kind, gain, table = _mobility_kernel(bearing, mobility, march["mobility_scale"])
    vel = K.squeeze_velocities(ex, ey, fx, fy, 0.5 * (wj + wb), kind, float(gain), *table)
    t = (th - th[0]) / angle_rate
    return assemble_orbit(bearing, th, t, period / angle_rate, fx, fy, ex, ey, vel, wj - wb,
                          film, terms, coarse.method, coarse.cycles, coarse.periodicity_error,
                          coarse.converged)


def _mobility_kernel(bearing, mobility, mobility_scale: float):
    """(kind, gain, table arrays) of the compiled mobility for ``mobility``."""
    from . import _orbit_kernel as K

    if isinstance(mobility, MobilityMap):
        return K.TABLE, mobility_scale * mobility.gain(bearing), (mobility.eps, mobility.m_xi,
                                                                  mobility.m_mu)
    kind = K.EXACT if mobility == "exact" else K.BOOKER
    return kind, mobility_scale * (1.0 if mobility == "exact" else 2.0) / bearing.stiffness, \
        _NO_TABLE


def assemble_orbit(bearing, th, t, T, fx, fy, ex, ey, vel, wrel, film, terms, method, cycles,
                   change, converged) -> JournalOrbit:
    """The JournalOrbit of a solved eccentricity path (shared by the mobility march, the
    steady-load locus and the finite-bearing models): attitude, film, power, periodicity."""
    e = np.hypot(ex, ey)
    pos = np.arctan2(ey, ex)
    att = np.arctan2(fx * ey - fy * ex, fx * ex + fy * ey)
    ps = shear_power(bearing, e, vel[:, 2], wrel, film)
    # translatory term: W . (c w), w in clearance units per second
    pq = bearing.clearance * (fx * vel[:, 0] + fy * vel[:, 1])
    pq = np.maximum(pq, 0.0)  # W . w = k w.Kw >= 0; clip round-off only
    return JournalOrbit(angle=th, time=t, load_x=fx, load_y=fy, eps_x=ex, eps_y=ey,
                        eccentricity=e, attitude=att, position=pos,
                        h_min=bearing.clearance * (1.0 - e), power_shear=ps, power_squeeze=pq,
                        power=ps + pq if terms == "all" else ps, method=method, film=film,
                        cycles=cycles, periodicity_error=change, converged=converged, period=T)


def journal_orbit(load_x, load_y, angle_grid, omega_journal, omega_bearing, diameter, length,
                  clearance, viscosity, *, groove_width: float = 0.0, **options) -> JournalOrbit:
    """Stand-alone entry: a load diagram in, the periodic orbit out (see :func:`bearing_orbit`).

    Args (SI): diameter d [m], length b [m], clearance c (radial) [m], viscosity [Pa s],
    groove_width [m] (0 = ungrooved); the rest as :func:`bearing_orbit`.
    """
    brg = JournalBearing(float(diameter), float(length), float(clearance), float(viscosity),
                         float(groove_width))
    return bearing_orbit(brg, load_x, load_y, angle_grid, omega_journal, omega_bearing,
                         **options)
