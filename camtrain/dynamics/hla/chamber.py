"""The chamber's compiled step (numba, cached on disk): the pressure and the plunger force of
one implicit step (the package docstring), shared by the train's march and the leak-down test."""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from camtrain.dynamics.hla.element import (
    BULK_MODELS,
    CHAMBER_SCHEMES,
    CHECK_VALVES,
    P_ATM,
    LashAdjuster,
    couette_coefficient,
)
from camtrain.dynamics.records import HP_SIZE, Hydraulic


def hydraulic_record(adj: LashAdjuster, follower: int, plunger: int, ratio: float,
                     w0: float) -> Hydraulic:
    """The compiled march's record of an adjuster between train nodes ``follower`` (the body)
    and ``plunger``, its plunger moving ``ratio`` times the valve-referred motion, ``w0`` the
    valve-referred compression u_follower - u_plunger at rest."""
    if adj.scheme not in CHAMBER_SCHEMES:
        raise ValueError(f"unknown chamber scheme {adj.scheme!r}")
    if adj.bulk_model not in BULK_MODELS:
        raise ValueError(f"unknown bulk-modulus model {adj.bulk_model!r}")
    if adj.check_valve not in CHECK_VALVES:
        raise ValueError(f"unknown check-valve model {adj.check_valve!r}")
    root = math.sqrt(2.0 / adj.oil_density)
    ball_c = 2.0 * adj.ball_damping_ratio * math.sqrt(adj.ball_spring_rate * adj.ball_mass)
    return Hydraulic(
        1, follower, plunger, ratio, adj.area, adj.dead_volume, adj.rest_extension, adj.stroke,
        w0, adj.stop_stiffness, adj.conductance(),
        couette_coefficient(adj.plunger_diameter, adj.radial_clearance), adj.supply_pressure,
        adj.cracking_pressure, adj.discharge_coefficient * adj.check_area * root,
        adj.full_open, adj.bulk_modulus, adj.air_fraction, adj.polytropic_index,
        adj.vapour_pressure - P_ATM, CHAMBER_SCHEMES[adj.scheme], CHECK_VALVES[adj.check_valve],
        adj.ball_mass, adj.ball_spring_rate, adj.ball_preload, ball_c, adj.seat_area,
        adj.ball_lift, adj.discharge_coefficient * math.pi * adj.seat_diameter * root)


def no_adjuster() -> Hydraulic:
    """The record of a train without a hydraulic adjuster (``on`` 0: nothing of it runs)."""
    return Hydraulic(0, 0, 0, 1.0, 1.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
                     1.0, 0.0, 1.0, 0.0, 1.0, 0, 1.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0)


def chamber_start(hr: Hydraulic, pressure: float) -> np.ndarray:
    """A chamber state ``hp`` (records.HP_SLOTS) at rest at gauge ``pressure``: no flow, the
    ball (if any) on its seat."""
    hp = np.zeros(HP_SIZE)
    hp[0] = pressure
    return hp


@njit(cache=True)
def _ln_phi(p, hr):
    """ln phi(p) and d ln phi / dp = -1/K_e (the free-air mixture)."""
    liquid = (1.0 - hr.air) * math.exp(-p / hr.k_liq)
    p_abs = max(p + P_ATM, 1e-9)
    ratio = P_ATM / p_abs
    # isothermal air (n = 1, the default): the ratio itself, which pow returns exactly too
    air = hr.air * (ratio if hr.n_poly == 1.0 else ratio ** (1.0 / hr.n_poly))
    phi = liquid + air
    dphi = -liquid / hr.k_liq - air / (hr.n_poly * p_abs)
    return math.log(phi), dphi / phi


@njit(cache=True)
def _check(p, hr):
    """Quasi-static check-valve flow into the chamber and its derivative in p."""
    drop = hr.p_supply - p
    above = (drop - hr.p_crack) / hr.full_open
    if above <= 0.0 or drop <= 0.0:
        return 0.0, 0.0
    root = math.sqrt(drop)
    if above >= 1.0:
        return hr.check_k * root, -0.5 * hr.check_k / root
    q = hr.check_k * above * root
    return q, -hr.check_k * (root / hr.full_open + 0.5 * above / root)


@njit(cache=True)
def _ball_force(p, y, yd, hr):
    """Force [N] on the check ball off its seat, the stops' reactions left out: the supply's
    pressure above the chamber's on the seat's area, less the spring (preload F_0 at rest on the
    seat, rate k) and the viscous damping: (p_s - p) A_seat - F_0 - k y - c y'."""
    return (hr.p_supply - p) * hr.seat_area - hr.ball_f0 - hr.ball_k * y - hr.ball_c * yd


@njit(cache=True)
def _ball_held(p, y, yd, hr):
    """The ball's force with the stops' reactions: none while it is pressed on its seat or on
    its lift stop (the stop takes the force)."""
    f = _ball_force(p, y, yd, hr)
    if (y <= 0.0 and f < 0.0) or (y >= hr.ball_lift and f > 0.0):
        return 0.0
    return f


