"""Every lobe's hydraulic lash adjuster in the coupled march (:mod:`camtrain.coupled.march`):
the compiled record of the trains' adjuster with the state index of every lobe's plunger, and
every chamber's start from the single train's periodic response (docs/lash_adjusters.md)."""
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
