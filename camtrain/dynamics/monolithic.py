"""Several elastic valve trains and the elastic camshaft marched together in time (monolithic).

One state vector holds the shaft's bending in both planes and its twist (the free degrees of
freedom of :class:`camtrain.camshaft.elastic.ElasticShaft`) and every lobe's lumped train
(:class:`camtrain.dynamics.train.TrainModel`). Their linear parts are block diagonal; the lobes'
cam contacts couple them. Lobe j's contact closes with

    delta_j = b_j(theta) + offset_j - u_follower,j + R_j(theta) (cos a_j x_j + sin a_j y_j)
              + l'_j(theta) phi_j

(valve-referred: b the rigid valve lift of the lobe, R the rocker ratio, x_j, y_j the shaft
deflection at the lobe, a_j its follower axis, phi_j its twist against the drive, l' the valve
lift per cam radian), so one spring of stiffness k_j pushes the follower (+k delta) and the shaft
(-k delta times the gradient of delta: the lobe force along the follower axis and the torque
W l' = W e). Each valve seat is the train's own unilateral contact.

Integrator: Newmark average acceleration (trapezoidal; unconditionally stable, second order, no
numerical damping), the contact states found by an active-set iteration inside each step, one
compiled revolution at a time (:mod:`._coupled_kernel`). The linear part's effective matrix is
inverted once; the active contacts enter each step as a
low-rank update (Woodbury), because every contact's gradient lies in a fixed four-vector
subspace (x_j, y_j, phi_j, u_follower,j) with time-varying coefficients. Friction of each
contact enters as a tangential force mu_j(theta) W_j on the shaft and a torque mu W r, with
mu_j(theta) from the contact model on the previous revolution's loads (consistent at the
periodic state). Revolutions are marched from rest until two agree at the grid samples.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["MonolithicResult", "march_coupled"]


@dataclass(frozen=True)
class MonolithicResult:
    """Periodic state on the run's grid: ``loads`` (n_lobes, n) valve-referred cam contact
    loads [N]; ``valve_acceleration`` (n_lobes, n) [m/s^2]; revolutions marched, converged,
    the last relative change; steps per revolution; contact changes located in the last
    revolution and the steps of it that had more than the kernel's limit of them."""

    loads: np.ndarray
    valve_acceleration: np.ndarray
    cycles: int
    converged: bool
    change: float
    steps: int
    switches: int = 0
    cut: int = 0


def _periodic(values, theta_grid):
    """Periodic linear interpolant of grid values (for the ratio and friction coefficient)."""
    values = np.asarray(values, dtype=float) * np.ones_like(theta_grid)

    def at(theta):
        return np.interp(theta, theta_grid, values, period=2.0 * math.pi)

    return at


#: valve-referred load levels [N] of the friction tables (ratio 10^(1/8): the coefficient
#: between levels is linear in ln W)
FRICTION_LEVELS = np.geomspace(0.1, 1.0e5, 49)


def _table_at(table, levels, w, cols):
    """The tabulated coefficient (``table`` (levels, grid)) at loads ``w`` and grid columns
    ``cols`` (same shape), linear in ln W as the kernel reads it, held beyond the levels."""
    x = np.clip(np.log(np.maximum(w, levels[0]) / levels[0]) / math.log(levels[1] / levels[0]),
                0.0, levels.size - 1.0)
    i = np.minimum(x.astype(int), levels.size - 2)
    t = x - i
    return (1.0 - t) * table[i, cols] + t * table[i + 1, cols]


def _own_columns(theta_grid, phases):
    """Grid column, in each lobe's own angle frame, of every grid angle of the shaft."""
    step = 2.0 * math.pi / theta_grid.size
    local = theta_grid[None, :] - np.asarray(phases, dtype=float)[:, None]
    return np.rint((local - theta_grid[0]) / step).astype(int) % theta_grid.size


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


