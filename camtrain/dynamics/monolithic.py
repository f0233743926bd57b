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
contact enters as a tangential force mu_j W_j on the shaft and a torque mu W r, with mu_j from
the contact's current load (a steady film) or its current load and film (the level-1 squeeze
film, carried per contact as state: :mod:`.coupled_film`), explicit by one step. The drive's
hub load (a belt: |T|/r + 2 preload along the hub-load angle, T the summed lobe torque) acts at
the drive station, its torque-dependent part explicit by one step. Revolutions are marched from
the single train's periodic state until two agree at the grid samples.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .monolithic_tables import FRICTION_LEVELS, own_columns, periodic, table_at

__all__ = ["MonolithicResult", "march_coupled", "FRICTION_LEVELS"]


@dataclass(frozen=True)
class MonolithicResult:
    """Periodic state on the run's grid: ``loads`` (n_lobes, n) valve-referred cam contact
    loads [N]; ``valve_acceleration`` (n_lobes, n) [m/s^2]; revolutions marched, converged,
    the last relative change; steps per revolution; contact changes located in the last
    revolution and the steps of it that had more than the kernel's limit of them; ``film``
    (n_lobes, n) every contact's level-1 film [m] (held where the contact is open), or None
    without the squeeze film; ``missed`` the staggered steps of the last revolution whose
    passes did not agree within the iterations allowed."""

    loads: np.ndarray
    valve_acceleration: np.ndarray
    cycles: int
    converged: bool
    change: float
    steps: int
    switches: int = 0
    cut: int = 0
    film: np.ndarray | None = None
    missed: int = 0


@dataclass(frozen=True)
class _System:
    """The assembled march: matrices (M, K, C, f0) and the state indices of every lobe's shaft
    coordinates (ix, iy, iphi), follower (ifol), seat (ival) and valve, the block boundaries
    and the drive station's bending coordinates (hub_x, hub_y; -1 at a rigid support)."""

    M: np.ndarray
    K: np.ndarray
    C: np.ndarray
    f0: np.ndarray
    ix: np.ndarray
    iy: np.ndarray
    iphi: np.ndarray
    ifol: np.ndarray
    ival: np.ndarray
    valve: np.ndarray
    blocks: np.ndarray
    nb: int
    t0: int
    tr0: int
    hub_x: int
    hub_y: int


def _assemble(shaft, train, n_lobes: int) -> _System:
    from .train import CAM, SEAT

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
    free_b = {int(d): i for i, d in enumerate(beam.free)}
    free_t = {int(d): i for i, d in enumerate(tors.free)}
    ix = np.array([free_b[int(beam.v_index[node])] for node in shaft.lobe_nodes])
    iphi = np.array([t0 + free_t[int(node)] for node in shaft.lobe_nodes])
    hub = free_b.get(int(beam.v_index[shaft.drive_node]), -1)
    # the linear part is block diagonal: both bending planes, the twist, each train
    blocks = np.array([0, nb, 2 * nb, tr0] + [tr0 + (j + 1) * nt for j in range(n_lobes)],
                      dtype=np.int64)
    trains = tr0 + np.arange(n_lobes) * nt
    return _System(M, K, C, f0, ix, ix + nb, iphi, trains + train.uni_node[CAM],
                   trains + train.uni_node[SEAT], trains + train.valve, blocks, nb, t0, tr0,
                   int(hub), int(hub + nb) if hub >= 0 else -1)


