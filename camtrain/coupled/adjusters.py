"""Every lobe's hydraulic lash adjuster in the coupled march (:mod:`camtrain.coupled.march`):
the compiled record of the trains' adjuster with the state index of every lobe's plunger,
every chamber's start from the single train's periodic response, and the chambers' way to
their periodic state: their oil contents solved over the revolutions (secant rule)
(docs/lash_adjusters.md)."""
from __future__ import annotations

import math

import numpy as np


def adjuster_record(asm, train):
    """Every train's lash adjuster (one record: the trains are copies, its nodes train-local)
    and the state index of every lobe's plunger; without one, ``no_adjuster`` and none."""
    from camtrain.dynamics.hla import hydraulic_record, no_adjuster
    from camtrain.dynamics.train import CAM, static_state

    if train.series is None:
        return no_adjuster(), np.zeros(0, dtype=np.int64)
    if train.follower != train.uni_node[CAM]:
        raise ValueError("the coupled march takes a lash adjuster on the cam's follower node")
    u0 = static_state(train)[0]
    element = train.series
    w0 = float(u0[train.follower] - u0[element.node])
    record = hydraulic_record(element.adjuster, train.follower, element.node, element.ratio, w0)
    starts = asm.tr0 + np.arange(asm.ix.size) * train.size
    return record, (starts + train.series.node).astype(np.int64)


def adjusters_start(asm, train, start, theta_grid, phases, state, minv):
    """Every adjuster from the single train's periodic response at its lobe's angle: the
    plunger moved with its follower (the warm start moves the follower with the shaft), so
    the chamber keeps the single train's volume, its pressure, and the acceleration with
    the chamber's force (in place in ``state`` = (q, v, acc, hp)); ``minv`` = M^-1 (the
    march's, set once: block diagonal, not inverted again here)."""
    from camtrain.dynamics.hla.chamber import plunger_force
    from camtrain.dynamics.hla.sealed import consistent_restart

    q, v, acc, hp = state
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
    acc += minv @ force
    for j, g in enumerate(phases):     # the plunger's acceleration relative to its body as
        at = float(theta_grid[0]) - float(g)     # the single train's: no start-up jolt of a
        rel = (np.interp(at, start.theta, start.a[train.series.node], period=period)  # stiff chamber
               - np.interp(at, start.theta, start.a[train.follower], period=period))
        acc[ipl[j]] = acc[asm.ifol[j]] + rel
    if record.on:       # a sealed incompressible chamber: no acceleration in its body
        for j in range(len(phases)):
            consistent_restart(record, hp[j], acc, minv, asm.ifol[j], ipl[j])


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


def accelerate_chambers(sysm, state, series):
    """After an open revolution, every chamber's oil content moved toward its periodic value
    by the secant rule on its net change over a revolution (in place): ``series`` = (every
    content at the revolution's start, the last revolution's (start contents, net changes) or
    None). The periodic chamber keeps its content over a revolution (refill = leak-down), a
    root of the net change f(m) = m_end - m_start; with two revolutions the secant through
    them gives the root, taken where the revolution's map contracts (its slope 1 + f' within
    0.9 of zero: the refill and leak-down balance converging), else the content the
    revolution ended with. Each chamber is set to its content by the pressure at which it
    holds it in its present volume. Returns the series for the next revolution."""
    now = chamber_contents(sysm.hla, state, sysm.lay)
    if now is None:
        return series
    start, last = series
    change = now - start
    target = now.copy()
    if last is not None:
        with np.errstate(divide="ignore", invalid="ignore"):
            slope = (change - last[1]) / (start - last[0])
        ok = np.isfinite(slope) & (np.abs(1.0 + slope) < 0.9)
        target = np.where(ok, start - change / np.where(ok, slope, 1.0), now)
    volumes = _volumes(sysm.hla, state, sysm.lay)
    for j in range(now.size):
        if target[j] != now[j]:
            _set_content(sysm.hla, state, j, volumes[j], target[j])
    return chamber_contents(sysm.hla, state, sysm.lay), (start, change)


def extension_change(extensions, previous, record) -> float:
    """The largest change of a plunger's extension at the grid samples (lobes, n) from the
    ``previous`` revolution's, over the largest travel of one in the revolution (at least a
    thousandth of the stroke)."""
    travel = max(float(np.max(np.ptp(extensions, axis=1))), 1e-3 * record.stroke)
    return float(np.max(np.abs(extensions - previous))) / travel
