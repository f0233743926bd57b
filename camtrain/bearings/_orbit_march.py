"""Compiled march of the journal orbit (numba, cached on disk, ``cache=True``).

The algorithm is the one documented in :mod:`camtrain.bearings.orbit`: embedded Dormand-Prince
5(4) with absolute error control on eps, steps that would reach EPS_LIMIT quartered, cycles until
two agree to ``period_tol``. The load and speeds come as one cubic per load interval (linear, or
:func:`periodic_spline`, or the shape-preserving Hermite of ``orbit.periodic_pchip``). The steps
either end on every grid angle (:func:`_grid_cycle`) or run free of the load grid
(:func:`_free_cycle`: a step ends on the last grid angle it reaches, the grid angles inside it
sampled by the continuous extension, and from the third cycle each cycle first replays the
previous cycle's steps). The mobility is :func:`._orbit_kernel._squeeze`.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from camtrain.numerics.compile_notice import announce

from ._orbit_kernel import BUDGET, NOT_PERIODIC, OFF_MAP, OK, STALL_CYCLES, _squeeze, steady_start

# Dormand-Prince 5(4) tableau (rows of A padded with zeros).
_C = np.array([0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0, 1.0])
_A = np.array([
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [1 / 5, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3 / 40, 9 / 40, 0.0, 0.0, 0.0, 0.0],
    [44 / 45, -56 / 15, 32 / 9, 0.0, 0.0, 0.0],
    [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729, 0.0, 0.0],
    [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656, 0.0],
    [35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84]])
_E = np.array([71 / 57600, 0.0, -71 / 16695, 71 / 1920, -17253 / 339200, 22 / 525, -1 / 40])
#: continuous extension of the 5(4) pair (Shampine 1986; Hairer, Norsett & Wanner, Solving ODEs
#: I, §II.6; the coefficients of scipy's RK45): y(t + theta h) = y + h sum_q k_q sum_j P[q, j]
#: theta^(j + 1), 4th order in h; theta = 1 gives the step's end
_P = np.array([
    [1.0, -8048581381 / 2820520608, 8663915743 / 2820520608, -12715105075 / 11282082432],
    [0.0, 0.0, 0.0, 0.0],
    [0.0, 131558114200 / 32700410799, -68118460800 / 10900136933, 87487479700 / 32700410799],
    [0.0, -1754552775 / 470086768, 14199869525 / 1410260304, -10690763975 / 1880347072],
    [0.0, 127303824393 / 49829197408, -318862633887 / 49829197408,
     701980252875 / 199316789632],
    [0.0, -282668133 / 205662961, 2019193451 / 616988883, -1453857185 / 822651844],
    [0.0, 40617522 / 29380423, -110615467 / 29380423, 69997945 / 29380423]])
#: cycles marched with free steps before a cycle replays the previous one's steps: the first
#: two bring the orbit near its attractor (a step sequence of the start's transient would be
#: needlessly fine)
REPLAY_FROM = 3
#: a stage off a tabulated mobility map rejects its step until the step is this fraction of the
#: cycle (or of the load interval): a long trial step may probe beyond the orbit, a short one
#: that still leaves the map follows an orbit that does
_MAP_STEP = 1e-6

@njit(cache=True, error_model="numpy")
def linear_coefficients(t, period, fx, fy, wbar):
    """Coefficients (n, 4, 3) of the load x, y and wbar linear in each interval of the times t
    (cycle ``period``): c0 the value at the interval's start, c1 the slope, c2 = c3 = 0."""
    n = t.size
    coef = np.zeros((n, 4, 3))
    for i in range(n):
        j = i + 1 if i + 1 < n else 0
        dt = (t[i + 1] if i + 1 < n else period) - t[i]
        coef[i, 0, 0], coef[i, 0, 1], coef[i, 0, 2] = fx[i], fy[i], wbar[i]
        coef[i, 1, 0] = (fx[j] - fx[i]) / dt
        coef[i, 1, 1] = (fy[j] - fy[i]) / dt
        coef[i, 1, 2] = (wbar[j] - wbar[i]) / dt
    return coef


