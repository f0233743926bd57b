"""Compiled mobility of the journal orbit (numba, cached on disk, ``cache=True``); the march
itself is :mod:`camtrain.bearings._orbit_march`.

The mobilities are those of :mod:`camtrain.bearings.mobility` (exact pi-film inversion, Booker's
closed form) plus a tabulated map (:class:`camtrain.bearings.mobility_map.MobilityMap`). Only
this module and the march import numba, and only decks that march an orbit import them, so the
CLI start of other decks does not pay for numba. Errors come back as status codes; the Python
side turns them into ConvergenceError.
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit

EXACT, BOOKER, TABLE = 0, 1, 2
OK, BUDGET, NOT_PERIODIC, OFF_MAP = 0, 1, 2, 3
#: cycles without a new smallest cycle-to-cycle change after which the march gives up: a change
#: that converges falls every cycle; one that sits at the step error never reaches period_tol
STALL_CYCLES = 10
#: the mobility of the compiled march as one typed record: ``kind`` (EXACT, BOOKER, TABLE), its
#: ``gain`` (the scale of the mobility: see orbit.py), the map's tables eps, m_xi, m_mu (empty
#: without a map)
Mobility = namedtuple("Mobility", "kind gain t_eps t_mxi t_mmu")

_TWO_PI = 2.0 * math.pi
_HALF_PI = 0.5 * math.pi


@njit(cache=True, error_model="numpy")
def _remainder(x, y):
    """IEEE remainder x - y rint(x / y) (math.remainder)."""
    return x - y * np.rint(x / y)


@njit(cache=True, error_model="numpy")
def _sommerfeld(s, c, m):
    """Sommerfeld angle gamma (mobility._sommerfeld) with its sine and cosine, from the scaled
    half-angle vector (s, c) = (k sin(b0/2), cos(b0/2)), b0 = beta - 2 pi m in [-pi, pi]."""
    r2 = s * s + c * c
    return 2.0 * math.atan2(s, c) + _TWO_PI * m, 2.0 * s * c / r2, (c * c - s * s) / r2


@njit(cache=True, error_model="numpy")
def _kd(eps, delta, k, q25, q2, q15):
    """K d and det K in the line-of-centres frame (mobility._kd, pi film).

    The film window runs from beta0 = delta + pi/2 to beta0 + pi. One sine and one cosine of
    the wrapped half angle h0 = beta0/2 - pi m0 give everything else: the half angle of the
    window's end is h0 + pi/2 (less pi when it wraps one more turn), and cos(delta) = sin(2 h0),
    sin(delta) = -cos(2 h0) (the march spends its time in this function). ``k`` =
    sqrt((1 - eps)/(1 + eps)) and ``q25``, ``q2``, ``q15`` = (1 - eps^2)^(5/2, 2, 3/2) depend on
    eps only: the Newton iteration of one mobility forms them once."""
    a = delta + _HALF_PI
    m0 = np.rint(a / _TWO_PI)
    m1 = np.rint((a + math.pi) / _TWO_PI)
    h0 = 0.5 * (a - _TWO_PI * m0)
    sh, ch = math.sin(h0), math.cos(h0)
    flip = 1.0 if m1 == m0 else -1.0    # h1 = h0 + pi/2 - pi (m1 - m0)
    g0, s0, c0 = _sommerfeld(k * sh, ch, m0)
    g1, s1, c1 = _sommerfeld(flip * k * ch, -flip * sh, m1)
    dg = g1 - g0
    d2 = 0.5 * (s1 * c1 - s0 * c0)
    icc = (0.5 * dg + d2 - 2.0 * eps * (s1 - s0) + eps * eps * dg) / q25
    ics = (0.5 * (s1 * s1 - s0 * s0) + eps * (c1 - c0)) / q2
    iss = (0.5 * dg - d2) / q15
    cd, sd = 2.0 * sh * ch, sh * sh - ch * ch
    return icc * cd + ics * sd, ics * cd + iss * sd, icc * iss - ics * ics


@njit(cache=True, error_model="numpy")
def _mobility_exact(eps, tau, delta0, warm):
    """(delta, m) of mobility.mobility_exact (safeguarded Newton, tol 1e-13)."""
    tol = 1e-13
    lo, hi = tau - _HALF_PI, tau + _HALF_PI
    x = delta0 if (warm and lo < delta0 < hi) else tau
    ct, st = math.cos(tau), math.sin(tau)
    k = math.sqrt((1.0 - eps) / (1.0 + eps))
    q = 1.0 - eps * eps
    q25, q2, q15 = q ** 2.5, q ** 2, q ** 1.5
    for _ in range(100):
        fx, fy, det = _kd(eps, x, k, q25, q2, q15)
        g = math.atan2(ct * fy - st * fx, ct * fx + st * fy)
        if g > 0.0:
            hi = x
        else:
            lo = x
        if abs(g) < tol:
            return x, 1.0 / math.hypot(fx, fy)  # K d at this x is already known
        xn = x - g * (fx * fx + fy * fy) / det
        x = xn if lo < xn < hi else 0.5 * (lo + hi)
        if hi - lo < tol:
            break
    fx, fy, _ = _kd(eps, x, k, q25, q2, q15)
    return x, 1.0 / math.hypot(fx, fy)


@njit(cache=True, error_model="numpy")
def _table(xi, mu, t_eps, t_mxi, t_mmu):
    """Bilinear (eps, angle) interpolation of a tabulated map in the load frame; the angle grid
    is uniform over one turn, periodic. Returns (M_xi, M_mu, inside)."""
    r = math.hypot(xi, mu)
    n = t_eps.size
    if r > t_eps[n - 1]:
        return 0.0, 0.0, False
    i = min(max(np.searchsorted(t_eps, r, side="right") - 1, 0), n - 2)
    u = (r - t_eps[i]) / (t_eps[i + 1] - t_eps[i])
    nphi = t_mxi.shape[1]
    phi = math.atan2(mu, xi) % _TWO_PI
    s = phi * nphi / _TWO_PI
    j = int(math.floor(s))
    v = s - j
    j %= nphi
    j1 = (j + 1) % nphi
    mxi = ((1 - u) * ((1 - v) * t_mxi[i, j] + v * t_mxi[i, j1])
           + u * ((1 - v) * t_mxi[i + 1, j] + v * t_mxi[i + 1, j1]))
    mmu = ((1 - u) * ((1 - v) * t_mmu[i, j] + v * t_mmu[i, j1])
           + u * ((1 - v) * t_mmu[i + 1, j] + v * t_mmu[i + 1, j1]))
    return mxi, mmu, True


@njit(cache=True, error_model="numpy")
def _squeeze(ex, ey, wx, wy, wbar, kind, gain, state, t_eps, t_mxi, t_mmu):
    """Mobility velocity (1/s) and its angle from the line of centres; ``state`` holds the
    exact mobility's warm start [delta, has_delta] and the off-map flag."""
    load = math.hypot(wx, wy)
    e = math.hypot(ex, ey)
    if load == 0.0:
        return 0.0, 0.0, -math.copysign(_HALF_PI, wbar if wbar != 0.0 else 1.0)
    lam = math.atan2(wy, wx)
    psi = math.atan2(ey, ex) if e > 0.0 else lam
    if kind == EXACT:
        tau = _remainder(lam - psi, _TWO_PI)
        delta, m = _mobility_exact(e, tau, state[0], state[1] > 0.0)
        state[0] = delta
        state[1] = 1.0
        speed = gain * m * load
        ang = psi + delta
        return speed * math.cos(ang), speed * math.sin(ang), delta
    s = 1.0 if wbar >= 0.0 else -1.0
    ux, uy = wx / load, wy / load
    nx, ny = -s * uy, s * ux
    xi, mu = ex * ux + ey * uy, ex * nx + ey * ny
    if kind == BOOKER:
        q = 1.0 - xi
        mxi, mmu = q ** 2.5 / math.pi, -4.0 * mu * q ** 1.5 / math.pi ** 2
    else:
        mxi, mmu, inside = _table(xi, mu, t_eps, t_mxi, t_mmu)
        if not inside:
            state[2] = 1.0
    g = gain * load
    vx, vy = g * (mxi * ux + mmu * nx), g * (mxi * uy + mmu * ny)
    return vx, vy, _remainder(math.atan2(vy, vx) - psi, _TWO_PI)


