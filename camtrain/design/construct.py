"""A lift law from valve events and limits: the acceleration-spline construction.

The lift over the event is a quintic B-spline (its acceleration a cubic spline, its jerk
continuous): the acceleration-spline construction of cam design (Norton 2009, *Cam Design and
Manufacturing Handbook*, 2nd ed.: B-spline cam functions with boundary conditions solved for
their coefficients; de Boor 2001 for the basis). Every event is a linear condition on the
coefficients, every limit a linear inequality at collocation points, and among the curves that
meet them the one with the least jerk energy, integral of l'''^2 d(theta), is taken: a convex
quadratic programme (the smoothness objective of cubic-spline cam synthesis, Yoon & Rao 1993,
*J. Mech. Des.* 115:441-446, and of the optimised piecewise-polynomial cams of Mermelstein &
Acar 2004, *Eng. Comput.* 19:241-254).

Events (all in the units of this module's inputs: mm, cam deg; the nose at 0 deg):

* the lift starts and ends on the base circle with lift, velocity, acceleration and jerk zero
  (the first and last four coefficients are zero, end knots of multiplicity 6);
* the nose: lift = max_lift and velocity 0 at 0 deg, and lift <= max_lift everywhere;
* each checking height: the lift equals it at its opening (and closing) angle;
* each ramp: the lift reaches the ramp height at the ramp's end with the ramp velocity held
  constant over the last two thirds of its lift (the first third is the smooth rise of the
  velocity from zero, so the ramp lasts 4/3 of height / velocity);
* flanks rise and fall monotonically (l' >= 0 before the nose, <= 0 after).

Limits: l'' <= max_acceleration, -l'' <= max_deceleration, |l'''| <= max_jerk, imposed at four
points per knot span with a 0.5 % margin, and at any point of a grid of 16 per span where the
solution still exceeds one. They are solved by cutting planes: a linear programme (HiGHS) first
says whether any lift meets them, then SLSQP solves the programme with the rows violated so far
and rows are added until none is.

Where the ramp ends is not an event: it is first placed where a 3-4-5 polynomial rise (Norton
2009) from the ramp to the nose would pass the lowest checking height above the ramp, then
scaled (both sides together) to the feasible placement of least jerk energy (see
:func:`design_lift`). A checking height on the ramp fixes the ramp end.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from camtrain.numerics.blas_threads import one_blas_thread

#: fraction of the ramp's lift over which its velocity rises from zero
RAMP_RISE = 1.0 / 3.0
#: collocation points per knot span for the limits, and the margin they keep
POINTS_PER_SPAN = 4
LIMIT_MARGIN = 0.005
DEGREE = 5


class DesignInfeasible(Exception):
    """The events and limits admit no lift (a physically impossible request)."""


@dataclass(frozen=True)
class Flank:
    """One side's events: checking heights [mm] at angles from the nose [deg, > 0]; ramp."""

    heights: tuple[float, ...]
    angles: tuple[float, ...]
    ramp_height: float = 0.0
    ramp_velocity: float | None = None      # mm/deg
    ramp_length: float | None = None        # deg

    def ramp(self) -> tuple[float, float]:
        """(velocity [mm/deg], total duration [deg]) of the ramp; (0, 0) without one."""
        if self.ramp_height <= 0.0:
            return 0.0, 0.0
        if self.ramp_velocity is not None:
            return self.ramp_velocity, self.ramp_height / self.ramp_velocity * (1 + RAMP_RISE)
        return self.ramp_height * (1 + RAMP_RISE) / self.ramp_length, self.ramp_length


@dataclass(frozen=True)
class Events:
    """What the lift must give (mm, deg, mm/deg^k; cam angles from the nose)."""

    max_lift: float
    opening: Flank
    closing: Flank
    max_acceleration: float | None = None
    max_deceleration: float | None = None
    max_jerk: float | None = None
    symmetric: bool = False
    spans: int = 40


@dataclass
class Designed:
    """The designed spline (knots [deg], coefficients [mm], degree) and where its ramps end."""

    knots: np.ndarray
    coefficients: np.ndarray
    degree: int
    ramp_ends: tuple[float, float]           # deg from the nose (opening negative)
    energy: float = 0.0                      # jerk energy, integral of jerk^2 [mm^2/deg^5]
    notes: list[str] = field(default_factory=list)


