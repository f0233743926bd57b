"""The chamber's compiled step (numba, cached on disk): the pressure and the plunger force of
one implicit step (the package docstring), shared by the train's march and the leak-down test."""
from __future__ import annotations

import math

from numba import njit

from camtrain.dynamics.hla.element import (
    BULK_MODELS,
    CHAMBER_SCHEMES,
    P_ATM,
    LashAdjuster,
    couette_coefficient,
)
from camtrain.dynamics.records import Hydraulic


def hydraulic_record(adj: LashAdjuster, follower: int, plunger: int, ratio: float,
                     w0: float) -> Hydraulic:
    """The compiled march's record of an adjuster between train nodes ``follower`` (the body)
    and ``plunger``, its plunger moving ``ratio`` times the valve-referred motion, ``w0`` the
    valve-referred compression u_follower - u_plunger at rest."""
    if adj.scheme not in CHAMBER_SCHEMES:
        raise ValueError(f"unknown chamber scheme {adj.scheme!r}")
    if adj.bulk_model not in BULK_MODELS:
        raise ValueError(f"unknown bulk-modulus model {adj.bulk_model!r}")
    return Hydraulic(
        1, follower, plunger, ratio, adj.area, adj.dead_volume, adj.rest_extension, adj.stroke,
        w0, adj.stop_stiffness, adj.conductance(),
        couette_coefficient(adj.plunger_diameter, adj.radial_clearance), adj.supply_pressure,
        adj.cracking_pressure, adj.discharge_coefficient * adj.check_area
        * math.sqrt(2.0 / adj.oil_density), adj.full_open, adj.bulk_modulus, adj.air_fraction,
        adj.polytropic_index, adj.vapour_pressure - P_ATM, CHAMBER_SCHEMES[adj.scheme])


def no_adjuster() -> Hydraulic:
    """The record of a train without a hydraulic adjuster (``on`` 0: nothing of it runs)."""
    return Hydraulic(0, 0, 0, 1.0, 1.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
                     1.0, 0.0, 1.0, 0.0, 1.0)


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
    over V at the start, x at the start), from :func:`chamber_step`."""
    ln0, v0, net0 = start[0], start[1], start[2]
    f, df = _force_at(p, big_x, sigma, hr)
    x1 = big_x + sigma * f
    rate = 2.0 * sigma / h if h > 0.0 else 0.0   # sigma ~ h^2: no speed change in no time
    xd1 = big_xd + rate * f
    v1 = max(hr.v_dead + hr.area * x1, 1e-3 * hr.v_dead)
    ln1, dln1 = _ln_phi(p, hr)
    qin, dqin = _check(p, hr)
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
    compliance). ``hp`` = (p0, q_in0, q_out0, dp/dt of the last step) at the start.
    Safeguarded Newton on the monotone residual (bisection when a step leaves the bracket),
    from the last step's pressure rate carried over h (a first guess that saves about one
    residual per step while the pressure rises or falls); below the vapour pressure the
    chamber cavitates and its pressure stays there. Returns (p1, F, q_in1, q_out1)."""
    p0 = hp[0]
    ln0 = _ln_phi(p0, hr)[0]
    v0 = max(hr.v_dead + hr.area * x0, 1e-3 * hr.v_dead)
    start = (ln0, v0, (hp[1] - hp[2]) / v0, x0)
    lo, hi = hr.p_floor, 4.0e9
    floor_known = False
    p = min(max(p0 + hp[3] * h, lo), hi)
    for _ in range(100):
        r, dr, qin, qout = _residual(p, big_x, big_xd, sigma, h, start, hr)
        if r > 0.0:
            lo = p
        else:
            hi = p
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
        if dr >= 0.0 or pn <= lo or pn >= hi:
            pn = 0.5 * (lo + hi)
        elif abs(pn - p) <= 1e-8 * (abs(p) + P_ATM):
            # Newton's last step: pn is the root to about the square of it (1e-16); the
            # flows are p's, within 1e-8 of the root's
            return pn, _force_at(pn, big_x, sigma, hr)[0], qin, qout
        if abs(pn - p) <= 1e-12 * (abs(p) + P_ATM):
            break   # p is the root to round-off: its own flows are those returned
        p = pn
    return p, _force_at(p, big_x, sigma, hr)[0], qin, qout