@njit(cache=True, error_model="numpy")
def steady_start(wx, wy, wbar, ocvirk_k):
    """Quasi-static eps vector for the load (wx, wy): the Ocvirk load inverted by the 64-step
    bisection of formulas.bearings.ocvirk_eccentricity, turned by the Ocvirk attitude angle in
    the sense of wbar (steady.steady_eccentricity_vector). ``ocvirk_k`` = eta r land^3 / (2 c^2)
    per land (the Ocvirk load at journal speed 2 |wbar| is |wbar| ocvirk_k shape(eps))."""
    load = math.hypot(wx, wy)
    if load == 0.0 or wbar == 0.0:
        return 0.0, 0.0
    target = load / (abs(wbar) * ocvirk_k)
    lo, hi = 0.0, 1.0
    top = np.nextafter(1.0, 0.0)
    for _ in range(64):
        mid = min(0.5 * (lo + hi), top)
        q = 1.0 - mid ** 2
        if mid / q ** 2 * math.sqrt(math.pi ** 2 * q + 16.0 * mid ** 2) > target:
            hi = mid
        else:
            lo = mid
    e = 0.5 * (lo + hi)
    att = math.atan2(math.pi * math.sqrt(1.0 - e ** 2), 4.0 * e)
    ang = math.atan2(wy, wx) + math.copysign(att, wbar)
    return e * math.cos(ang), e * math.sin(ang)


@njit(cache=True, error_model="numpy")
def squeeze_velocities(ex, ey, fx, fy, wbar, kind, gain, t_eps, t_mxi, t_mmu):
    """Mobility velocity [vx, vy, delta] at each point of a given eccentricity path (the orbit
    marched on a coarser load grid, interpolated onto the run's grid): as the end of
    :func:`march_orbit`, with the load and speed of each point."""
    n = ex.size
    state = np.zeros(3)
    vel = np.empty((n, 3))
    for i in range(n):
        vel[i, 0], vel[i, 1], vel[i, 2] = _squeeze(ex[i], ey[i], fx[i], fy[i], wbar[i], kind,
                                                   gain, state, t_eps, t_mxi, t_mmu)
    return vel
