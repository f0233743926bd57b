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
numerical damping), the contact states found by an active-set iteration inside each step. The
linear part's effective matrix is factorised once; the active contacts enter each step as a
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
    from scipy.linalg import lu_factor, lu_solve

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
    Khat = K + a1 * C + a0 * M
    lu = lu_factor(Khat)
    # A^-1 of every basis vector a contact gradient is made of
    basis = np.zeros((n, 5 * n_lobes))
    for j in range(n_lobes):
        for b, dof in enumerate((ix[j], iy[j], iphi[j], ifol[j], ival[j])):
            basis[dof, 5 * j + b] = 1.0
    Ainv_basis = lu_solve(lu, basis)
    ratio_at = _periodic(ratio, theta_grid)
    cosa, sina = np.cos(axes), np.sin(axes)
    arm_at = _periodic(np.zeros(grid) if friction_arm is None else friction_arm, theta_grid)

    mu = np.zeros((n_lobes, grid))
    mu_at = [(_periodic(mu[j], theta_grid)) for j in range(n_lobes)]
    q = np.zeros(n)
    v = np.zeros(n)
    acc = np.zeros(n)  # at rest; the start-up transient decays over the revolutions
    previous = None
    change = math.inf
    samples_load = np.zeros((n_lobes, grid))
    samples_acc = np.zeros((n_lobes, grid))
    t = 0.0
    cycle = 0
    w_prev = np.zeros(n_lobes)
    for cycle in range(1, int(cycles_max) + 1):
        for step in range(steps):
            t_next = t + dt
            theta = theta_grid[0] + omega * t_next
            local = theta - np.asarray(phases)
            lift, d1, _ = cam.evaluate(local)
            rate = lift * 0.0 + omega
            b, bd = lift, d1 * rate
            r = ratio_at(local)
            # gradients of every cam contact: shaft part (x, y, phi) and follower -1
            gx, gy, gphi = r * cosa, r * sina, d1
            rhs = f0 + M @ (a0 * q + (4.0 / dt) * v + acc) + C @ (a1 * q + v)
            # friction (explicit, from the last step's load): the tangential force on the shaft
            # opposes its rotation, the torque F r resists it (cam-level F = mu R W)
            mu_now = np.array([mu_at[j](local[j]) for j in range(n_lobes)])
            arm = arm_at(local)
            fric = mu_now * r * w_prev
            tangential = -turn * fric * np.sign(np.where(arm == 0, 1.0, arm))
            rhs[ix] += -tangential * sina
            rhs[iy] += tangential * cosa
            rhs[iphi] += -fric * arm
            # active-set iteration
            active_c = np.zeros(n_lobes, dtype=bool)
            active_s = np.zeros(n_lobes, dtype=bool)
            delta_c = b + offc - q[ifol] + gx * q[ix] + gy * q[iy] + gphi * q[iphi]
            delta_s = offs - q[ival]
            active_c = delta_c > 0.0
            active_s = delta_s > 0.0
            for _ in range(8):
                qn, W = _solve_step(lu, rhs, Ainv_basis, active_c, active_s, gx, gy, gphi,
                                    kc, cc, ks, cs_, b, bd, offc, offs, q, v, a1,
                                    ix, iy, iphi, ifol, ival)
                dc = b + offc - qn[ifol] + gx * qn[ix] + gy * qn[iy] + gphi * qn[iphi]
                ds = offs - qn[ival]
                new_c, new_s = dc > 0.0, ds > 0.0
                if np.array_equal(new_c, active_c) and np.array_equal(new_s, active_s):
                    break
                active_c, active_s = new_c, new_s
            w_prev = W
            vn = a1 * (qn - q) - v
            an = a0 * (qn - q) - (4.0 / dt) * v - acc
            q, v, acc, t = qn, vn, an, t_next
            if (step + 1) % substeps == 0:
                g = ((step + 1) // substeps) % grid
                samples_load[:, g] = W
                samples_acc[:, g] = acc[valve_dof]
        # samples are at shaft angles theta_grid[0] + g * h: loads in the shaft frame
        if friction is not None:
            mu = friction(samples_load)
            mu_at = [_periodic(mu[j], theta_grid) for j in range(n_lobes)]
        if previous is not None:
            scale = max(float(np.max(np.abs(samples_load))), 1e-12)
            change = float(np.max(np.abs(samples_load - previous))) / scale
            if change <= period_tol and cycle >= 2:
                break
        previous = samples_load.copy()
    return MonolithicResult(samples_load.copy(), samples_acc.copy(), cycle,
                            change <= period_tol, change, steps)


def _solve_step(lu, rhs, Ainv_basis, active_c, active_s, gx, gy, gphi, kc, cc, ks, cs_, b, bd,
                offc, offs, q, v, a1, ix, iy, iphi, ifol, ival):
    """One Newmark step's displacement with the given contact states (Woodbury update)."""
    from scipy.linalg import lu_solve

    n_lobes = gx.size
    cols, rhs_add = [], np.zeros_like(rhs)
    for j in range(n_lobes):
        if active_c[j]:
            # gradient h = gx e_x + gy e_y + gphi e_phi - e_f (plus the friction's projection
            # would make the matrix unsymmetric: friction is applied explicitly below)
            coef = np.array([gx[j], gy[j], gphi[j], -1.0, 0.0])
            h_inv = Ainv_basis[:, 5 * j:5 * j + 5] @ coef
            kk = kc + a1 * cc
            hq = gx[j] * q[ix[j]] + gy[j] * q[iy[j]] + gphi[j] * q[iphi[j]] - q[ifol[j]]
            hv = gx[j] * v[ix[j]] + gy[j] * v[iy[j]] + gphi[j] * v[iphi[j]] - v[ifol[j]]
            force0 = kc * (b[j] + offc) + cc * (bd[j] - a1 * hq - hv)
            # f_c = -h (k delta + c delta'): constant part to the right-hand side
            rhs_add[ix[j]] -= gx[j] * force0
            rhs_add[iy[j]] -= gy[j] * force0
            rhs_add[iphi[j]] -= gphi[j] * force0
            rhs_add[ifol[j]] += force0
            cols.append((j, "c", coef, h_inv, kk))
        if active_s[j]:
            coef = np.array([0.0, 0.0, 0.0, 0.0, -1.0])
            h_inv = Ainv_basis[:, 5 * j:5 * j + 5] @ coef
            kk = ks + a1 * cs_
            force0 = ks * offs + cs_ * (-(-a1 * q[ival[j]] - v[ival[j]]))
            rhs_add[ival[j]] += force0
            cols.append((j, "s", coef, h_inv, kk))
    x0 = lu_solve(lu, rhs + rhs_add)
    if cols:
        m = len(cols)
        Hinv = np.column_stack([c[3] for c in cols])
        # H^T z for each column: h = coef on (x, y, phi, f, valve) dofs of lobe j
        def ht(z):
            out = np.empty(m)
            for i, (j, _, coef, _, _) in enumerate(cols):
                out[i] = (coef[0] * z[ix[j]] + coef[1] * z[iy[j]] + coef[2] * z[iphi[j]]
                          + coef[3] * z[ifol[j]] + coef[4] * z[ival[j]])
            return out

        HtAinvH = np.column_stack([ht(Hinv[:, i]) for i in range(m)])
        D = np.array([c[4] for c in cols])
        small = np.diag(1.0 / D) + HtAinvH
        y = np.linalg.solve(small, ht(x0))
        x = x0 - Hinv @ y
    else:
        x = x0
    # contact loads at the new state (valve-referred), friction applied for the next state's
    # right-hand side is explicit: here only the normal load is returned
    W = np.zeros(gx.size)
    for j in range(gx.size):
        d = b[j] + offc - x[ifol[j]] + gx[j] * x[ix[j]] + gy[j] * x[iy[j]] + gphi[j] * x[iphi[j]]
        if active_c[j] and d > 0.0:
            hq = gx[j] * x[ix[j]] + gy[j] * x[iy[j]] + gphi[j] * x[iphi[j]] - x[ifol[j]]
            hq0 = gx[j] * q[ix[j]] + gy[j] * q[iy[j]] + gphi[j] * q[iphi[j]] - q[ifol[j]]
            hv0 = gx[j] * v[ix[j]] + gy[j] * v[iy[j]] + gphi[j] * v[iphi[j]] - v[ifol[j]]
            dd = bd[j] + a1 * (hq - hq0) - hv0
            W[j] = max(kc * d + cc * dd, 0.0)
    return x, W