@njit(cache=True)
def ball_end(p1, y0, yd0, f0, h, hr):
    """The check ball's lift and speed at the end of a step h whose chamber ends at p1, and
    d lift/d p1: m y'' = F (:func:`_ball_force`) by the chamber's theta-method on (y, y')
    (theta = 1 backward Euler, 1/2 the trapezoidal rule: Newmark's average acceleration),
    linear in the unknowns and solved in closed form; ``f0`` the force at the start
    (:func:`_ball_held`). The seat and the lift stop are inelastic: a ball reaching one stays
    there at rest until the force turns."""
    th = hr.theta
    m, k, c = hr.ball_m, hr.ball_k, hr.ball_c
    g = (hr.p_supply - p1) * hr.seat_area - hr.ball_f0 - k * (y0 + h * (1.0 - th) * yd0)
    d = m + h * th * c + h * h * th * th * k
    yd1 = (m * yd0 + h * (th * g + (1.0 - th) * f0)) / d
    y1 = y0 + h * (th * yd1 + (1.0 - th) * yd0)
    if y1 <= 0.0:
        return 0.0, 0.0, 0.0
    if y1 >= hr.ball_lift:
        return hr.ball_lift, 0.0, 0.0
    return y1, yd1, -h * h * th * th * hr.seat_area / d


@njit(cache=True)
def _ball_flow(p, y, dy, hr):
    """Flow [m^3/s] into the chamber through the ball's curtain at lift y (a sharp-edged
    orifice of area pi d y, at most the bore's pi d^2/4; Merritt 1967 eq. 3-9), either way:
    back out of the chamber while the ball is still off its seat and the chamber is above the
    supply. Its derivative in p with the lift's ``dy`` = dy/dp."""
    drop = hr.p_supply - p
    if y <= 0.0:
        return 0.0, 0.0
    cap = 0.5 * math.sqrt(hr.seat_area / math.pi)   # pi d y = pi d^2/4 at y = d/4
    if y >= cap:
        y, dy = cap, 0.0
    root = math.sqrt(max(abs(drop), 1e-6))
    sign = 1.0 if drop >= 0.0 else -1.0
    q = hr.curtain_k * y * sign * root
    return q, hr.curtain_k * (dy * sign * root - 0.5 * y / root)


@njit(cache=True)
def _inflow(p, h, start, hr):
    """Check-valve flow into the chamber at its end pressure p and its derivative: the
    quasi-static orifice, or the ball's curtain at the lift it reaches under p."""
    if hr.valve == 0:
        return _check(p, hr)
    y1, _, dy = ball_end(p, start[4], start[5], start[6], h, hr)
    return _ball_flow(p, y1, dy, hr)


@njit(cache=True)
def plunger_force(p, x, hr):
    """Force [N] of chamber and end stops on the plunger (its own frame; the spring is a link
    of the train's linear part), at gauge pressure p and extension x."""
    f = hr.area * p
    if x < 0.0:
        f -= hr.k_stop * x
    elif x > hr.stroke:
        f -= hr.k_stop * (x - hr.stroke)
    return f


@njit(cache=True)
def extension(uf, uq, hr):
    """Plunger extension x [m] from the follower and plunger displacements (valve-referred)."""
    return hr.x_rest - hr.ratio * (uf - uq - hr.w0)


@njit(cache=True)
def _force_at(p, big_x, sigma, hr):
    """The plunger force F and dF/dp when the end extension is x1 = X + sigma F."""
    f = hr.area * p
    x1 = big_x + sigma * f
    if x1 < 0.0:
        d = 1.0 + hr.k_stop * sigma
        return (f - hr.k_stop * big_x) / d, hr.area / d
    if x1 > hr.stroke:
        d = 1.0 + hr.k_stop * sigma
        return (f - hr.k_stop * (big_x - hr.stroke)) / d, hr.area / d
    return f, hr.area


@njit(cache=True)
def _residual(p, big_x, big_xd, sigma, h, start, hr):
    """Chamber residual R(p1) (falls with p1) and dR/dp; ``start`` = (ln phi0, V0, net flow
    over V at the start, x at the start, the ball's lift, speed and force at the start), from
    :func:`chamber_step`."""
    ln0, v0, net0 = start[0], start[1], start[2]
    f, df = _force_at(p, big_x, sigma, hr)
    x1 = big_x + sigma * f
    rate = 2.0 * sigma / h if h > 0.0 else 0.0   # sigma ~ h^2: no speed change in no time
    xd1 = big_xd + rate * f
    v1 = max(hr.v_dead + hr.area * x1, 1e-3 * hr.v_dead)
    ln1, dln1 = _ln_phi(p, hr)
    qin, dqin = _inflow(p, h, start, hr)
    qout = hr.g_leak * (p - hr.p_supply) + hr.c_couette * xd1
    net1 = (qin - qout) / v1
    r = ln1 - ln0 - math.log(v1 / v0) + h * (hr.theta * net1 + (1.0 - hr.theta) * net0)
    dv1 = hr.area * sigma * df
    dnet = (dqin - hr.g_leak - hr.c_couette * rate * df) / v1 - net1 * dv1 / v1
    return r, dln1 - dv1 / v1 + h * hr.theta * dnet, qin, qout