@njit(cache=True, error_model="numpy")
def periodic_spline(t, period, f):
    """Periodic cubic spline (C2) through the columns of ``f`` (n, m) at times ``t`` (n,
    increasing, t[n-1] < t[0] + period): coefficients (n, 4, m) of c0 + s (c1 + s (c2 + s c3))
    in each interval, s the time since its start. The second derivatives M solve the cyclic
    tridiagonal system h[i-1] M[i-1] + 2 (h[i-1] + h[i]) M[i] + h[i] M[i+1] = 6 (d[i] - d[i-1])
    (d the interval slopes), by the Thomas algorithm with the Sherman-Morrison correction for
    the corners (the system is strictly diagonally dominant)."""
    n, m = f.shape
    h = np.empty(n)
    for i in range(n - 1):
        h[i] = t[i + 1] - t[i]
    h[n - 1] = t[0] + period - t[n - 1]
    d = np.empty((n, m))
    for i in range(n):
        for c in range(m):
            d[i, c] = (f[(i + 1) % n, c] - f[i, c]) / h[i]
    mm = np.zeros((n, m))
    if n >= 3:
        # rows i: sub a = h[i-1], diag b = 2 (h[i-1] + h[i]), super c = h[i]; corners a[0], c[n-1]
        a = np.empty(n)
        b = np.empty(n)
        cc = np.empty(n)
        for i in range(n):
            a[i] = h[i - 1]     # h[-1] is h[n-1]: the periodic neighbour
            b[i] = 2.0 * (h[i - 1] + h[i])
            cc[i] = h[i]
        gamma = -b[0]
        bb = b.copy()
        bb[0] -= gamma
        bb[n - 1] -= a[0] * cc[n - 1] / gamma
        rhs = np.empty((n, m))
        u = np.zeros(n)
        u[0], u[n - 1] = gamma, cc[n - 1]
        for i in range(n):
            for c in range(m):
                rhs[i, c] = 6.0 * (d[i, c] - d[i - 1, c])
        # forward sweep, shared by the m right-hand sides and u
        cp = np.empty(n)
        cp[0] = cc[0] / bb[0]
        for c in range(m):
            rhs[0, c] /= bb[0]
        u[0] /= bb[0]
        for i in range(1, n):
            den = bb[i] - a[i] * cp[i - 1]
            cp[i] = cc[i] / den
            for c in range(m):
                rhs[i, c] = (rhs[i, c] - a[i] * rhs[i - 1, c]) / den
            u[i] = (u[i] - a[i] * u[i - 1]) / den
        for i in range(n - 2, -1, -1):
            for c in range(m):
                rhs[i, c] -= cp[i] * rhs[i + 1, c]
            u[i] -= cp[i] * u[i + 1]
        vu = u[0] + a[0] / gamma * u[n - 1]
        for c in range(m):
            k = (rhs[0, c] + a[0] / gamma * rhs[n - 1, c]) / (1.0 + vu)
            for i in range(n):
                mm[i, c] = rhs[i, c] - k * u[i]
    coef = np.zeros((n, 4, m))
    for i in range(n):
        j = (i + 1) % n
        for c in range(m):
            coef[i, 0, c] = f[i, c]
            coef[i, 1, c] = d[i, c] - h[i] * (2.0 * mm[i, c] + mm[j, c]) / 6.0
            coef[i, 2, c] = 0.5 * mm[i, c]
            coef[i, 3, c] = (mm[j, c] - mm[i, c]) / (6.0 * h[i])
    return coef


@njit(cache=True, error_model="numpy")
def _load(coef, seg, s):
    """Load x, y and wbar at time s into load interval ``seg``: the piecewise cubic
    c0 + s (c1 + s (c2 + s c3)) of that interval (a linear diagram has c2 = c3 = 0)."""
    c = coef[seg]
    return (c[0, 0] + s * (c[1, 0] + s * (c[2, 0] + s * c[3, 0])),
            c[0, 1] + s * (c[1, 1] + s * (c[2, 1] + s * c[3, 1])),
            c[0, 2] + s * (c[1, 2] + s * (c[2, 2] + s * c[3, 2])))


@njit(cache=True, error_model="numpy")
def _rhs(seg, s, x, y, coef, mob, state):
    """The orbit's rate at time s into load interval ``seg`` (``mob``: the mobility record,
    :data:`._orbit_kernel.Mobility`)."""
    wx, wy, wb = _load(coef, seg, s)
    vx, vy, _ = _squeeze(x, y, wx, wy, wb, mob.kind, mob.gain, state, mob.t_eps, mob.t_mxi,
                         mob.t_mmu)
    return vx - wb * y, vy + wb * x


@njit(cache=True, error_model="numpy")
def _segment(t, seg, tt):
    """Load interval holding time tt, searched forward from ``seg`` (the march only advances)."""
    n = t.size
    while seg + 1 < n and t[seg + 1] <= tt:
        seg += 1
    return seg


@njit(cache=True, error_model="numpy")
def _dense(ex, ey, h, theta, ks):
    """Dormand-Prince continuous extension (4th order) at fraction theta of an accepted step
    from (ex, ey) of length h; ks[6] is the right-hand side at the step's end."""
    w1, w2, w3, w4 = theta, theta * theta, theta ** 3, theta ** 4
    dx, dy = 0.0, 0.0
    for q in range(7):
        b = _P[q, 0] * w1 + _P[q, 1] * w2 + _P[q, 2] * w3 + _P[q, 3] * w4
        dx += b * ks[q, 0]
        dy += b * ks[q, 1]
    return ex + h * dx, ey + h * dy


