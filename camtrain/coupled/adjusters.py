"""Every lobe's hydraulic lash adjuster in the coupled march (:mod:`camtrain.coupled.march`):
the compiled record of the trains' adjuster with the state index of every lobe's plunger,
every chamber's start from the single train's periodic response, and the chambers' way to
their periodic state: closed through the shaft's start-up transient, then open, their oil
contents extrapolated over the revolutions (docs/lash_adjusters.md)."""
from __future__ import annotations

import math

import numpy as np


def adjuster_record(asm, train):
    """Every train's lash adjuster (one record: the trains are copies, its nodes train-local)
    and the state index of every lobe's plunger; without one, ``no_adjuster`` and none."""
    from camtrain.dynamics.hla import hydraulic_record, no_adjuster
    from camtrain.dynamics.train import CAM, static_state

    if train.hla is None:
        return no_adjuster(), np.zeros(0, dtype=np.int64)
    if train.follower != train.uni_node[CAM]:
        raise ValueError("the coupled march takes a lash adjuster on the cam's follower node")
    u0 = static_state(train)[0]
    w0 = float(u0[train.follower] - u0[train.plunger])
    record = hydraulic_record(train.hla, train.follower, train.plunger, train.hla_ratio, w0)
    starts = asm.tr0 + np.arange(asm.ix.size) * train.size
    return record, (starts + train.plunger).astype(np.int64)


def adjusters_start(asm, train, start, theta_grid, phases, q, v, acc, hp):
    """Every adjuster from the single train's periodic response at its lobe's angle: the
    plunger moved with its follower (the warm start moves the follower with the shaft), so
    the chamber keeps the single train's volume, its pressure, and the acceleration with
    the chamber's force (in place)."""
    from camtrain.dynamics.hla.chamber import plunger_force
    from camtrain.dynamics.hla.sealed import consistent_restart

    period = 2.0 * math.pi
    record, ipl = adjuster_record(asm, train)
    force = np.zeros(q.size)
    for j, g in enumerate(phases):
        at = float(theta_grid[0]) - float(g)
        f, p = asm.ifol[j], ipl[j]
        q[p] += q[f] - np.interp(at, start.theta, start.u[train.follower], period=period)
        v[p] += v[f] - np.interp(at, start.theta, start.v[train.follower], period=period)
        hp[j, 0] = np.interp(at, start.theta, start.hydraulic[0], period=period)
        ext = record.x_rest - record.ratio * (q[f] - q[p] - record.w0)
        push = record.ratio * plunger_force(hp[j, 0], ext, record)
        force[f] -= push
        force[p] += push
    acc += np.linalg.solve(asm.M, force)
    for j, g in enumerate(phases):     # the plunger's acceleration relative to its body as
        at = float(theta_grid[0]) - float(g)     # the single train's: no start-up jolt of a
        rel = (np.interp(at, start.theta, start.a[train.plunger], period=period)  # stiff chamber
               - np.interp(at, start.theta, start.a[train.follower], period=period))
        acc[ipl[j]] = acc[asm.ifol[j]] + rel
    if record.on:       # a sealed incompressible chamber: no acceleration in its body
        minv = np.linalg.inv(asm.M)
        for j in range(len(phases)):
            consistent_restart(record, hp[j], acc, minv, asm.ifol[j], ipl[j])


def closed_chambers(record):
    """``record`` with every chamber closed: no check-valve inflow, no leak-down or Couette
    flow, so each chamber keeps its oil and acts as the closed chamber's spring (its
    compressibility). The coupled march's first revolutions use it (docs/lash_adjusters.md):
    the shaft's start-up transient would otherwise pump the plungers up (a follower leaving
    its cam opens the check valve) by more than their leak-down takes back in many
    revolutions; once the closed chambers' revolutions agree, the chambers are opened."""
    return record._replace(check_k=0.0, g_leak=0.0, c_couette=0.0)


def _volumes(record, state, lay):
    """Every chamber's volume [m^3] in ``state`` (its plunger's extension)."""
    q = state.q
    ext = record.x_rest - record.ratio * (q[lay.ifol] - q[lay.ipl] - record.w0)
    return np.maximum(record.v_dead + record.area * ext, 1e-3 * record.v_dead)


def chamber_contents(record, state, lay) -> np.ndarray | None:
    """Every chamber's oil [m^3 at atmospheric pressure]: its volume over phi(p), the volume
    a unit of the mixture takes at its pressure (:func:`camtrain.dynamics.hla.mixture_volume`);
    None for incompressible oil without air (no pressure holds another content)."""
    from camtrain.dynamics.hla import mixture_volume

    if record.air == 0.0 and math.isinf(record.k_liq):
        return None
    phi = mixture_volume(state.hp[:, 0], record.k_liq, record.air, record.n_poly)
    return _volumes(record, state, lay) / phi