@njit(cache=True)
def chamber_step(hr, hp, x0, big_x, big_xd, sigma, h):
    """Chamber pressure at the end of a step of length h, the plunger's end extension and speed
    being x1 = X + sigma F, x1' = X' + 2 sigma/h F under the plunger force F(p1) (the train's
    Newmark step with the force as unknown, ``sigma`` = ratio^2 h^2/4 times the pair's
    compliance). ``hp`` the chamber state at the start (records.HP_SLOTS: p0, q_in0, q_out0,
    dp/dt of the last step, the volumes so far, the ball's lift and speed; a quasi-static valve
    reads the first four only); :func:`chamber_advance` makes the end state.
    Safeguarded Newton on the monotone residual (bisection when a step leaves the bracket),
    from the last step's pressure rate carried over h (a first guess that saves about one
    residual per step while the pressure rises or falls); below the vapour pressure the
    chamber cavitates and its pressure stays there. Returns (p1, F, q_in1, q_out1)."""
    p0 = hp[0]
    ln0 = _ln_phi(p0, hr)[0]
    v0 = max(hr.v_dead + hr.area * x0, 1e-3 * hr.v_dead)
    y0 = yd0 = fb0 = 0.0
    if hr.valve == 1:
        y0, yd0 = hp[6], hp[7]
        fb0 = _ball_held(p0, y0, yd0, hr)
    start = (ln0, v0, (hp[1] - hp[2]) / v0, x0, y0, yd0, fb0)
    lo, hi = hr.p_floor, 4.0e9
    r_lo = r_hi = 0.0   # the residuals at the bracket's ends, once evaluated (0: not yet)
    side = 0
    floor_known = False
    p = min(max(p0 + hp[3] * h, lo), hi)
    for it in range(100):
        r, dr, qin, qout = _residual(p, big_x, big_xd, sigma, h, start, hr)
        if r > 0.0:
            lo, r_lo = p, r
            r_hi *= 0.5 if side == 1 else 1.0   # Illinois: the end kept twice counts half
            side = 1
        else:
            hi, r_hi = p, r
            r_lo *= 0.5 if side == -1 else 1.0
            side = -1
        pn = p - r / dr if dr < 0.0 else lo
        if dr < 0.0 and abs(pn - p) <= 1e-8 * (abs(p) + P_ATM) and lo <= pn <= hi:
            # converged: tested before the bracket, since at the root pn rounds onto p, the
            # bracket's end (a bisection of the whole bracket from there took 40 evaluations)
            return pn, _force_at(pn, big_x, sigma, hr)[0], qin, qout
        if pn <= lo and not floor_known:
            floor_known = True
            rf, _, qf, qo = _residual(hr.p_floor, big_x, big_xd, sigma, h, start, hr)
            if rf <= 0.0:   # cavitation: even the vapour pressure over-fills the chamber
                return hr.p_floor, _force_at(hr.p_floor, big_x, sigma, hr)[0], qf, qo
        if it >= 4 and r_lo > 0.0 and r_hi < 0.0:
            # Newton alternates about the root where the ball's flow reverses (the orifice's
            # square root has an infinite slope at zero drop): Illinois false position
            pn = lo + r_lo * (hi - lo) / (r_lo - r_hi)
        elif dr >= 0.0 or pn <= lo or pn >= hi:
            pn = 0.5 * (lo + hi)
        elif abs(pn - p) <= 1e-8 * (abs(p) + P_ATM):
            # Newton's last step: pn is the root to about the square of it (1e-16); the
            # flows are p's, within 1e-8 of the root's
            return pn, _force_at(pn, big_x, sigma, hr)[0], qin, qout
        if abs(pn - p) <= 1e-12 * (abs(p) + P_ATM) or hi - lo <= 1e-12 * (abs(p) + P_ATM):
            break   # p is the root to round-off: its own flows are those returned
        if it < 99:
            p = pn
    return p, _force_at(p, big_x, sigma, hr)[0], qin, qout


@njit(cache=True)
def chamber_advance(hr, hp, p1, qin, qout, h, dest):
    """The chamber state (records.HP_SLOTS) after a step h from ``hp`` that
    :func:`chamber_step` ended at p1 with flows ``qin``, ``qout``, into ``dest`` (``hp`` itself
    allowed): the volumes through the check valve and the annulus accumulated with the
    chamber's theta weights (its own discrete balance), the ball's end lift and speed."""
    th = hr.theta
    v_in = hp[4] + h * (th * qin + (1.0 - th) * hp[1])
    v_out = hp[5] + h * (th * qout + (1.0 - th) * hp[2])
    y1 = yd1 = 0.0
    if hr.valve == 1:
        y1, yd1, _ = ball_end(p1, hp[6], hp[7], _ball_held(hp[0], hp[6], hp[7], hr), h, hr)
    rate = (p1 - hp[0]) / h if h > 0.0 else hp[3]   # the next step's first guess
    dest[0], dest[1], dest[2], dest[3] = p1, qin, qout, rate
    dest[4], dest[5], dest[6], dest[7] = v_in, v_out, y1, yd1
