"""The monolithic march's start near its periodic state (:mod:`camtrain.coupled.march`):
every train from the single train's periodic response at its lobe's angle, the shaft from its
periodic answer (harmonic balance) to those trains' loads, friction and the drive's hub load."""
from __future__ import annotations

import math

import numpy as np

from .tables import own_columns, table_at


def _periodic_start(K, M, C, forces, omega, orders: int = 100):
    """Displacement and velocity at the first grid angle of the linear system's periodic
    response to ``forces`` (n_dof, grid) (harmonic balance, orders up to ``orders``: the
    shaft's answer to the higher ones is far smaller than its start-up error)."""
    n = forces.shape[-1]
    Fk = np.fft.rfft(forces, axis=-1)[:, :min(orders, n // 2 - 1) + 1]
    k = np.arange(Fk.shape[-1])
    w = k * omega
    Z = (K[None] - (w * w)[:, None, None] * M[None] + 1j * w[:, None, None] * C[None])
    X = np.linalg.solve(Z, Fk.T[:, :, None])[:, :, 0]          # (orders, n_dof)
    weight = np.where(k == 0, 1.0, 2.0)[:, None] / n
    q = np.sum(weight * X.real, axis=0)
    v = -np.sum(weight * (w[:, None] * X.imag), axis=0)
    return q, v


def quiet_bending_orders(K, M, omega) -> int:
    """The highest order of the shaft's revolution below half the lowest natural frequency
    of its bending block (stiffness ``K``, mass ``M``), at least 1: up to it the bare shaft's
    answer to a load is within 4/3 of its static answer (undamped single-mode amplification
    1/(1 - r^2), r <= 1/2).

    Why a start may leave out the orders above it: the bending modes of a camshaft between
    its bearings are lightly damped (on the Zeta shaft at orders 96-112 of the cam speed,
    modal damping ratios 0.1-0.5 %), and the bare shaft's resonant answer to the small high
    orders of the single trains' rigid-shaft loads there is not the coupled shaft's (the
    trains riding on the shaft detune and damp those modes): on the Zeta shaft it gave the
    followers 0.14-0.36 m/s away from their cams at the start, which threw the
    followers on the base circle off their cams in the first revolution."""
    import scipy.linalg

    lowest = math.sqrt(max(float(scipy.linalg.eigh(K, M, eigvals_only=True,
                                                   subset_by_index=[0, 0])[0]), 0.0))
    return max(int(math.ceil(0.5 * lowest / omega)) - 1, 1)


def warm_start(start, cam, theta_grid, phases, ratio, axes, train, M, K, C, f0, omega, sysm,
               b0, bd0, gx0, gy0, gphi0, drag=None, hub=None, quiet: bool = False):
    """State at the march's first angle from the single train's periodic response (see
    :func:`march_coupled`): each train at its lobe's angle, the shaft at its periodic answer
    to the trains' contact forces and torques (with their friction when ``drag`` = (coefficient
    table (levels, grid) in the lobe's frame, load levels, friction arm on the grid, turn,
    whether the levels are cam-level loads) is given, and the drive's hub load when ``hub`` =
    (pitch radius, hub-load direction, the preload's constant x and y parts) is), the
    follower (and an open valve) moved with the lobe, the contact states from
    their indicators and the acceleration from the equilibrium. ``quiet``: the shaft's
    bending in each plane answered only up to its :func:`quiet_bending_orders` (its twist to
    every order up to 100), a start that does not throw followers off their cams (the lash
    adjusters' march)."""
    from camtrain.dynamics.train import CAM

    idx = dict(ix=sysm.ix, iy=sysm.iy, iphi=sysm.iphi, ifol=sysm.ifol, ival=sysm.ival,
               nb=sysm.nb, t0=sysm.t0, tr0=sysm.tr0)
    n_lobes = len(phases)
    n = M.shape[0]
    nt = train.size
    q, v = np.zeros(n), np.zeros(n)
    theta0 = float(theta_grid[0])
    period = 2.0 * math.pi
    for j, g in enumerate(phases):
        at = theta0 - float(g)
        s = slice(idx["tr0"] + j * nt, idx["tr0"] + (j + 1) * nt)
        q[s] = [np.interp(at, start.theta, row, period=period) for row in start.u]
        v[s] = [np.interp(at, start.theta, row, period=period) for row in start.v]
    # the trains' forces on the shaft over the revolution, in the shaft's frame
    local = theta_grid[None, :] - np.asarray(phases, dtype=float)[:, None]
    w = np.interp(local, start.theta, np.maximum(start.contact_force[CAM], 0.0), period=period)
    rr = np.interp(local, theta_grid, np.asarray(ratio, dtype=float) * np.ones_like(theta_grid),
                   period=period)
    lift_rate = cam.evaluate(local)[1]
    nb, t0 = idx["nb"], idx["t0"]
    fb = np.zeros((2 * nb, theta_grid.size))
    ft = np.zeros((M.shape[0] - 2 * nb, theta_grid.size))
    torque = np.zeros(theta_grid.size)     # summed lobe torque W l' + mu W r
    for j in range(n_lobes):
        fb[idx["ix"][j]] -= w[j] * rr[j] * math.cos(axes[j])
        fb[idx["iy"][j]] -= w[j] * rr[j] * math.sin(axes[j])
        ft[idx["iphi"][j] - t0] -= w[j] * lift_rate[j]
        torque += w[j] * lift_rate[j]
    if drag is not None:     # friction: the tangential force and the torque mu W r
        table, levels, arm_grid, turn, cam_level = drag
        arm = np.interp(local, theta_grid, arm_grid, period=period)
        mu_all = table_at(table, levels, w * rr if cam_level else w,
                          own_columns(theta_grid, phases))
        for j in range(n_lobes):
            fr = mu_all[j] * rr[j] * w[j]
            tang = -turn * fr * np.where(arm[j] >= 0.0, 1.0, -1.0)
            fb[idx["ix"][j]] -= tang * math.sin(axes[j])
            fb[idx["iy"][j]] += tang * math.cos(axes[j])
            ft[idx["iphi"][j] - t0] -= fr * arm[j]
            torque += fr * arm[j]
    if hub is not None:      # the belt's pull at the drive station
        radius, direction, const_x, const_y = hub
        fb[sysm.hub_x] += np.abs(torque) / radius * direction[0] + const_x
        fb[sysm.hub_y] += np.abs(torque) / radius * direction[1] + const_y
    for lo, hi, force in ((0, nb, fb[:nb]), (nb, 2 * nb, fb[nb:])):    # each plane's bending
        Kb, Mb = K[lo:hi, lo:hi], M[lo:hi, lo:hi]
        orders = quiet_bending_orders(Kb, Mb, omega) if quiet else 100
        q[lo:hi], v[lo:hi] = _periodic_start(Kb, Mb, C[lo:hi, lo:hi], force, omega, orders)
    hi = idx["tr0"]
    q[t0:hi], v[t0:hi] = _periodic_start(K[t0:hi, t0:hi], M[t0:hi, t0:hi], C[t0:hi, t0:hi],
                                         ft[:hi - t0], omega)
    # the shaft's motion moves each lobe's cam input: the follower (and an open valve) moves
    # with it, so the contact keeps the single train's compression
    kc, cc, offc = train.uni_k[0], train.uni_c[0], train.uni_offset[0]
    ks, cs, offs = train.uni_k[1], train.uni_c[1], train.uni_offset[1]
    for j in range(n_lobes):
        ix, iy, iphi, ifol, ival = (idx[k][j] for k in ("ix", "iy", "iphi", "ifol", "ival"))
        shift = gx0[j] * q[ix] + gy0[j] * q[iy] + gphi0[j] * q[iphi]
        rate = gx0[j] * v[ix] + gy0[j] * v[iy] + gphi0[j] * v[iphi]
        moved = [ifol] + ([ival] if ival != ifol and offs - q[ival] < 0.0 else [])
        for dof in moved:
            q[dof] += shift
            v[dof] += rate
    # contact states and forces at the start
    force = f0.copy()
    act_c = np.zeros(n_lobes, dtype=bool)
    act_s = np.zeros(n_lobes, dtype=bool)
    for j in range(n_lobes):
        ix, iy, iphi, ifol, ival = (idx[k][j] for k in ("ix", "iy", "iphi", "ifol", "ival"))
        d = b0[j] + offc - q[ifol] + gx0[j] * q[ix] + gy0[j] * q[iy] + gphi0[j] * q[iphi]
        dd = bd0[j] - v[ifol] + gx0[j] * v[ix] + gy0[j] * v[iy] + gphi0[j] * v[iphi]
        wc = kc * d + cc * dd
        if min(kc * d, wc) > 0.0:
            act_c[j] = True
            force[ifol] += wc
            force[ix] -= wc * gx0[j]
            force[iy] -= wc * gy0[j]
            force[iphi] -= wc * gphi0[j]
        ds, dds = offs - q[ival], -v[ival]
        ws = ks * ds + cs * dds
        if min(ks * ds, ws) > 0.0:
            act_s[j] = True
            force[ival] += ws
    acc = np.linalg.solve(M, force - K @ q - C @ v)
    return q, v, acc, act_c, act_s