def _set_content(record, state, j, volume, content) -> bool:
    """Chamber j set to the pressure at which it holds ``content`` in ``volume`` (in place);
    False (nothing changed) where no pressure between the vapour pressure and 4 GPa does."""
    from scipy.optimize import brentq

    from camtrain.dynamics.hla import mixture_volume

    def gap(p):
        return float(mixture_volume(p, record.k_liq, record.air, record.n_poly)) \
            - volume / content

    lo, hi = record.p_floor, 4.0e9
    if gap(lo) <= 0.0 or gap(hi) >= 0.0:
        return False
    state.hp[j, 0] = brentq(gap, lo, hi, xtol=1e-6, rtol=1e-12)
    return True


def refill_contents(record, state, lay, samples) -> None:
    """Every chamber opened with the oil it holds in the periodic state's balance of refill and
    leak-down, estimated from the last closed revolution's ``samples`` (pressure and extension,
    lobes x 2 x n): over a periodic revolution the check valve just makes up what the annulus
    lost, so the chamber's lowest pressure sits at the valve's cracking threshold (supply less
    cracking pressure). The content that gives that pressure at the lowest sample's volume
    (the closed chamber's content does not change over its revolution) replaces the content,
    set by the pressure at the chamber's present volume (in place)."""
    from camtrain.dynamics.hla import mixture_volume

    if chamber_contents(record, state, lay) is None:
        return
    target = record.p_supply - record.p_crack
    phi = float(mixture_volume(target, record.k_liq, record.air, record.n_poly))
    volumes = _volumes(record, state, lay)
    for j in range(volumes.size):
        low = int(np.argmin(samples[j, 0]))
        ext = samples[j, 1, low]
        volume = max(record.v_dead + record.area * ext, 1e-3 * record.v_dead)
        _set_content(record, state, j, volumes[j], volume / phi)


def extrapolate_contents(record, state, lay, history, ratios) -> bool:
    """Aitken's extrapolation of every chamber's oil over the revolutions: ``history`` the
    contents at the ends of the last revolutions (oldest first). Where a chamber's content
    changes by a ratio r of its last change each revolution (|r| < 0.9: the refill and
    leak-down balance converging; r from the last three contents, or from ``ratios`` (the
    last extrapolation's, NaN where none) with two), it is set to the limit of that geometric
    series (the last content plus its last change times r/(1 - r)), by the pressure at which
    the chamber holds it in its present volume (in place); ``ratios`` keeps the r used.
    Returns whether any chamber moved."""
    last = history[-1] - history[-2]
    if len(history) >= 3:
        before = history[-2] - history[-3]
        with np.errstate(divide="ignore", invalid="ignore"):
            ratios[:] = np.where(before != 0.0, last / before, np.nan)
    volumes = _volumes(record, state, lay)
    moved = False
    for j in range(last.size):
        r = ratios[j]
        if not abs(r) < 0.9:
            continue
        moved |= _set_content(record, state, j, volumes[j],
                              history[-1][j] + last[j] * r / (1.0 - r))
    return moved


def accelerate_chambers(sysm, state, series):
    """The open chambers' contents after one more revolution (:func:`chamber_contents`) added
    to ``series`` = (contents since the last extrapolation, its ratios) and, with three in a
    row or two and the last ratios, their extrapolation (:func:`extrapolate_contents`), which
    starts the contents again. Returns the series."""
    now = chamber_contents(sysm.hla, state, sysm.lay)
    if now is None:
        return series
    contents, ratios = series
    contents = contents[-2:] + [now]
    if ratios is None:
        ratios = np.full(now.size, np.nan)
    known = len(contents) == 2 and bool(np.any(np.isfinite(ratios)))
    if (len(contents) == 3 or known) and extrapolate_contents(sysm.hla, state, sysm.lay,
                                                              contents, ratios):
        return [chamber_contents(sysm.hla, state, sysm.lay)], ratios
    return contents, ratios


def extension_change(extensions, previous, record) -> float:
    """The largest change of a plunger's extension at the grid samples (lobes, n) from the
    ``previous`` revolution's, over the largest travel of one in the revolution (at least a
    thousandth of the stroke)."""
    travel = max(float(np.max(np.ptp(extensions, axis=1))), 1e-3 * record.stroke)
    return float(np.max(np.abs(extensions - previous))) / travel