@njit(cache=True, error_model="numpy")
def _step(ex, ey, h, tl, seg, free, t, coef, ks, mob, state, eps_limit, tol):
    """One Dormand-Prince step of length h from (ex, ey) at time tl (ks[0] holds the
    right-hand side there): stages into ks. Returns (end x, end y, error / tol, inside), inside
    False when a stage or the end would reach eps_limit (the mobility is not evaluated there).
    ``free``: the time is the cycle's (the load interval of each stage is searched from
    ``seg``); else it is the time since the start of load interval ``seg``."""
    xs, ys = ex, ey
    for st in range(1, 7):
        sx, sy = 0.0, 0.0
        for q in range(st):
            sx += _A[st, q] * ks[q, 0]
            sy += _A[st, q] * ks[q, 1]
        xs, ys = ex + h * sx, ey + h * sy
        if math.hypot(xs, ys) >= eps_limit:
            return xs, ys, np.inf, False
        tt = tl + _C[st] * h
        ss = seg
        if free:
            ss = _segment(t, seg, tt)
            tt -= t[ss]
        ks[st, 0], ks[st, 1] = _rhs(ss, tt, xs, ys, coef, mob, state)
    errx, erry = 0.0, 0.0
    for q in range(7):
        errx += _E[q] * ks[q, 0]
        erry += _E[q] * ks[q, 1]
    return xs, ys, max(abs(h * errx), abs(h * erry)) / tol, True


@njit(cache=True, error_model="numpy")
def _grow(h, err):
    """Next step after one with error ratio err (the usual 5th-order controller, 0.2x-5x)."""
    return h * min(5.0, max(0.2, 0.9 * (err + 1e-300) ** -0.2))


@njit(cache=True, error_model="numpy")
def _step_end(t, period, seg, tl, h):
    """End of a free step of at most h from tl (in load interval seg): the last grid angle it
    reaches, or tl + h when it stays inside its interval. A step shorter than an interval
    therefore never crosses a grid angle (where a linear load has its kink); a longer one
    crosses those inside it only where the error estimate lets the step be that long."""
    slack = 1e-12 * period
    target = tl + h
    if target >= period - slack:
        return period
    k = _segment(t, seg, target + slack)
    return t[k] if k > seg else target


@njit(cache=True, error_model="numpy")
def _grid_cycle(cur, ex, ey, h, t, dts, coef, ks, mob, state, eps_limit, tol, budget):
    """One cycle marched interval by interval (a piecewise-linear load: every step ends on a
    grid angle). Returns (ex, ey, h, status, time of a failure, accepted steps)."""
    n = t.size
    steps = 0
    for i in range(n):
        cur[i, 0], cur[i, 1] = ex, ey
        dt = dts[i]
        tl, used = 0.0, 0
        k1x, k1y = _rhs(i, 0.0, ex, ey, coef, mob, state)
        while tl < dt:
            if used >= budget:
                return ex, ey, h, BUDGET, t[i] + tl, steps
            used += 1
            h = min(h, dt - tl)
            if dt - tl - h < 1e-12 * dt:
                h = dt - tl
            ks[0, 0], ks[0, 1] = k1x, k1y
            xs, ys, err, inside = _step(ex, ey, h, tl, i, False, t, coef, ks, mob, state,
                                        eps_limit, tol)
            if state[2] > 0.0:
                if h > _MAP_STEP * dts[i]:  # a trial stage off the map: retry shorter
                    state[2] = 0.0
                    h *= 0.25
                    continue
                return xs, ys, h, OFF_MAP, t[i] + tl, steps
            if not inside:
                h *= 0.25
                continue
            if err <= 1.0:
                steps += 1
                tl += h
                ex, ey = xs, ys
                k1x, k1y = ks[6, 0], ks[6, 1]
            h = _grow(h, err)
        budget -= used
        h = max(h, 1e-9 * dt)
    return ex, ey, h, OK, 0.0, steps


