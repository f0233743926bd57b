"""Compiled scalar kernel of the ring film and its time march (numba, cached on disk).

The equations are documented where they are used from Python: :mod:`camtrain.piston.ring_face`
(the closed-form integrals), :mod:`camtrain.piston.ring_film` (one instant) and
:mod:`camtrain.piston.ring` (the march). A ring cycle evaluates the film ~50 000 times; as
plain Python that took ~8 s per ring-cycle, compiled it takes milliseconds.
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit

from camtrain.numerics.compile_notice import announce
from camtrain.numerics.roots import false_position_mean, illinois_update
from camtrain.piston.film_floor import FILM_FLOOR

RUPTURE_SCAN = 16
#: Films below this [m] count as equal in the cyclic convergence of a self-fed ring: a dry ring
#: (the march's floor is 0.1 nm), three orders below any ring's roughness.
FILM_SCALE = 1e-9
#: Bounds of the film march [ln m]: 0.1 nm (a dry ring, all boundary) to 1 mm.
LOG_H_MIN = math.log(FILM_FLOOR)
LOG_H_MAX = math.log(1e-3)


#: the ring's geometry as the compiled march takes it: axial height [m], crown radius [m],
#: crown offset x_min [m], tension [N/m], whether the outlet film is striated (Yang's rule)
RingGeometry = namedtuple("RingGeometry", "height radius x_min tension striated")
#: the self-fed ring's supply: per angle the angles (own_from, own_to; -1: not self-fed) and
#: weight of the layer it left itself, and that layer before the march has been there [m]
OwnFeed = namedtuple("OwnFeed", "own_from own_to own_weight own_start")


@njit(cache=True)
def _anti(t):
    q = 1.0 + t * t
    at = math.atan(t)
    return (at, 0.5 * t / q + 0.5 * at, 0.25 * t / (q * q) + 0.375 * t / q + 0.375 * at,
            -0.5 / q, -0.25 / (q * q))


@njit(cache=True)
def integrals(a, c, h_m, x_c, radius):
    """(int 1/h, int 1/h^2, int 1/h^3, int x/h^2, int x/h^3, int x^2/h^3) over [a, c]."""
    s = math.sqrt(2.0 * radius * h_m)
    a1, a2, a3, ak2, ak3 = _anti((a - x_c) / s)
    c1, c2, c3, ck2, ck3 = _anti((c - x_c) / s)
    j1, j2, j3, k2, k3 = c1 - a1, c2 - a2, c3 - a3, ck2 - ak2, ck3 - ak3
    l3 = j2 - j3
    f1, f2, f3 = s / h_m, s / (h_m * h_m), s / (h_m * h_m * h_m)
    return (f1 * j1, f2 * j2, f3 * j3, f2 * (x_c * j2 + s * k2), f3 * (x_c * j3 + s * k3),
            f3 * (x_c * x_c * j3 + 2.0 * x_c * s * k3 + s * s * l3))


@njit(cache=True)
def gap(x, h_m, x_c, radius):
    d = x - x_c
    return h_m + d * d / (2.0 * radius)


@njit(cache=True)
def inlet_position(h_available, h_m, x_c, radius):
    if h_available <= h_m:
        return x_c
    return max(0.0, x_c - math.sqrt(2.0 * radius * (h_available - h_m)))


@njit(cache=True)
def _pressure_at(x, x1, p_in, c1, c2, c3, h_m, x_c, radius):
    _, i2, i3, _, x3, _ = integrals(x1, x, h_m, x_c, radius)
    return p_in + c1 * i2 + c2 * x3 + c3 * i3


@njit(cache=True)
def _rupture_residual(x2, x1, p_in, c1, c2, h_m, x_c, radius):
    _, i2, i3, _, x3, _ = integrals(x1, x2, h_m, x_c, radius)
    h2 = gap(x2, h_m, x_c, radius)
    return p_in + c1 * (i2 - h2 * i3) + c2 * (x3 - x2 * i3)


@njit(cache=True)
def _reform_residual(x, b, p_out, c1, h2, h_m, x_c, radius):
    _, i2, i3, _, _, _ = integrals(x, b, h_m, x_c, radius)
    return c1 * (i2 - h2 * i3) - p_out


@njit(cache=True)
def _illinois(kind, lo, hi, f_lo, f_hi, tol, p0, p1, p2, p3, p4, p5, p6, p7):
    """Regula falsi, Illinois variant, on one of the two boundary residuals (kind 0 / 1)."""
    side = 0
    x = lo
    for _ in range(200):
        x = false_position_mean(lo, f_lo, hi, f_hi)
        if kind == 0:
            fx = _rupture_residual(x, p0, p1, p2, p3, p4, p5, p6)
        else:
            fx = _reform_residual(x, p0, p1, p2, p3, p4, p5, p6)
        if fx == 0.0 or hi - lo < tol:
            return x
        lo, f_lo, hi, f_hi, side = illinois_update(lo, f_lo, hi, f_hi, x, fx, side)
    return x


@njit(cache=True)
def film(h_m, V, u, eta, p_in, p_out, b, x_c, radius, x1, striated, open_outlet=False):
    """(load, friction, flow, x_rupture, x_reform, cavitated, fallback, inflow) in the entrainment
    frame; ``flow`` leaves at the outlet, ``inflow`` enters at the inlet x1 (they differ by the
    squeeze, dQ/dx = -V). ``open_outlet``: no oil at the outlet flank to reform the film from,
    so past a rupture line the face is open to the outlet gas (a starved ring)."""
    p_in, p_out = max(p_in, 0.0), max(p_out, 0.0)
    c1, c2 = 6.0 * eta * u, 12.0 * eta * V
    h1, i2, i3, xx2, x3, xx3 = integrals(x1, b, h_m, x_c, radius)
    c3 = (p_out - p_in - c1 * i2 - c2 * x3) / i3
    lowest = min(p_in, p_out)
    qa, qb, qc = c1 / (2.0 * radius), c2, c1 * h_m + c2 * x_c + c3
    if qa != 0.0:
        disc = qb * qb - 4.0 * qa * qc
        if disc >= 0.0:
            sq = math.sqrt(disc)
            for d in ((-qb - sq) / (2.0 * qa), (-qb + sq) / (2.0 * qa)):
                x = x_c + d
                if x1 < x < b:
                    lowest = min(lowest, _pressure_at(x, x1, p_in, c1, c2, c3, h_m, x_c, radius))
    elif qb != 0.0:
        x = x_c - qc / qb
        if x1 < x < b:
            lowest = min(lowest, _pressure_at(x, x1, p_in, c1, c2, c3, h_m, x_c, radius))
    scale = max(max(p_in, p_out), max(abs(c1) / (h_m * h_m) * b, 1.0))
    if lowest >= -1e-9 * scale:
        load = b * p_out - x1 * p_in - (c1 * xx2 + c2 * xx3 + c3 * x3)
        friction = -2.0 * eta * u * h1 - 0.5 * (c2 * xx2 + c3 * i2)
        q_in = -V * x1 - c3 / (12.0 * eta)
        return load, friction, -V * b - c3 / (12.0 * eta), b, b, False, False, q_in
    # rupture line: first sign change of the residual past the inlet
    x2 = -1.0
    prev_x, prev_f = x1, p_in
    for i in range(1, RUPTURE_SCAN + 1):
        x = x1 + (b - x1) * i / RUPTURE_SCAN
        fx = _rupture_residual(x, x1, p_in, c1, c2, h_m, x_c, radius)
        if i == 1 and prev_f <= 0.0 and fx <= 0.0:
            # an inlet at zero gauge: the residual starts at 0, and the pressure the converging
            # inlet builds may fall back to a rupture inside the first scan interval (a
            # separating squeeze near a dead centre, or a minimum gap near the inlet flank).
            # Look for that hump by halving towards the inlet (values within round-off of the
            # film's pressure scale do not count); without one, scan on.
            d = x - x1
            for _ in range(40):
                d *= 0.5
                f_half = _rupture_residual(x1 + d, x1, p_in, c1, c2, h_m, x_c, radius)
                if f_half > 1e-9 * scale:
                    prev_x, prev_f = x1 + d, f_half
                    break
        if prev_f > 0.0 and fx <= 0.0:
            x2 = _illinois(0, prev_x, x, prev_f, fx, 1e-12 * b, x1, p_in, c1, c2, h_m, x_c,
                           radius, 0.0)
            break
        prev_x, prev_f = x, fx
    if x2 < 0.0:
        return _half_sommerfeld(h_m, V, u, eta, p_in, p_out, b, x_c, radius, x1, c1, c2, c3)
    h2 = gap(x2, h_m, x_c, radius)
    c3 = -c1 * h2 - c2 * x2
    h1, i2, i3, xx2, x3, xx3 = integrals(x1, x2, h_m, x_c, radius)
    load = -x1 * p_in - (c1 * xx2 + c2 * xx3 + c3 * x3)
    friction = -2.0 * eta * u * h1 - 0.5 * (c2 * xx2 + c3 * i2)
    xr = b
    exposed = False
    if p_out > 0.0:
        f2 = -p_out
        if c1 > 0.0:
            f2 = _reform_residual(x2, b, p_out, c1, h2, h_m, x_c, radius)
        if f2 <= 0.0 or open_outlet:
            # the diverging gap cannot build the flank pressure again: the outlet face past the
            # rupture line is open to the flank gas (Yang's x_4 < b of eq. 5.17)
            xr = x2
            exposed = True
        else:
            xr = _illinois(1, x2, b, f2, -p_out, 1e-12 * b, b, p_out, c1, h2, h_m, x_c,
                           radius, 0.0)
    if exposed:
        load += p_out * (b - x2)
    elif xr < b:
        h1b, i2b, _, xx2b, x3b, _ = integrals(xr, b, h_m, x_c, radius)
        load += b * p_out - c1 * (xx2b - h2 * x3b)
        friction += -2.0 * eta * u * h1b + 3.0 * eta * u * h2 * i2b
    if striated and xr > x2:
        _, i2c, _, _, _, _ = integrals(x2, xr, h_m, x_c, radius)
        friction += eta * u * h2 * i2c
    return load, friction, 0.5 * u * h2, x2, xr, True, False, 0.5 * u * h2 + V * (x2 - x1)


@njit(cache=True)
def _half_sommerfeld(h_m, V, u, eta, p_in, p_out, b, x_c, radius, x1, c1, c2, c3):
    """Fallback when no rupture line exists: the full film with negative pressures dropped."""
    n = 400
    load = 0.0
    friction = 0.0
    dx = (b - x1) / (n - 1)
    prev_p, prev_t = 0.0, 0.0
    for i in range(n):
        x = x1 + i * dx
        p = _pressure_at(x, x1, p_in, c1, c2, c3, h_m, x_c, radius)
        h = gap(x, h_m, x_c, radius)
        tau = 0.0
        if p > 0.0:
            tau = -0.5 * h * (c1 * h + c2 * x + c3) / (h * h * h) + eta * u / h
        p = max(p, 0.0)
        if i > 0:
            load += 0.5 * dx * (p + prev_p)
            friction += 0.5 * dx * (tau + prev_t)
        prev_p, prev_t = p, tau
    return (load, friction, -V * b - c3 / (12.0 * eta), b, b, True, True,
            -V * x1 - c3 / (12.0 * eta))


@njit(cache=True)
def _partial_film(f, phi, p_out, b):
    """A film filling the fraction ``phi`` of the circumference (streamers): its hydrodynamic
    load, shear and flows scale with phi; the gas on the face past its rupture line does not."""
    gas = 0.0
    if f[5] and f[4] == f[3] and f[3] < b:
        gas = max(p_out, 0.0) * (b - f[3])
    return (gas + phi * (f[0] - gas), phi * f[1], phi * f[2], f[3], f[4], f[5], f[6],
            phi * f[7])


@njit(cache=True)
def _frame(U, x_min, height, p_above, p_below):
    if U >= 0.0:
        return 1.0, x_min, p_above, p_below
    return -1.0, height - x_min, p_below, p_above


@njit(cache=True)
def state(h, V, U, eta, p_above, p_below, layer, height, radius, x_min, tension, striated):
    """(film tuple, F_z, sign, gas) of a ring at one instant; layer < 0 means flooded.

    F_z is Yang's radial load (5.17), the back-face gas and tension less the gas on the exposed
    face at both flanks: the dry inlet 0..x_1 at p_in and, where the film does not reform, the
    outlet past the rupture line at p_out (Yang's x_4 < b). ``gas`` is that outlet gas load,
    which the film tuple's load includes; the film proper carries F_z = load - gas.
    """
    sign, x_c, p_in, p_out = _frame(U, x_min, height, p_above, p_below)
    x1 = 0.0
    u = abs(U)
    starved = layer >= 0.0
    if starved:
        x1 = inlet_position(2.0 * layer, h, x_c, radius)
    f = film(h, V, u, eta, p_in, p_out, height, x_c, radius, x1, striated, starved)
    if starved and f[7] > u * layer:
        # continuity (Yang 5.34): the ring cannot draw more oil through its inlet meniscus than
        # the layer brings; move the inlet downstream (less inlet film) until the flows match
        # (Illinois regula falsi on the excess inflow)
        supply = u * layer
        lo, r_lo = x1, f[7] - supply
        f_hi = f
        if x1 < x_c:
            f_hi = film(h, V, u, eta, p_in, p_out, height, x_c, radius, x_c, striated, starved)
        hi, r_hi = x_c, f_hi[7] - supply
        x1 = x_c
        f = f_hi
        if r_hi > 0.0:
            # no inlet position satisfies continuity: the layer cannot fill the conjunction even
            # from the minimum gap. The film splits into streamers (the finger pattern of Yang
            # §5.3.2.3) that fill a fraction phi = supply / inflow of the circumference: the
            # ring's load beyond them rests on its asperities, and the oil drawn is the layer
            # brought (eq. 5.34 with equality); phi = 1 is the full film with its inlet at the
            # minimum gap, and phi -> 0 no film at all
            f = _partial_film(f_hi, supply / f_hi[7], p_out, height)
        elif lo < hi:
            side = 0
            for _ in range(60):
                mid = false_position_mean(lo, r_lo, hi, r_hi)
                f_mid = film(h, V, u, eta, p_in, p_out, height, x_c, radius, mid, striated,
                             starved)
                r_mid = f_mid[7] - supply
                lo, r_lo, hi, r_hi, side = illinois_update(lo, r_lo, hi, r_hi, mid, r_mid, side)
                if side == 1:                   # the inlet at mid draws no more than the layer
                    x1, f = mid, f_mid
                if hi - lo < 1e-9 * height or r_mid == 0.0:
                    break
    gas = 0.0
    if f[5] and f[4] == f[3] and f[3] < height:
        gas = max(p_out, 0.0) * (height - f[3])
    p_back = max(max(p_above, p_below), 0.0)
    f_z = (p_back + tension) * height - max(p_in, 0.0) * x1 - gas
    return f, f_z, sign, gas


@njit(cache=True)
def _residual(log_h, h0, g0, dth, w, trapezoid, U, eta, pa, pb, layer, height, radius, x_min,
              tension, striated):
    h1 = math.exp(log_h)
    if trapezoid:
        g = 2.0 * (h1 - h0) / dth - g0
    else:
        g = (h1 - h0) / dth
    f, f_z, _, gas = state(h1, w * g, U, eta, pa, pb, layer, height, radius, x_min, tension,
                           striated)
    return f[0] - gas - f_z


@njit(cache=True)
def step(h0, g0, dth, w, trapezoid, U, eta, pa, pb, layer, height, radius, x_min, tension,
         striated):
    """One implicit step of the film march; returns (h1, dh/dtheta at h1)."""
    args = (h0, g0, dth, w, trapezoid, U, eta, pa, pb, layer, height, radius, x_min, tension,
            striated)
    lo = hi = math.log(h0)
    r_lo = r_hi = _residual(lo, *args)
    inc = 0.05
    while r_hi > 0.0 and hi < LOG_H_MAX:
        lo, r_lo = hi, r_hi
        hi = min(hi + inc, LOG_H_MAX)
        inc *= 2.0
        r_hi = _residual(hi, *args)
    inc = 0.05
    while r_lo < 0.0 and lo > LOG_H_MIN:
        hi, r_hi = lo, r_lo
        lo = max(lo - inc, LOG_H_MIN)
        inc *= 2.0
        r_lo = _residual(lo, *args)
    x = lo
    if r_lo < 0.0:
        x = LOG_H_MIN                # no oil can carry the load: the film collapses to the floor
    elif r_hi > 0.0:
        x = LOG_H_MAX
    elif hi > lo and r_hi != r_lo:                                  # Illinois regula falsi in log h
        side = 0
        for _ in range(200):
            x = false_position_mean(lo, r_lo, hi, r_hi)
            fx = _residual(x, *args)
            if fx == 0.0 or hi - lo < 1e-10:
                break
            lo, r_lo, hi, r_hi, side = illinois_update(lo, r_lo, hi, r_hi, x, fx, side)
    h1 = math.exp(x)
    g = 2.0 * (h1 - h0) / dth - g0 if trapezoid else (h1 - h0) / dth
    return h1, g


#: Liner speeds below this fraction of the cycle's largest are a dead centre, where the layer a
#: ring leaves (flow / speed) is undefined.
DEAD_CENTRE = 1e-9


@njit(cache=True)
def _own_layer(f, U, u_dead):
    """The layer [m] a ring leaves on the liner behind it, Q_out/|U| (Yang eq. 5.35); -1 at a
    dead centre (|U| <= u_dead)."""
    if abs(U) <= u_dead:
        return -1.0
    return max(f[2], 0.0) / abs(U)


@njit(cache=True)
def march(h_start, dth, w, trapezoid, U, eta, pa, pb, layer, feed, geometry, tolerance,
          max_cycles):
    """Cycles of the film march until the start film repeats; returns (h, g, supply, cycles,
    change), ``supply`` the layer each angle's inlet was given on the last cycle. ``geometry``:
    the ring's :data:`RingGeometry`; ``feed``: its :data:`OwnFeed`.

    Where ``own_from[i] >= 0`` the ring is fed by the layer it left itself on its previous
    stroke at the same liner position (Yang eq. 5.36 and his dead-centre assumption): the layer
    interpolated between angles ``own_from`` and ``own_to`` of this march (``own_start`` before
    the march has been there). Elsewhere ``layer`` (< 0: flooded).
    """
    own_from, own_to, own_weight, own_start = feed
    height, radius, x_min, tension, striated = geometry
    n = U.size
    h = np.empty(n)
    g = np.empty(n)
    own = own_start.copy()
    used = layer.copy()
    self_fed = np.any(own_from >= 0)
    u_dead = DEAD_CENTRE * np.max(np.abs(U))
    h_prev, g_prev = h_start, 0.0
    change = np.inf
    cycles = 0
    while cycles < max_cycles:
        cycles += 1
        start = h_prev
        own_diff = 0.0
        own_top = 0.0
        for i in range(n):
            lay = layer[i]
            if own_from[i] >= 0:
                a, b = own[own_from[i]], own[own_to[i]]
                if a < 0.0:
                    a = b
                if b < 0.0:
                    b = a
                lay = max((1.0 - own_weight[i]) * a + own_weight[i] * b, 0.0)
            used[i] = lay
            h_prev, g_prev = step(h_prev, g_prev, dth, w, trapezoid, U[i], eta[i], pa[i], pb[i],
                                  lay, height, radius, x_min, tension, striated)
            h[i] = h_prev
            g[i] = g_prev
            if self_fed:
                f, _, _, _ = state(h_prev, w * g_prev, U[i], eta[i], pa[i], pb[i], lay, height,
                                   radius, x_min, tension, striated)
                left = _own_layer(f, U[i], u_dead)
                if left >= 0.0 and own[i] >= 0.0:
                    own_diff = max(own_diff, abs(left - own[i]))
                own_top = max(own_top, left)
                own[i] = left
        change = abs(h_prev - start) / start
        if self_fed:
            # a self-fed ring may run dry (at the march's floor) at the start angle: films below
            # FILM_SCALE count as equal there
            change = abs(h_prev - start) / max(start, FILM_SCALE)
            if own_top > 0.0:
                change = max(change, own_diff / own_top)
        if change < tolerance and cycles > 1:
            break
    return h, g, used, cycles, change


announce("ring-film", (march, step, film, integrals))