def march_coupled(shaft, train, cam, ratio, axes, phases, omega: float, *, substeps: int,
                  friction=None, friction_arm=None, turn: float = 1.0, cycles_max: int = 30,
                  period_tol: float = 1e-5, start=None, friction_table=None, film=None,
                  drive=None, staggered: bool = False, predictor: str = "linear",
                  iterations: int = 1, step_tol: float = 1e-6, speed=None) -> MonolithicResult:
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
        film: a :class:`~camtrain.dynamics.coupled_film.SqueezeFilmModel` (the level-1 squeeze
            film), or None. Given, every contact carries its film as state, marched once per
            accepted step, and its coefficient comes from its current load and film at every
            step (``friction_table`` and ``friction`` are then not used).
        friction: callable(loads (n_lobes, n) in the shaft's frame) -> the contact model's
            friction coefficient (n_lobes, n) under those loads. With ``friction_table`` it
            corrects the table after every revolution by the table's error at that
            revolution's loads, so that the coefficient is the contact model's own at the
            periodic state; alone (a film with a history other than the level-1 film, which
            no table holds) it gives the coefficient on the previous revolution's loads.
            Neither (nor ``film``): no friction.
        friction_arm: the friction force's arm about the cam axis on the grid [m] (signed).
        turn: +1 anticlockwise shaft rotation, -1 clockwise.
        start: the single train's periodic response on a rigid shaft
            (:class:`~camtrain.dynamics.integrators.TrainResponse` on ``cam.theta``), or None.
            Given, every train starts from it at its lobe's angle and the shaft from its
            periodic answer to those trains' loads, so the march starts near the coupled
            periodic state instead of at rest (the shaft's torsion, lightly damped and slow,
            would otherwise take most of the revolutions to settle).
        drive: (pitch radius [m], hub-load angle [rad], preload [N]) of a belt drive at the
            shaft's drive station (:func:`camtrain.camshaft.loads.pulley_load`), or None (no
            hub load).
        staggered: march shaft and trains in turn within every step instead of together
            (:mod:`._coupled_partition`): the shaft under each contact's ``predictor`` load
            (``constant`` or ``linear``), then the trains with the shaft's lobe motion
            prescribed; ``iterations`` passes of a step at most, until the load a pass
            produces agrees with its prediction within ``step_tol`` of the largest load (1: a
            single pass, the loosely coupled scheme).
        speed: the drive's time base (:class:`~camtrain.dynamics.excitation.TimeBase`) when
            its speed oscillates (Williams 2013 App A6): every lobe then turns with the drive's
            angle plus its twist, the twist (measured from the drive) carries the inertia load
            -J theta'', and the results are carried from their sample times onto the grid
            angles, as the single train's march does. None: constant speed ``omega``.

    Why the tables are corrected after every revolution: the friction laws have kinks (where
    Ball's boundary cap takes over, where Greenwood-Tripp asperity contact starts at lambda
    = 3) and there the interpolation between the table's levels errs by up to about 10 % of
    the coefficient. The correction by the table's error at the last revolution's loads (and
    films) makes the coefficient at every grid angle the contact model's own at the periodic
    state, and costs one evaluation of the law per revolution. Below the table's first load
    level (0.1 N) the table holds that level's coefficient and is not corrected: there the
    coefficient of a law with a Hertz area A ~ W^1/2 in it (Greenwood-Tripp's tau0 A / W)
    grows without bound as the load falls (7.8 at the 2e-13 N a grid sample caught as a
    contact closed), and a correction taken there would be applied at the next revolution's
    load at that angle, which can be hundreds of newtons.
    """
    from ._coupled_kernel import revolution
    from ._coupled_partition import PREDICTORS
    from .coupled_film import film_state, film_table_error, start_film
    from .monolithic_start import warm_start

    theta_grid = cam.theta
    grid = theta_grid.size
    n_lobes = len(phases)
    sysm = _assemble(shaft, train, n_lobes)
    M, K, C, f0 = sysm.M, sysm.K, sysm.C, sysm.f0.copy()
    n = M.shape[0]
    ix, iy, iphi, ifol, ival = sysm.ix, sysm.iy, sysm.iphi, sysm.ifol, sysm.ival
    from .train import CAM, SEAT
    kc, cc, offc = train.uni_k[CAM], train.uni_c[CAM], train.uni_offset[CAM]
    ks, cs_, offs = train.uni_k[SEAT], train.uni_c[SEAT], train.uni_offset[SEAT]
    hub_x = hub_y = -1
    hub_dir, hub_radius = (0.0, 0.0), 1.0
    if drive is not None and sysm.hub_x >= 0:
        hub_radius, angle, preload = (float(v) for v in drive)
        hub_x, hub_y = sysm.hub_x, sysm.hub_y
        hub_dir = (math.cos(angle), math.sin(angle))
        f0[hub_x] += 2.0 * preload * hub_dir[0]       # the preload's part: constant
        f0[hub_y] += 2.0 * preload * hub_dir[1]

    steps = grid * int(substeps)
    period = 2.0 * math.pi / omega
    dt = period / steps
    a0, a1 = 4.0 / dt ** 2, 2.0 / dt
    Ainv = np.linalg.inv(K + a1 * C + a0 * M)
    P, Q, x_f0 = Ainv @ M, Ainv @ C, Ainv @ f0
    Minv = np.linalg.inv(M)      # block diagonal as M (the acceleration after a switch)
    # A^-1 of every basis vector a contact gradient is made of: (x, y, phi, follower, valve)
    ainv_basis = np.empty((n, 5 * n_lobes))
    for j in range(n_lobes):
        for k, dof in enumerate((ix[j], iy[j], iphi[j], ifol[j], ival[j])):
            ainv_basis[:, 5 * j + k] = Ainv[:, dof]
    hub_basis = (np.ascontiguousarray(Ainv[:, [hub_x, hub_y]]) if hub_x >= 0
                 else np.zeros((n, 2)))
    # the inputs at every step of a revolution, in each lobe's own angle frame
    theta = theta_grid[0] + omega * dt * np.arange(1, steps + 1)
    rate, drive_acc = np.full(steps, omega), np.zeros(steps)
    oscillates = speed is not None and bool(speed.amplitude) and bool(speed.order)
    if oscillates:
        angle, rate, drive_acc = speed.angle(dt * np.arange(1, steps + 1))
        theta = theta_grid[0] + angle
    drive_j = np.zeros(n)      # J 1 on the twist coordinates: the drive's inertia load
    drive_j[sysm.t0:sysm.tr0] = M[sysm.t0:sysm.tr0, sysm.t0:sysm.tr0].sum(axis=1)
    drive_u = Ainv @ drive_j
    local = theta[None, :] - np.asarray(phases, dtype=float)[:, None]
    lift, d1, _ = cam.evaluate(local)
    r = periodic(ratio, theta_grid)(local)
    arm_grid = np.zeros(grid) if friction_arm is None else friction_arm
    arm = periodic(arm_grid, theta_grid)(local)
    cosa, sina = np.cos(axes), np.sin(axes)
    gx, gy = r * cosa[:, None], r * sina[:, None]
    # friction coefficient tables (n_lobes, levels, steps): in the current load, or lagged
    ln_first, ln_step = 0.0, 1.0
    grid_mu = None
    if film is not None:
        friction_table = friction = None
    if friction_table is not None:
        levels = FRICTION_LEVELS
        ln_first, ln_step = math.log(levels[0]), math.log(levels[1] / levels[0])
        grid_mu = np.asarray(friction_table(levels), dtype=float)      # (levels, grid), own
        mu = np.stack([np.array([np.interp(local[j], theta_grid, row, period=2.0 * math.pi)
                                 for row in grid_mu]) for j in range(n_lobes)])
    else:
        mu = np.zeros((n_lobes, 1, steps))
    fs = film_state(film, theta_grid, local, n_lobes, grid)
    if film is not None:
        ln_first, ln_step = math.log(film.levels[0]), math.log(film.levels[1] / film.levels[0])
    # the table's error at the last revolution's loads, when the exact law is also given
    corr = np.zeros((n_lobes, steps))
    q, v, acc = np.zeros(n), np.zeros(n), np.zeros(n)  # at rest: the start-up transient decays
    act_c = np.zeros(n_lobes, dtype=bool)
    act_s = np.ones(n_lobes, dtype=bool)
    if start is not None:
        drag = None
        if grid_mu is not None:
            drag = (grid_mu, FRICTION_LEVELS, arm_grid, float(turn), False)
        elif film is not None:
            one = int(np.argmin(np.abs(np.log(fs["ratios"]))))
            drag = (film.table[one], film.levels, arm_grid, float(turn), True)
        q, v, acc, act_c, act_s = warm_start(
            start, cam, theta_grid, phases, ratio, axes, train, M, K, C, f0, omega, sysm,
            lift[:, -1], d1[:, -1] * rate[-1], gx[:, -1], gy[:, -1], d1[:, -1], drag,
            None if hub_x < 0 else (hub_radius, hub_dir, f0[hub_x], f0[hub_y]))
        if film is not None:
            fs["h"][:] = start_film(film, start, theta_grid, phases, ratio, omega)
    w_prev = np.zeros(n_lobes)
    w_older = np.zeros(n_lobes)     # the load one step before w_prev (the linear predictor)
    if staggered:   # the shaft's first predicted loads: the start's contact loads
        w_prev[:] = _start_loads(q, v, act_c, lift[:, -1], d1[:, -1] * rate[-1], gx[:, -1],
                                 gy[:, -1], d1[:, -1], kc, cc, offc, sysm)
        w_older[:] = w_prev
    if start is not None and friction is not None and friction_table is None:
        # the lagged coefficient on the start's loads
        at = theta_grid[None, :] - np.asarray(phases, dtype=float)[:, None]
        grid_mu = friction(np.interp(at, start.theta, np.maximum(start.contact_force[CAM], 0.0),
                                     period=2.0 * math.pi))
        mu = np.array([periodic(grid_mu[j], theta_grid)(theta) for j in range(n_lobes)])
        mu = mu[:, None, :]
    switches = cut = missed = 0
    loads = np.zeros((n_lobes, grid))
    valve_acc = np.zeros((n_lobes, grid))
    films = np.zeros((n_lobes, grid))
    previous, change, cycle = None, math.inf, 0
    for cycle in range(1, int(cycles_max) + 1):
        switches, cut, missed = revolution(
            q, v, acc, act_c, act_s, w_prev, x_f0, P, Q, sysm.blocks, ainv_basis, K, C, M, Minv,
            f0, lift, d1 * rate, gx, gy, d1, mu, corr, ln_first, ln_step, arm, r, cosa, sina,
            float(turn), kc, cc, ks, cs_, offc, offs, a0, a1, dt, ix, iy, iphi, ifol, ival,
            sysm.valve, int(substeps), loads, valve_acc, film is not None,
            film is not None and film.squeeze, fs["h"], fs["unit"], fs["exponent"], fs["speed"],
            fs["table"], fs["col"], fs["ln_r0"], fs["d_ln_r"], films, hub_basis, hub_x, hub_y,
            hub_dir[0], hub_dir[1], hub_radius, bool(staggered), PREDICTORS[predictor],
            int(iterations), float(step_tol), w_older, drive_u, drive_j, drive_acc)
        if film is not None:
            # correct the table by its error at this revolution's loads and films
            error = film_table_error(film, loads, films, ratio, theta_grid, phases)
            corr = np.array([periodic(error[j], theta_grid)(theta) for j in range(n_lobes)])
        elif friction is not None and friction_table is not None:
            # correct the table by its error at this revolution's loads: the coefficient is
            # the contact model's own at the periodic state, and follows the load in between
            exact = friction(loads)
            tabled = table_at(grid_mu, FRICTION_LEVELS, loads, own_columns(theta_grid, phases))
            error = np.where(loads >= FRICTION_LEVELS[0], exact - tabled, 0.0)
            corr = np.array([periodic(error[j], theta_grid)(theta) for j in range(n_lobes)])
        elif friction is not None:  # the coefficient on this revolution's loads, for the next
            grid_mu = friction(loads)
            mu = np.array([periodic(grid_mu[j], theta_grid)(theta) for j in range(n_lobes)])
            mu = mu[:, None, :]
        if previous is not None:
            scale = max(float(np.max(np.abs(loads))), 1e-12)
            change = float(np.max(np.abs(loads - previous))) / scale
            if change <= period_tol and cycle >= 2:
                break
        previous = loads.copy()
    if oscillates:  # samples are uniform in time: carry them onto the grid angles
        from .integrators import samples_to_grid

        at = theta_grid[0] + speed.angle(np.arange(grid) * period / grid)[0]
        loads, valve_acc = samples_to_grid(loads, at, theta_grid), samples_to_grid(valve_acc, at, theta_grid)
        films = samples_to_grid(films, at, theta_grid)
    return MonolithicResult(loads.copy(), valve_acc.copy(), cycle, change <= period_tol,
                            change, steps, int(switches), int(cut),
                            films.copy() if film is not None else None, int(missed))


def _start_loads(q, v, act_c, b, bd, gx, gy, gphi, kc, cc, offc, sysm) -> np.ndarray:
    """Every closed cam contact's load k delta + c delta' in the state (q, v) (inputs at the
    state's angle), never a pull."""
    d = b + offc - q[sysm.ifol] + gx * q[sysm.ix] + gy * q[sysm.iy] + gphi * q[sysm.iphi]
    dd = bd - v[sysm.ifol] + gx * v[sysm.ix] + gy * v[sysm.iy] + gphi * v[sysm.iphi]
    return np.where(act_c, np.maximum(kc * d + cc * dd, 0.0), 0.0)
