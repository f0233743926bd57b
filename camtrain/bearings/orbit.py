"""Journal orbit under a periodic load diagram: one march-in-time kernel (Booker's mobility method).

Equation of motion (Yang 1992 eq. 1.12/1.14, Ball 1988 eq. 6.3, vector form, see the mobility
module): d(eps)/dt = w(eps, W) + wbar z x eps, where w is the mobility velocity for the load W.

Kernel: embedded Dormand-Prince 5(4) steps with absolute error control on eps, marched interval
by interval along the load grid (the load and speeds are linear in time inside an interval, so
the right-hand side is smooth inside each step). A step whose stage or end point would reach
|eps| >= EPS_LIMIT is rejected and quartered before the mobility is evaluated there, so the
eccentricity never reaches 1 (Yang's program halved the step on overshoot, §2.2). Cycles repeat
until the grid samples of two successive cycles differ by no more than ``period_tol``.
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.errors import ConvergenceError, field_error

from .geometry import JournalBearing
from .mobility import mobility_booker, mobility_exact
from .power import check_film, check_terms, shear_power
from .result import JournalOrbit

__all__ = ["journal_orbit", "bearing_orbit", "load_diagram", "EPS_LIMIT", "MOBILITIES"]

#: Largest eccentricity ratio a step may visit; the film is then c * 1e-12 thick.
EPS_LIMIT = 1.0 - 1e-12
MOBILITIES = ("exact", "booker")

# Dormand-Prince 5(4) tableau.
_C = (0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0, 1.0)
_A = ((), (1 / 5,), (3 / 40, 9 / 40), (44 / 45, -56 / 15, 32 / 9),
      (19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729),
      (9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656),
      (35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84))
_E = (71 / 57600, 0.0, -71 / 16695, 71 / 1920, -17253 / 339200, 22 / 525, -1 / 40)


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


class _Field:
    """d(eps)/dt for one bearing; keeps the last squeeze direction as a warm start."""

    def __init__(self, bearing: JournalBearing, mobility: str, scale: float):
        self.k = bearing.stiffness
        self.exact = mobility == "exact"
        self.scale = scale
        self.delta = None

    def squeeze(self, ex, ey, wx, wy, wbar):
        """Mobility velocity w (1/s) and its direction from the line of centres."""
        load = math.hypot(wx, wy)
        e = math.hypot(ex, ey)
        if load == 0.0:
            return 0.0, 0.0, -math.copysign(0.5 * math.pi, wbar or 1.0)
        lam = math.atan2(wy, wx)
        psi = math.atan2(ey, ex) if e > 0.0 else lam
        if self.exact:
            tau = math.remainder(lam - psi, 2.0 * math.pi)
            delta, m = mobility_exact(e, tau, self.delta)
            self.delta = delta
            speed = self.scale * m * load / self.k
            ang = psi + delta
            return speed * math.cos(ang), speed * math.sin(ang), delta
        # Booker's closed form in the load frame (Yang eqs 1.15, 1.16): xi along W, mu normal
        # to it in the sense of wbar.
        s = 1.0 if wbar >= 0.0 else -1.0
        ux, uy = wx / load, wy / load
        nx, ny = -s * uy, s * ux
        mxi, mmu = mobility_booker(ex * ux + ey * uy, ex * nx + ey * ny)
        g = self.scale * 2.0 * load / self.k
        vx, vy = g * (mxi * ux + mmu * nx), g * (mxi * uy + mmu * ny)
        return vx, vy, math.remainder(math.atan2(vy, vx) - psi, 2.0 * math.pi)

    def __call__(self, ex, ey, wx, wy, wbar):
        vx, vy, _ = self.squeeze(ex, ey, wx, wy, wbar)
        return vx - wbar * ey, vy + wbar * ex


def _march(f: _Field, y, t0, dt, p0, p1, h, tol, budget):
    """Integrate one grid interval of length dt; p0/p1 are (Wx, Wy, wbar) at its ends.

    Returns (y_end, last step, steps used)."""
    ex, ey = y
    t, used = 0.0, 0
    slope = [(b - a) / dt for a, b in zip(p0, p1, strict=True)]

    def rhs(tt, x, yv):
        return f(x, yv, *(a + s * tt for a, s in zip(p0, slope, strict=True)))

    k1 = rhs(0.0, ex, ey)
    while t < dt:
        if used >= budget:
            raise ConvergenceError(
                f"journal orbit: step budget ({budget}) exhausted at t = {t0 + t:.6g} s, "
                f"eps = {math.hypot(ex, ey):.12f}; loosen tol or check the load units")
        used += 1
        h = min(h, dt - t)
        if dt - t - h < 1e-12 * dt:
            h = dt - t
        ks = [k1]
        ok = True
        for i in range(1, 7):
            a = _A[i]
            xs = ex + h * sum(a[j] * ks[j][0] for j in range(i))
            ys = ey + h * sum(a[j] * ks[j][1] for j in range(i))
            if math.hypot(xs, ys) >= EPS_LIMIT:
                ok = False
                break
            ks.append(rhs(t + _C[i] * h, xs, ys))
        if not ok:
            h *= 0.25
            continue
        # ks[6] was evaluated at the 5th-order solution (FSAL).
        x5, y5 = xs, ys
        errx = h * sum(c * k[0] for c, k in zip(_E, ks, strict=False))
        erry = h * sum(c * k[1] for c, k in zip(_E, ks, strict=False))
        err = max(abs(errx), abs(erry)) / tol
        if err <= 1.0:
            t += h
            ex, ey = x5, y5
            k1 = ks[6]
        h *= min(5.0, max(0.2, 0.9 * (err + 1e-300) ** -0.2))
    return (ex, ey), h, used


def bearing_orbit(bearing: JournalBearing, load_x, load_y, angle_grid, omega_journal,
                  omega_bearing=0.0, *, angle_rate=None, period: float = 2.0 * math.pi,
                  film: str = "pi", terms: str = "shear", mobility: str = "exact",
                  mobility_scale: float = 1.0, tol: float = 1e-7, period_tol: float = 1e-5,
                  max_cycles: int = 20, start: str = "steady",
                  max_steps_per_cycle: int = 200_000) -> JournalOrbit:
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
        mobility: "exact" pi-film inversion (Ball's recipe) or "booker" (Yang eqs 1.15/1.16).
        mobility_scale: multiplies the mobility; 0.5 mimics Yang's program (reference note,
            Yang §4.6 reproduction), 1.0 is the physics.
        tol: absolute error per step on eps (resolution knob).
        period_tol: cycle-to-cycle change on eps that counts as periodic.
        max_cycles: give up (ConvergenceError) after this many cycles.
        start: "steady" (quasi-static eps at the first angle) or "centre" (eps = 0, Yang).
    """
    film, terms = check_film(film), check_terms(terms)
    if mobility not in MOBILITIES:
        raise field_error("mobility", "unknown mobility", mobility, " or ".join(MOBILITIES))
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
    wbar = 0.5 * (wj + wb)
    t = (th - th[0]) / angle_rate
    T = period / angle_rate
    n = th.size
    f = _Field(bearing, mobility, mobility_scale)
    if start == "steady":
        from .steady import steady_eccentricity_vector
        y = steady_eccentricity_vector(bearing, fx[0], fy[0], wbar[0])
    else:
        y = (0.0, 0.0)
    pts = [(fx[i], fy[i], wbar[i]) for i in range(n)]
    dts = np.append(np.diff(t), T - t[-1])
    h = float(dts[0])
    prev = None
    change = math.inf
    cycles = 0
    for cycles in range(1, int(max_cycles) + 1):  # noqa: B007 (count reported)
        cur = np.empty((n, 2))
        budget = max_steps_per_cycle
        for i in range(n):
            cur[i] = y
            y, h, used = _march(f, y, float(t[i]), float(dts[i]), pts[i], pts[(i + 1) % n], h,
                                tol, budget)
            budget -= used
            h = max(h, 1e-9 * float(dts[i]))
        if prev is not None:
            change = float(np.max(np.hypot(*(cur - prev).T)))
            if change <= period_tol:
                break
        prev = cur
    if change > period_tol:
        raise ConvergenceError(
            f"journal orbit not periodic after {cycles} cycles: change {change:.3g} > "
            f"period_tol {period_tol:.3g}; raise max_cycles or period_tol")
    vel = np.array([f.squeeze(cur[i, 0], cur[i, 1], fx[i], fy[i], wbar[i]) for i in range(n)])
    return _finish(bearing, th, t, T, fx, fy, cur[:, 0], cur[:, 1], vel, wj - wb, film, terms,
                   f"mobility-{mobility}", cycles, change, True)


def _finish(bearing, th, t, T, fx, fy, ex, ey, vel, wrel, film, terms, method, cycles, change,
            converged) -> JournalOrbit:
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