def rise_345(x):
    """The 3-4-5 polynomial rise, 10 x^3 - 15 x^4 + 6 x^5 on [0, 1] (Norton 2009)."""
    return x ** 3 * (10.0 - 15.0 * x + 6.0 * x * x)


def ramp_end(flank: Flank, max_lift: float) -> float:
    """Angle [deg, > 0, from the nose] where the ramp ends (see the module docstring)."""
    from scipy.optimize import brentq

    v, _ = flank.ramp()
    h_r = flank.ramp_height
    for h, a in sorted(zip(flank.heights, flank.angles, strict=True)):
        if h <= h_r and v > 0.0:         # on the constant-velocity ramp: it fixes the end
            return a - (h_r - h) / v
    h, a = min((p for p in zip(flank.heights, flank.angles, strict=True) if p[0] > h_r),
               default=(None, None))
    if h is None:
        return max(flank.angles) * 1.2

    def miss(span):
        return h_r + (max_lift - h_r) * rise_345(1.0 - a / span) - h

    return brentq(miss, a * (1 + 1e-9), 179.0)


def _knots(start: float, end: float, spans: int, symmetric: bool) -> np.ndarray:
    if symmetric:
        half = np.linspace(0.0, end, spans // 2 + 1)
        inner = np.concatenate((-half[:0:-1], half))
    else:
        inner = np.concatenate((np.linspace(start, 0.0, spans // 2 + 1)[:-1],
                                np.linspace(0.0, end, spans // 2 + 1)))
    return np.concatenate(([start] * DEGREE, inner, [end] * DEGREE))


def _basis(t: np.ndarray, x: np.ndarray, nu: int) -> np.ndarray:
    """(len(x), n) matrix of the nu-th derivative of every B-spline basis function at x."""
    from scipy.interpolate import BSpline

    n = t.size - DEGREE - 1
    return BSpline(t, np.eye(n), DEGREE, extrapolate=False)(x, nu=nu)


@one_blas_thread()     # small dense solves in a loop: see camtrain.numerics.blas_threads
def design_lift(ev: Events) -> Designed:
    """The least-jerk-energy quintic spline meeting ``ev``; raises DesignInfeasible.

    The ramp ends (see the module docstring) are scaled together by one factor, chosen among
    the feasible ones for the least jerk energy: a scan of six values, then a bounded
    golden-section refinement (scipy's ``minimize_scalar``) around the best.
    """
    from scipy.optimize import minimize_scalar

    guess = [ramp_end(ev.opening, ev.max_lift), ramp_end(ev.closing, ev.max_lift)]
    fixed = [_ramp_fixed(ev.opening), _ramp_fixed(ev.closing)]
    if all(fixed):
        return _design_at(ev, *guess)
    low = max(_lowest_end(f) / g for f, g, x in zip((ev.opening, ev.closing), guess, fixed,
                                                      strict=True) if not x)
    high = max(low * 1.05, 1.4)
    tried: dict[float, Designed | DesignInfeasible] = {}

    def at(scale: float) -> float:
        if scale not in tried:
            ends = [g if x else g * scale for g, x in zip(guess, fixed, strict=True)]
            try:
                tried[scale] = _design_at(ev, *ends)
            except DesignInfeasible as exc:
                tried[scale] = exc
        got = tried[scale]
        return got.energy if isinstance(got, Designed) else np.inf

    grid = np.linspace(low, high, 6)
    energies = [at(float(x)) for x in grid]
    best = int(np.argmin(energies))
    if not np.isfinite(energies[best]):
        raise next(v for v in tried.values() if isinstance(v, DesignInfeasible))
    a, b = grid[max(best - 1, 0)], grid[min(best + 1, grid.size - 1)]
    minimize_scalar(lambda x: min(at(float(x)), 1e300), bounds=(a, b), method="bounded",
                    options={"xatol": 2e-3, "maxiter": 4})
    return min((v for v in tried.values() if isinstance(v, Designed)), key=lambda d: d.energy)


def _ramp_fixed(flank: Flank) -> bool:
    """True when a checking height on the ramp fixes where the ramp ends."""
    return flank.ramp()[0] > 0.0 and any(h <= flank.ramp_height for h in flank.heights)


def _lowest_end(flank: Flank) -> float:
    """The ramp cannot end before (nearer the nose than) a checking height above it."""
    above = [a for h, a in zip(flank.heights, flank.angles, strict=True)
             if h > flank.ramp_height]
    return max(above) + 0.5 if above else 1.0


def _rows(ev: Events, t: np.ndarray, end_open: float, end_close: float):
    """Equality (A, b) and inequality (G, h: G c <= h) rows of the events and limits."""
    eq_a, eq_b, in_g, in_h = [], [], [], []

    def equal(x, nu, value):
        eq_a.append(_basis(t, np.atleast_1d(float(x)), nu)[0])
        eq_b.append(value)

    n = t.size - DEGREE - 1
    for i in list(range(4)) + list(range(n - 4, n)):       # base circle: l, l', l'', l''' = 0
        row = np.zeros(n)
        row[i] = 1.0
        eq_a.append(row)
        eq_b.append(0.0)
    equal(0.0, 0, ev.max_lift)
    equal(0.0, 1, 0.0)
    for flank, sign, end in ((ev.opening, -1.0, end_open), (ev.closing, 1.0, end_close)):
        for h, a in zip(flank.heights, flank.angles, strict=True):
            equal(sign * a, 0, h)
        v, length = flank.ramp()
        if length > 0.0:
            equal(sign * end, 0, flank.ramp_height)
            constant = flank.ramp_height * (1 - RAMP_RISE) / v
            for x in np.linspace(end, end + constant, 5):
                equal(sign * x, 1, -sign * v)
    x = np.linspace(t[0], t[-1], POINTS_PER_SPAN * ev.spans + 1)[1:-1]
    b0, b1, b2, b3 = (_basis(t, x, nu) for nu in range(4))
    keep = 1.0 - LIMIT_MARGIN
    for g, h in ((b0, np.full(x.size, ev.max_lift)), (-b0, np.zeros(x.size)),
                 (np.where((x < 0)[:, None], -b1, b1), np.zeros(x.size))):
        in_g.append(g)
        in_h.append(h)
    for g, limit in ((b2, ev.max_acceleration), (-b2, ev.max_deceleration), (b3, ev.max_jerk),
                     (-b3, ev.max_jerk)):
        if limit is not None:
            in_g.append(g)
            in_h.append(np.full(x.size, keep * limit))
    return (np.array(eq_a), np.array(eq_b), np.vstack(in_g), np.concatenate(in_h))


def _feasible(G: np.ndarray, h: np.ndarray) -> np.ndarray:
    """A point inside G z <= h, as deep inside as the LP finds (HiGHS), or DesignInfeasible."""
    from scipy.optimize import linprog

    # maximise the slack s of every row (capped): G z + s <= h, s <= 1
    n = G.shape[1]
    cost = np.zeros(n + 1)
    cost[-1] = -1.0
    norms = np.linalg.norm(G, axis=1)[:, None]
    res = linprog(cost, A_ub=np.hstack((G, norms)), b_ub=h,
                  bounds=[(None, None)] * n + [(None, 1e-3)], method="highs")
    if res.status != 0 or res.x[-1] < -1e-9:
        raise DesignInfeasible("no lift meets every event within the limits (the linear "
                               "programme of the events and limits has no solution)")
    return res.x[:n]


def _design_at(ev: Events, end_open: float, end_close: float) -> Designed:
    """The least-jerk-energy spline with the ramps ending at these angles [deg from the nose]."""
    from scipy.linalg import null_space

    if ev.symmetric:
        end_close = end_open
    start = -(end_open + ev.opening.ramp()[1])
    stop = end_close + ev.closing.ramp()[1]
    if start <= -180.0 or stop >= 180.0 or stop - start >= 360.0:
        raise DesignInfeasible(f"the event would span {stop - start:.1f} deg of cam angle")
    t = _knots(start, stop, ev.spans, ev.symmetric)
    A, b, G, h = _rows(ev, t, end_open, end_close)
    n = t.size - DEGREE - 1
    if ev.symmetric:                      # c_i = c_(n-1-i): one flank mirrored
        for i in range(n // 2):
            row = np.zeros(n)
            row[i], row[n - 1 - i] = 1.0, -1.0
            A = np.vstack((A, row))
            b = np.append(b, 0.0)
    xq = np.linspace(t[0], t[-1], 8 * ev.spans + 1)
    b3 = _basis(t, xq, 3)
    Q = b3.T @ b3 * (xq[1] - xq[0])
    # the events fix an affine set c = c_p + N z (redundant rows, e.g. mirrored events of a
    # symmetric design, drop out here); the limits are inequalities on z
    c_p = np.linalg.lstsq(A, b, rcond=None)[0]
    N = null_space(A, rcond=1e-10)
    _feasible(G @ N, h - G @ c_p)       # raises at once when no lift meets the rows
    c, G, h, message = _cutting_planes(ev, t, Q, c_p, N, G, h)
    worst_eq = float(np.max(np.abs(A @ c - b)))
    worst_in = float(np.max(G @ c - h))
    tol = 1e-7 * max(1.0, ev.max_lift)
    if worst_eq > tol or worst_in > tol:
        raise DesignInfeasible(
            f"no lift meets every event within the limits (largest event miss {worst_eq:.3g}, "
            f"largest limit excess {worst_in:.3g} in mm and deg units; {message})")
    c[np.abs(c) < 1e-13] = 0.0
    return Designed(t, c, DEGREE, (-end_open, end_close), float(c @ Q @ c))


def _cutting_planes(ev: Events, t, Q, c_p, N, G, h):
    """Minimise c'Qc over c = c_p + N z subject to G c <= h: solve with the rows violated so
    far, add the rows the solution violates (the collocation rows, then any excess a grid of
    16 points per span finds), until none is; SLSQP sees only the rows that matter.
    Returns (c, G, h with the added rows, the last solver message)."""
    scale = 1.0 / max(np.max(np.abs(Q)), 1e-300)
    Qz, gz = N.T @ Q @ N * scale, 2.0 * N.T @ Q @ c_p * scale
    fine = np.linspace(t[0], t[-1], 16 * ev.spans + 1)
    z = np.linalg.lstsq(2.0 * Qz, -gz, rcond=None)[0]
    active = np.zeros(h.size, dtype=bool)
    message = "no limit active"
    for _ in range(40):
        c = c_p + N @ z
        new = (G @ c - h > 1e-9 * np.maximum(1.0, np.abs(h))) & ~active
        if not np.any(new):
            extra_g, extra_h = _excess_rows(ev, t, fine, c)
            if extra_g is None:
                break
            G, h = np.vstack((G, extra_g)), np.concatenate((h, extra_h))
            active = np.concatenate((active, np.zeros(extra_h.size, dtype=bool)))
            new = np.zeros(h.size, dtype=bool)
            new[-extra_h.size:] = True
        active |= new
        res = _qp(Qz, gz, G[active] @ N, h[active] - G[active] @ c_p, z)
        z, message = res.x, str(res.message)
    return c_p + N @ z, G, h, message


def _qp(Q: np.ndarray, g: np.ndarray, G: np.ndarray, h: np.ndarray, start: np.ndarray):
    """min z'Qz + g'z subject to G z <= h, by SLSQP (scipy) from ``start``."""
    from scipy.optimize import minimize

    return minimize(lambda z: z @ Q @ z + g @ z, start, jac=lambda z: 2.0 * (Q @ z) + g,
                    method="SLSQP", constraints=[{"type": "ineq", "fun": lambda z: h - G @ z,
                                                  "jac": lambda z: -G}],
                    options={"maxiter": 1000, "ftol": 1e-12})



def _excess_rows(ev: Events, t: np.ndarray, x: np.ndarray, c: np.ndarray):
    """Limit rows at the fine-grid points where ``c`` exceeds a limit (None: none does)."""
    rows_g, rows_h = [], []
    for nu, limit, sign in ((2, ev.max_acceleration, 1.0), (2, ev.max_deceleration, -1.0),
                            (3, ev.max_jerk, 1.0), (3, ev.max_jerk, -1.0)):
        if limit is None:
            continue
        basis = sign * _basis(t, x, nu)
        over = basis @ c > limit
        if np.any(over):
            rows_g.append(basis[over])
            rows_h.append(np.full(int(over.sum()), (1.0 - LIMIT_MARGIN) * limit))
    if not rows_g:
        return None, None
    return np.vstack(rows_g), np.concatenate(rows_h)