def march_coupled(shaft, train, cam, ratio, axes, phases, omega: float, *, substeps: int,
                  friction=None, friction_arm=None, turn: float = 1.0, cycles_max: int = 30,
                  period_tol: float = 1e-5, start=None,
                  friction_table=None) -> MonolithicResult:
    """March the shaft and one copy of ``train`` per lobe to their common periodic state.

    Args:
        shaft: :class:`~camtrain.camshaft.elastic.ElasticShaft` (lobes in the order of
            ``phases``).
        train: the lumped train of every lobe (:class:`~camtrain.dynamics.train.TrainModel`).
        cam: its rigid valve-lift input (:class:`~camtrain.dynamics.excitation.CamInput`), in
            the lobe's own angle frame (maximum lift at 0).
        ratio: rocker ratio on the grid (valve motion per follower motion at the cam).
        axes, phases: each lobe's follower-axis angle and angle of maximum lift [rad].
        omega: constant camshaft speed [rad/s].
        substeps: time steps per grid interval.
        friction_table: callable(load levels [N], valve-referred) -> the friction coefficient
            (levels, n) of the contact under each constant load on the grid, in the lobe's own
            angle frame (the steady film and the deck's friction law depend only on the angle's
            kinematics and load). The march takes each contact's coefficient from its current
            load at every step (linear in ln W between the levels of
            :data:`FRICTION_LEVELS`).
        friction: callable(loads (n_lobes, n) in the shaft's frame) -> the contact model's
            friction coefficient (n_lobes, n) under those loads. With ``friction_table`` it
            corrects the table after every revolution by the table's error at that
            revolution's loads (the interpolation between levels errs most at a kink of the
            law, e.g. where the boundary cap takes over), so that the coefficient is the
            contact model's own at the periodic state; alone (a film with a history, which no
            table holds) it gives the coefficient on the previous revolution's loads. Neither:
            no friction.
        friction_arm: the friction force's arm about the cam axis on the grid [m] (signed).
        turn: +1 anticlockwise shaft rotation, -1 clockwise.
        start: the single train's periodic response on a rigid shaft
            (:class:`~camtrain.dynamics.integrators.TrainResponse` on ``cam.theta``), or None.
            Given, every train starts from it at its lobe's angle and the shaft from its
            periodic answer to those trains' loads, so the march starts near the coupled
            periodic state instead of at rest (the shaft's torsion, lightly damped and slow,
            would otherwise take most of the revolutions to settle).
    """
    from ._coupled_kernel import revolution
    from .train import CAM, SEAT

    theta_grid = cam.theta
    grid = theta_grid.size
    n_lobes = len(phases)
    beam, tors = shaft.beam, shaft.torsion
    Kb, Mb, Cb = beam.K, beam.M, beam.C
    nb = Kb.shape[0]
    Kt, Jt, Ct = tors.K, tors.J, tors.C
    ntor = Kt.shape[0]
    nt = train.size
    n = 2 * nb + ntor + n_lobes * nt
    M = np.zeros((n, n))
    K = np.zeros((n, n))
    C = np.zeros((n, n))
    for off in (0, nb):
        M[off:off + nb, off:off + nb] = Mb
        K[off:off + nb, off:off + nb] = Kb
        C[off:off + nb, off:off + nb] = Cb
    t0 = 2 * nb
    M[t0:t0 + ntor, t0:t0 + ntor] = Jt
    K[t0:t0 + ntor, t0:t0 + ntor] = Kt
    C[t0:t0 + ntor, t0:t0 + ntor] = Ct
    f0 = np.zeros(n)
    tr0 = t0 + ntor
    for j in range(n_lobes):
        s = slice(tr0 + j * nt, tr0 + (j + 1) * nt)
        M[s, s] = np.diag(train.mass)
        K[s, s] = train.stiffness
        C[s, s] = train.damping
        f0[s] = train.preload
    # indices of every lobe's shaft coordinates
    free_b = {int(d): i for i, d in enumerate(beam.free)}
    free_t = {int(d): i for i, d in enumerate(tors.free)}
    ix = np.array([free_b[int(beam.v_index[node])] for node in shaft.lobe_nodes])
    iy = ix + nb
    iphi = np.array([t0 + free_t[int(node)] for node in shaft.lobe_nodes])
    ifol = tr0 + np.arange(n_lobes) * nt + train.uni_node[CAM]
    ival = tr0 + np.arange(n_lobes) * nt + train.uni_node[SEAT]
    valve_dof = tr0 + np.arange(n_lobes) * nt + train.valve
    kc, cc, offc = train.uni_k[CAM], train.uni_c[CAM], train.uni_offset[CAM]
    ks, cs_, offs = train.uni_k[SEAT], train.uni_c[SEAT], train.uni_offset[SEAT]

    steps = grid * int(substeps)
    period = 2.0 * math.pi / omega
    dt = period / steps
    a0, a1 = 4.0 / dt ** 2, 2.0 / dt
    Ainv = np.linalg.inv(K + a1 * C + a0 * M)
    P, Q, x_f0 = Ainv @ M, Ainv @ C, Ainv @ f0
    # the linear part is block diagonal: both bending planes, the twist, each train
    blocks = np.array([0, nb, 2 * nb, tr0] + [tr0 + (j + 1) * nt for j in range(n_lobes)],
                      dtype=np.int64)
    Minv = np.linalg.inv(M)      # block diagonal as M (the acceleration after a switch)
    # A^-1 of every basis vector a contact gradient is made of: (x, y, phi, follower, valve)
    ainv_basis = np.empty((n, 5 * n_lobes))
    for j in range(n_lobes):
        for k, dof in enumerate((ix[j], iy[j], iphi[j], ifol[j], ival[j])):
            ainv_basis[:, 5 * j + k] = Ainv[:, dof]
    # the inputs at every step of a revolution, in each lobe's own angle frame
    theta = theta_grid[0] + omega * dt * np.arange(1, steps + 1)
    local = theta[None, :] - np.asarray(phases, dtype=float)[:, None]
    lift, d1, _ = cam.evaluate(local)
    r = _periodic(ratio, theta_grid)(local)
    arm = _periodic(np.zeros(grid) if friction_arm is None else friction_arm, theta_grid)(local)
    cosa, sina = np.cos(axes), np.sin(axes)
    gx, gy = r * cosa[:, None], r * sina[:, None]
    # friction coefficient tables (n_lobes, levels, steps): in the current load, or lagged
    ln_first, ln_step = 0.0, 1.0
    if friction_table is not None:
        levels = FRICTION_LEVELS
        ln_first, ln_step = math.log(levels[0]), math.log(levels[1] / levels[0])
        grid_mu = np.asarray(friction_table(levels), dtype=float)      # (levels, grid), own
        mu = np.stack([np.array([np.interp(local[j], theta_grid, row, period=2.0 * math.pi)
                                 for row in grid_mu]) for j in range(n_lobes)])
    else:
        mu = np.zeros((n_lobes, 1, steps))
    # the table's error at the last revolution's loads, when the exact law is also given
    corr = np.zeros((n_lobes, steps))
    q, v, acc = np.zeros(n), np.zeros(n), np.zeros(n)  # at rest: the start-up transient decays
    act_c = np.zeros(n_lobes, dtype=bool)
    act_s = np.ones(n_lobes, dtype=bool)
    if start is not None:
        drag = None
        if friction_table is not None:
            drag = (grid_mu, FRICTION_LEVELS,
                    np.zeros(grid) if friction_arm is None else friction_arm, float(turn))
        q, v, acc, act_c, act_s = _warm_start(
            start, cam, theta_grid, phases, ratio, axes, shaft, train, M, K, C, f0, omega,
            dict(ix=ix, iy=iy, iphi=iphi, ifol=ifol, ival=ival, nb=nb, t0=t0, tr0=tr0),
            lift[:, -1], d1[:, -1] * omega, gx[:, -1], gy[:, -1], d1[:, -1], drag)
    w_prev = np.zeros(n_lobes)
    if start is not None and friction is not None and friction_table is None:
        # the lagged coefficient on the start's loads
        at = theta_grid[None, :] - np.asarray(phases, dtype=float)[:, None]
        grid_mu = friction(np.interp(at, start.theta, np.maximum(start.contact_force[CAM], 0.0),
                                     period=2.0 * math.pi))
        mu = np.array([_periodic(grid_mu[j], theta_grid)(theta) for j in range(n_lobes)])
        mu = mu[:, None, :]
    switches = cut = 0
    loads = np.zeros((n_lobes, grid))
    valve_acc = np.zeros((n_lobes, grid))
    previous, change, cycle = None, math.inf, 0
    for cycle in range(1, int(cycles_max) + 1):
        switches, cut = revolution(
            q, v, acc, act_c, act_s, w_prev, x_f0, P, Q, blocks, ainv_basis, K, C, M, Minv, f0,
            lift,
            d1 * omega, gx, gy, d1, mu, corr, ln_first, ln_step, arm, r, cosa, sina, float(turn), kc,
            cc, ks, cs_, offc, offs, a0, a1, dt, ix, iy, iphi, ifol, ival, valve_dof, int(substeps), loads,
            valve_acc)
        if friction is not None and friction_table is not None:
            # correct the table by its error at this revolution's loads: the coefficient is
            # the contact model's own at the periodic state, and follows the load in between
            exact = friction(loads)
            tabled = _table_at(grid_mu, FRICTION_LEVELS, loads, _own_columns(theta_grid, phases))
            error = np.where(loads > 0.0, exact - tabled, 0.0)
            corr = np.array([_periodic(error[j], theta_grid)(theta) for j in range(n_lobes)])
        elif friction is not None:  # the coefficient on this revolution's loads, for the next
            grid_mu = friction(loads)
            mu = np.array([_periodic(grid_mu[j], theta_grid)(theta) for j in range(n_lobes)])
            mu = mu[:, None, :]
        if previous is not None:
            scale = max(float(np.max(np.abs(loads))), 1e-12)
            change = float(np.max(np.abs(loads - previous))) / scale
            if change <= period_tol and cycle >= 2:
                break
        previous = loads.copy()
    return MonolithicResult(loads.copy(), valve_acc.copy(), cycle, change <= period_tol,
                            change, steps, int(switches), int(cut))