@njit(cache=True, error_model="numpy")
def _free_cycle(cur, ex, ey, h, t, period, coef, ks, ends, m, mob, state, eps_limit,
                tol, budget):
    """One cycle with steps free of the load grid (a smooth load), the grid samples from the
    continuous extension. ``ends[:m]``: the step ends of the previous cycle, replayed while
    their steps pass the error test (m = 0: none); the first failing step hands over to the
    controller for the rest of the cycle. Replaying makes a settled cycle the same map of its
    start every time, so the cycle-to-cycle change falls to zero instead of sitting at the
    step error (steps placed afresh each cycle would move the samples by about the error).
    Returns (ex, ey, h, status, time of a failure, accepted steps = the new m, ends (grown
    when this cycle took more steps than it held))."""
    n = t.size
    cur[0, 0], cur[0, 1] = ex, ey
    nxt, seg, tl, used, steps = 1, 0, 0.0, 0, 0
    replay = m > 0
    k1x, k1y = _rhs(0, 0.0, ex, ey, coef, mob, state)
    while tl < period:
        if used >= budget:
            return ex, ey, h, BUDGET, tl, steps, ends
        used += 1
        end = ends[steps] if replay else _step_end(t, period, seg, tl, h)
        h = end - tl
        ks[0, 0], ks[0, 1] = k1x, k1y
        xs, ys, err, inside = _step(ex, ey, h, tl, seg, True, t, coef, ks, mob, state,
                                    eps_limit, tol)
        if state[2] > 0.0:
            if h > _MAP_STEP * period:  # a trial stage off the map: retry shorter
                state[2] = 0.0
                replay = False
                h *= 0.25
                continue
            return xs, ys, h, OFF_MAP, tl, steps, ends
        if not inside:
            replay = False
            h *= 0.25
            continue
        if err <= 1.0:
            while nxt < n and t[nxt] < end:  # grid samples inside the step
                cur[nxt, 0], cur[nxt, 1] = _dense(ex, ey, h, (t[nxt] - tl) / h, ks)
                nxt += 1
            if nxt < n and t[nxt] == end:   # the step ends on a grid angle
                cur[nxt, 0], cur[nxt, 1] = xs, ys
                nxt += 1
            if steps == ends.size:  # room for more steps than the last cycle's
                grown = np.empty(2 * ends.size)
                grown[:steps] = ends[:steps]
                ends = grown
            ends[steps] = end
            steps += 1
            replay = replay and steps < m
            tl = end
            seg = _segment(t, seg, tl)
            ex, ey = xs, ys
            k1x, k1y = ks[6, 0], ks[6, 1]
        else:
            replay = False
        h = _grow(h, err)
    return ex, ey, h, OK, 0.0, steps, ends


@njit(cache=True, error_model="numpy")
def march_orbit(coef, t, dts, period, y0x, y0y, grid_steps, mob, tol, period_tol,
                max_cycles, max_steps, eps_limit):
    """Periodic orbit sampled on the load grid ``t`` (time from the first angle; cycle length
    ``period``; dts the interval lengths).

    ``coef`` (n, 4, 3): load x, y and wbar in each load interval as a cubic in the time since
    its start (:func:`periodic_spline`, or linear with c2 = c3 = 0). ``grid_steps``: every step
    ends on a grid angle (a linear load: its kinks would cut the order of a step across them);
    else the steps run free of the grid. Returns (eps (n, 2), squeeze (n, 3) = [vx, vy, delta]
    at the grid points, cycles, change, status, time and |eps| where a march failed, accepted
    steps in the last cycle).
    """
    n = t.size
    state = np.zeros(3)
    cur = np.empty((n, 2))
    prev = np.empty((n, 2))
    ks = np.empty((7, 2))
    ends = np.empty(4 * n + 64)   # step ends of the last free cycle (grown when needed)
    ex, ey = y0x, y0y
    h = dts[0]
    change = np.inf
    cycles, steps = 0, 0
    best, best_cycle = np.inf, 0
    for cyc in range(1, max_cycles + 1):
        cycles = cyc
        if grid_steps:
            ex, ey, h, status, t_fail, steps = _grid_cycle(
                cur, ex, ey, h, t, dts, coef, ks, mob, state, eps_limit, tol, max_steps)
        else:
            ex, ey, h, status, t_fail, steps, ends = _free_cycle(
                cur, ex, ey, h, t, period, coef, ks, ends, steps if cyc >= REPLAY_FROM else 0,
                mob, state, eps_limit, tol, max_steps)
        if status != OK:
            return cur, np.empty((0, 3)), cycles, change, status, t_fail, math.hypot(ex, ey), \
                steps
        if cyc > 1:
            change = 0.0
            for i in range(n):
                change = max(change, math.hypot(cur[i, 0] - prev[i, 0], cur[i, 1] - prev[i, 1]))
            if change <= period_tol:
                break
            if change < best:
                best, best_cycle = change, cyc
            elif cyc - best_cycle >= STALL_CYCLES:
                break   # the change stopped falling: it sits at the march's own error
        prev[:, :] = cur
    vel = np.empty((n, 3))
    for i in range(n):
        wx, wy, wb = _load(coef, i, 0.0)
        vel[i, 0], vel[i, 1], vel[i, 2] = _squeeze(cur[i, 0], cur[i, 1], wx, wy, wb, mob.kind,
                                                   mob.gain, state, mob.t_eps, mob.t_mxi,
                                                   mob.t_mmu)
    status = OK if change <= period_tol else NOT_PERIODIC
    return cur, vel, cycles, change, status, 0.0, 0.0, steps


announce("journal-orbit", (march_orbit, linear_coefficients, periodic_spline, steady_start))
