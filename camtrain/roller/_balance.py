"""Compiled quasi-static torque balance of the roller, one angle at a time (numba, cached).

The same solve as :func:`camtrain.roller.solve._balance_roots` (breakaway and rolling tests,
two probes around the Newtonian slip, then the Illinois regula falsi on x = w_r / w* in [0, 1]
to a residual of RESIDUAL x the rolling pin torque or a bracket of BRACKET), with the traction
law and the needle pin written out per angle instead of as array operations over the loaded
angles: a run of the vectorised solve spends its time in the overhead of some thirty array
operations per traction evaluation, not in the arithmetic.

It covers the angles where the traction is the full-film law of :mod:`.traction`
(``limiting_shear`` or ``eyring``: Newtonian Barus shear below the limiting shear, capped at
mu_b W; no Greenwood-Tripp asperities because the film parameter stays at or above the mixed
limit over the whole bracket), the film is the pure-rolling film scaled by the power law
(|u_e| / |V_c|)^a_u, and the pin is a needle bearing (Palmgren's catalogue form,
:func:`camtrain.roller.pin.needle_torque`). Every other angle is solved by the array solve.
The records are named tuples (docs/architecture.md, "Compiled kernels take typed records").
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from camtrain.numerics.compile_notice import announce


class BalanceAngles(NamedTuple):
    """Per-angle data of the angles solved here (SI): non-rotating sliding ``v_s0``, cam surface
    speed ``v_cam``, ``load``, shear film at pure rolling ``film_rolling``, Newtonian shear per
    unit shear rate ``unit_shear``, Hertz ``area`` 2 b L, limiting shear force
    tau_0 A + gamma W ``limit``, cap mu_b W ``cap``."""

    v_s0: np.ndarray
    v_cam: np.ndarray
    load: np.ndarray
    film_rolling: np.ndarray
    unit_shear: np.ndarray
    area: np.ndarray
    limit: np.ndarray
    cap: np.ndarray


class BalanceLaw(NamedTuple):
    """Roller radius [m]; film speed exponent a_u; Eyring stress tau_0 [Pa] and whether the
    Eyring law applies; needle pitch diameter [m], kinematic viscosity [m^2/s], f_0, f_1;
    relative residual, bracket, smallest slip and most iterations of the solve."""

    radius: float
    exponent: float
    eyring: bool
    tau0: float
    pitch_diameter: float
    kinematic_viscosity: float
    f0: float
    f1: float
    residual: float
    bracket: float
    slip_min: float
    iterations: int
    nu_n_limit: float


@njit(cache=True)
def _traction(ang, law, i, u_s):
    """Traction [N] signed as u_s at angle i (the full-film law of :mod:`.traction`)."""
    u_e = ang.v_cam[i] - 0.5 * u_s
    h = ang.film_rolling[i] * (abs(u_e) / abs(ang.v_cam[i])) ** law.exponent
    rate = abs(u_s)
    if h > 0.0:
        rate = rate / h
    elif rate > 0.0:
        rate = np.inf
    newton = ang.unit_shear[i] * rate
    area = ang.area[i]
    if law.eyring and law.tau0 > 0.0:
        mean = newton / area if area > 0.0 else 0.0
        newton = area * law.tau0 * math.asinh(mean / law.tau0)
    mag = min(0.0 + min(newton, ang.limit[i]), ang.cap[i])
    return np.sign(u_s) * mag


@njit(cache=True)
def _needle(law, speed, load):
    """Palmgren's M_0 + M_1 [N m] at |w_r| = ``speed``."""
    n = speed * 60.0 / (2.0 * math.pi)
    nu_n = law.kinematic_viscosity * 1e6 * n
    dm = law.pitch_diameter * 1e3
    if nu_n >= law.nu_n_limit:
        m0 = 1e-7 * law.f0 * abs(nu_n) ** (2.0 / 3.0) * dm ** 3
    else:
        m0 = 160e-7 * law.f0 * dm ** 3
    return (m0 + law.f1 * load * dm) * 1e-3


@njit(cache=True)
def _balance(ang, law, i, x):
    v0 = ang.v_s0[i]
    w = x * (v0 / law.radius)
    pin = np.sign(w) * _needle(law, abs(w), max(ang.load[i], 0.0))
    return np.sign(v0) * (law.radius * _traction(ang, law, i, v0 * (1.0 - x)) - pin)


@njit(cache=True)
def _probe_bracket(ang, law, i, g_hi, lo, g_lo, hi):
    """Shrink [lo, hi] around the Newtonian slip estimate r k u_s = T (one probe each side)."""
    k = ang.unit_shear[i] / ang.film_rolling[i] if ang.film_rolling[i] > 0.0 else np.inf
    guess = -g_hi / (law.radius * k * abs(ang.v_s0[i]))
    if np.isnan(guess) or guess == np.inf:
        guess = 0.5
    guess = min(max(guess, 1e-15), 0.25)
    for factor in (4.0, 0.25):
        x = 1.0 - factor * guess
        g = _balance(ang, law, i, x)
        if g > 0.0:
            lo = max(lo, x)
            if x >= lo:
                g_lo = g
        else:
            hi = min(hi, x)
            if x <= hi:
                g_hi = g
    return lo, g_lo, hi, g_hi


@njit(cache=True)
def _root(ang, law, i):
    """x = w_r / w* at angle i (see the module docstring)."""
    v0 = ang.v_s0[i]
    load = max(ang.load[i], 0.0)
    g_lo = np.sign(v0) * law.radius * _traction(ang, law, i, v0) - _needle(law, 0.0, load)
    g_hi = -np.sign(v0) * (np.sign(v0 / law.radius) * _needle(law, abs(v0 / law.radius), load))
    if g_lo <= 0.0:
        return 0.0
    if g_hi >= 0.0:
        return 1.0
    if not g_hi < 0.0:          # NaN: the array solve's midpoint of [0, 1]
        return 0.5
    if _balance(ang, law, i, 1.0 - law.slip_min) >= 0.0:
        return 1.0
    scale = abs(g_hi) * law.residual
    lo, g_lo, hi, g_hi = _probe_bracket(ang, law, i, g_hi, 0.0, g_lo, 1.0)
    side = 0
    for _ in range(law.iterations):
        a, b, ga, gb = lo, hi, g_lo, g_hi
        x = a - ga * (b - a) / (gb - ga)
        x = min(max(x, a), b) if not np.isnan(x) else x
        if x <= a or x >= b:
            x = 0.5 * (a + b)
        g = _balance(ang, law, i, x)
        if g > 0.0:
            lo, hi, g_lo = x, b, g
            g_hi = 0.5 * gb if side == 1 else gb
            side = 1
        else:
            lo, hi, g_hi = a, x, g
            g_lo = 0.5 * ga if side == -1 else ga
            side = -1
        if abs(g) <= scale:
            return hi if g_hi >= 0.0 else x
        if hi - lo <= law.bracket:
            break
    return hi if g_hi >= 0.0 else 0.5 * (lo + hi)


@njit(cache=True)
def balance_roots(ang, law):
    """x = w_r / w* in [0, 1] at every angle of ``ang``."""
    out = np.empty(ang.v_s0.size)
    for i in range(out.size):
        out[i] = _root(ang, law, i)
    return out


announce("roller", (balance_roots,))