def _warm_start(start, cam, theta_grid, phases, ratio, axes, shaft, train, M, K, C, f0, omega, idx,
                b0, bd0, gx0, gy0, gphi0, drag=None):
    """State at the march's first angle from the single train's periodic response (see
    :func:`march_coupled`): each train at its lobe's angle, the shaft at its periodic answer
    to the trains' contact forces and torques (with their friction when ``drag`` = (coefficient
    table (levels, grid) in the lobe's frame, load levels, friction arm on the grid, turn) is
    given), the follower (and an open valve) moved with the lobe, the contact states from
    their indicators and the acceleration from the equilibrium."""
    from .train import CAM

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
    for j in range(n_lobes):
        fb[idx["ix"][j]] -= w[j] * rr[j] * math.cos(axes[j])
        fb[idx["iy"][j]] -= w[j] * rr[j] * math.sin(axes[j])
        ft[idx["iphi"][j] - t0] -= w[j] * lift_rate[j]
    if drag is not None:     # friction: the tangential force and the torque mu W r
        table, levels, arm_grid, turn = drag
        arm = np.interp(local, theta_grid, arm_grid, period=period)
        mu_all = _table_at(table, levels, w, _own_columns(theta_grid, phases))
        for j in range(n_lobes):
            fr = mu_all[j] * rr[j] * w[j]
            tang = -turn * fr * np.where(arm[j] >= 0.0, 1.0, -1.0)
            fb[idx["ix"][j]] -= tang * math.sin(axes[j])
            fb[idx["iy"][j]] += tang * math.cos(axes[j])
            ft[idx["iphi"][j] - t0] -= fr * arm[j]
    for lo, hi, force in ((0, nb, fb[:nb]), (nb, 2 * nb, fb[nb:])):
        q[lo:hi], v[lo:hi] = _periodic_start(K[lo:hi, lo:hi], M[lo:hi, lo:hi], C[lo:hi, lo:hi],
                                             force, omega)
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
