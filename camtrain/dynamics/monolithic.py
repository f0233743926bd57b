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
    the last relative change; steps per revolution."""

    loads: np.ndarray
    valve_acceleration: np.ndarray
    cycles: int
    converged: bool
    change: float
    steps: int


def _periodic(values, theta_grid):
    """Periodic linear interpolant of grid values (for the ratio and friction coefficient)."""
    values = np.asarray(values, dtype=float) * np.ones_like(theta_grid)

    def at(theta):
        return np.interp(theta, theta_grid, values, period=2.0 * math.pi)

    return at


def march_coupled(shaft, train, cam, ratio, axes, phases, omega: float, *, substeps: int,
                  friction=None, friction_arm=None, turn: float = 1.0, cycles_max: int = 30,
                  period_tol: float = 1e-5) -> MonolithicResult:
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
        friction: callable(loads (n_lobes, n) in the lobes' frames) -> friction coefficient
            (n_lobes, n), or None (no friction).
        friction_arm: the friction force's arm about the cam axis on the grid [m] (signed).
        turn: +1 anticlockwise shaft rotation, -1 clockwise.
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
    mu = np.zeros((n_lobes, steps))
    q, v, acc = np.zeros(n), np.zeros(n), np.zeros(n)  # at rest: the start-up transient decays
    w_prev = np.zeros(n_lobes)
    loads = np.zeros((n_lobes, grid))
    valve_acc = np.zeros((n_lobes, grid))
    previous, change, cycle = None, math.inf, 0
    for cycle in range(1, int(cycles_max) + 1):
        revolution(q, v, acc, w_prev, x_f0, P, Q, blocks, ainv_basis, lift, d1 * omega, gx, gy, d1, mu,
                   arm, r, cosa, sina, float(turn), kc, cc, ks, cs_, offc, offs, a0, a1, dt,
                   ix, iy, iphi, ifol, ival, valve_dof, int(substeps), loads, valve_acc)
        if friction is not None:  # the coefficient on this revolution's loads, for the next
            grid_mu = friction(loads)
            mu = np.array([_periodic(grid_mu[j], theta_grid)(theta) for j in range(n_lobes)])
        if previous is not None:
            scale = max(float(np.max(np.abs(loads))), 1e-12)
            change = float(np.max(np.abs(loads - previous))) / scale
            if change <= period_tol and cycle >= 2:
                break
        previous = loads.copy()
    return MonolithicResult(loads.copy(), valve_acc.copy(), cycle, change <= period_tol,
                            change, steps)


