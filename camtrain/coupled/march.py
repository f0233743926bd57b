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
compiled revolution at a time (:mod:`._revolution`). The linear part's effective matrix is
inverted once; the active contacts enter each step as a
low-rank update (Woodbury), because every contact's gradient lies in a fixed four-vector
subspace (x_j, y_j, phi_j, u_follower,j) with time-varying coefficients. Friction of each
contact enters as a tangential force mu_j W_j on the shaft and a torque mu W r, with mu_j from
the contact's current load (a steady film) or its current load and film (the level-1 squeeze
film, carried per contact as state: :mod:`.film`), explicit by one step. The drive's
hub load (a belt: |T|/r + 2 preload along the hub-load angle, T the summed lobe torque) acts at
the drive station, its torque-dependent part explicit by one step. Revolutions are marched from
the single train's periodic state until two agree at the grid samples.

Why the friction tables are corrected after every revolution (:func:`march_coupled`): the
friction laws have kinks (where
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

The compiled kernels take the records of :mod:`.records`, built here.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .adjusters import adjuster_record, adjusters_start
from .assembly import assemble
from .records import (
    Drive,
    Friction,
    Layout,
    Lobes,
    Matrices,
    Samples,
    Scheme,
    State,
    Stepper,
    System,
    workspace,
)
from .tables import FRICTION_LEVELS, own_columns, periodic, table_at

__all__ = ["MonolithicResult", "march_coupled", "FRICTION_LEVELS"]


@dataclass(frozen=True)
class MonolithicResult:
    """Periodic state on the run's grid: ``loads`` (n_lobes, n) valve-referred cam contact
    loads [N]; ``valve_acceleration`` (n_lobes, n) [m/s^2]; revolutions marched, converged,
    the last relative change; steps per revolution; contact changes located in the last
    revolution and the steps of it that had more than the kernel's limit of them; ``film``
    (n_lobes, n) every contact's level-1 film [m] (held where the contact is open), or None
    without the squeeze film; ``missed`` the staggered steps of the last revolution whose
    passes did not agree within the iterations allowed; ``adjuster`` (n_lobes, 2, n) every
    lash adjuster's chamber pressure [Pa, gauge] and plunger extension [m], or None without
    adjusters."""

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
    adjuster: np.ndarray | None = None


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
        film: a :class:`~camtrain.coupled.film.SqueezeFilmModel` (the level-1 squeeze
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
            (:mod:`._partition`): the shaft under each contact's ``predictor`` load
            (``constant`` or ``linear``), then the trains with the shaft's lobe motion
            prescribed; ``iterations`` passes of a step at most, until the load a pass
            produces agrees with its prediction within ``step_tol`` of the largest load (1: a
            single pass, the loosely coupled scheme).
        speed: the drive's time base (:class:`~camtrain.dynamics.excitation.TimeBase`) when
            its speed oscillates (Williams 2013 App A6): every lobe then turns with the drive's
            angle plus its twist, the twist (measured from the drive) carries the inertia load
            -J theta'', and the results are carried from their sample times onto the grid
            angles, as the single train's march does. None: constant speed ``omega``.
    """
    from ._partition import PREDICTORS
    from .film import start_film

    n_lobes = len(phases)
    asm = assemble(shaft, train, n_lobes)
    steps = cam.theta.size * int(substeps)
    dt = 2.0 * math.pi / omega / steps
    sysm, f0, hub = _system(asm, train, drive, dt)
    lob, theta, oscillates = _lobe_inputs(cam, ratio, axes, phases, omega, dt, steps, speed,
                                          friction_arm, turn)
    if film is not None:
        friction_table = friction = None
    path = _FrictionPath(cam.theta, theta, phases, ratio, friction, friction_table, film)
    state = _start(asm, lob, path, cam, train, (f0, sysm.mats.Minv), hub, start,
                   (phases, ratio, axes, omega), friction_arm)
    if start is not None and film is not None:
        state.film[:] = start_film(film, start, cam.theta, phases, ratio, omega)
    if staggered:   # the shaft's first predicted loads: the start's contact loads
        state.w_prev[:] = _start_loads(state, lob, train, asm)
        state.w_older[:] = state.w_prev
    if start is not None:
        path.lagged_start(start)
    scheme = Scheme(bool(staggered), PREDICTORS[predictor], int(iterations), float(step_tol),
                    int(substeps))
    loads, valve_acc, films, cycle, change, counts, adjuster = _revolutions(
        sysm, lob, path, scheme, state, cycles_max, period_tol)
    if oscillates:  # samples are uniform in time: carry them onto the grid angles
        from camtrain.dynamics.integrators import samples_to_grid

        grid, theta_grid = cam.theta.size, cam.theta
        at = theta_grid[0] + speed.angle(np.arange(grid) * (2.0 * math.pi / omega) / grid)[0]
        loads = samples_to_grid(loads, at, theta_grid)
        valve_acc = samples_to_grid(valve_acc, at, theta_grid)
        films = samples_to_grid(films, at, theta_grid)
        adjuster = np.stack([samples_to_grid(adjuster[:, k], at, theta_grid) for k in (0, 1)],
                            axis=1)
    return MonolithicResult(loads.copy(), valve_acc.copy(), cycle, change <= period_tol,
                            change, steps, int(counts[0]), int(counts[1]),
                            films.copy() if film is not None else None, int(counts[2]),
                            adjuster.copy() if train.series is not None else None)


def _revolutions(sysm, lob, path, scheme, state, cycles_max, period_tol):
    """Revolutions from the start until two agree at the grid samples (the friction corrected
    after each): the last one's loads, valve accelerations and films, revolutions, the last
    change and (contact changes, steps cut short, staggered steps missed) of the last.

    With lash adjusters every revolution is followed by the secant rule on every chamber's
    oil content (:func:`.adjusters.accelerate_chambers`), and two revolutions agree when the
    plungers' extensions do as well as the loads (:func:`_change`)."""
    from ._lowrank import dof_table
    from ._revolution import revolution
    from .adjusters import accelerate_chambers, chamber_contents

    n_lobes, grid = lob.b.shape[0], path.theta_grid.size
    out = Samples(np.zeros((n_lobes, grid)), np.zeros((n_lobes, grid)),
                  np.zeros((n_lobes, grid)), np.zeros((n_lobes, 2, grid)))
    dof = dof_table(sysm.lay)
    contents = chamber_contents(sysm.hla, state, sysm.lay) if sysm.hla.on else None
    series = None if contents is None else (contents, None)
    counts = (0, 0, 0)
    previous, change, cycle = None, math.inf, 0
    for cycle in range(1, int(cycles_max) + 1):
        work, at, pre = workspace(state.q.size, dof)
        counts = revolution(sysm, lob, path.record(), scheme, state, out, work, at, pre)
        path.after(out.load, out.film)
        if series is not None:
            series = accelerate_chambers(sysm, state, series)
        if cycle > 1:
            change = _change(out, previous, sysm.hla)
            if change <= period_tol:
                break
        previous = (out.load.copy(), out.hla[:, 1].copy())
    return out.load, out.acc, out.film, cycle, change, counts, out.hla


def _change(out, previous, hla) -> float:
    """The revolution's relative change from the ``previous`` one's (loads, extensions): the
    largest change of a load over the largest load, and with lash adjusters
    :func:`.adjusters.extension_change` (a chamber still pumping up or leaking down is not
    periodic even where the loads hardly move)."""
    from .adjusters import extension_change

    loads, extensions = previous
    scale = max(float(np.max(np.abs(out.load))), 1e-12)
    change = float(np.max(np.abs(out.load - loads))) / scale
    if hla.on:
        change = max(change, extension_change(out.hla[:, 1], extensions, hla))
    return change


def _system(asm, train, drive, dt):
    """The march's set-once record (:data:`.records.System`) for the step ``dt``, the constant
    forces with the belt's preload, and the belt (pitch radius, direction) or None."""
    from camtrain.dynamics.records import unilateral

    from ._lowrank import basis_rows

    M, K, C, f0 = asm.M, asm.K, asm.C, asm.f0.copy()
    n = M.shape[0]
    hub_x = hub_y = -1
    hub_dir, hub_radius = (0.0, 0.0), 1.0
    if drive is not None and asm.hub_x >= 0:
        hub_radius, angle, preload = (float(v) for v in drive)
        hub_x, hub_y = asm.hub_x, asm.hub_y
        hub_dir = (math.cos(angle), math.sin(angle))
        f0[hub_x] += 2.0 * preload * hub_dir[0]       # the preload's part: constant
        f0[hub_y] += 2.0 * preload * hub_dir[1]
    a0, a1 = 4.0 / dt ** 2, 2.0 / dt
    Ainv = np.linalg.inv(K + a1 * C + a0 * M)
    P, Q, x_f0 = Ainv @ M, Ainv @ C, Ainv @ f0
    Minv = np.linalg.inv(M)      # block diagonal as M (the acceleration after a switch)
    n_lobes = asm.ix.size
    hla, ipl = adjuster_record(asm, train)
    # A^-1 of every basis vector a contact gradient is made of: (x, y, phi, follower, valve;
    # the plunger, where an adjuster's chamber pushes)
    lay = Layout(asm.ix, asm.iy, asm.iphi, asm.ifol, asm.ival, asm.valve, asm.blocks, ipl)
    width = 6 if hla.on else 5
    ainv_basis = np.empty((width * n_lobes, n))      # one row per coordinate (see Stepper)
    for j in range(n_lobes):
        dofs = (asm.ix[j], asm.iy[j], asm.iphi[j], asm.ifol[j], asm.ival[j], ipl[j] if hla.on
                else -1)
        for k in range(width):
            ainv_basis[width * j + k, :] = Ainv[:, dofs[k]]
    hub_basis = (np.ascontiguousarray(Ainv[:, [hub_x, hub_y]]) if hub_x >= 0
                 else np.zeros((n, 2)))
    drive_j = np.zeros(n)      # J 1 on the twist coordinates: the drive's inertia load
    drive_j[asm.t0:asm.tr0] = M[asm.t0:asm.tr0, asm.t0:asm.tr0].sum(axis=1)
    tr = np.ascontiguousarray      # the step's products run along rows of the transposes
    step = Stepper(dt, a0, a1, x_f0, tr(P.T), tr(Q.T), ainv_basis, basis_rows(ainv_basis, lay))
    hub = Drive(hub_x, hub_y, hub_dir[0], hub_dir[1], hub_radius, hub_basis, drive_j,
                Ainv @ drive_j)
    sysm = System(lay, Matrices(tr(K.T), tr(C.T), tr(M.T), Minv, tr(Minv.T), f0), step, hub,
                  unilateral(train), hla)
    return sysm, f0, None if hub_x < 0 else (hub_radius, hub_dir, f0[hub_x], f0[hub_y])


def _lobe_inputs(cam, ratio, axes, phases, omega, dt, steps, speed, friction_arm, turn):
    """Every lobe's inputs at every step of a revolution (:data:`.records.Lobes`), in each
    lobe's own angle frame, the shaft's angle at every step and whether the drive's speed
    oscillates."""
    theta_grid = cam.theta
    grid = theta_grid.size
    theta = theta_grid[0] + omega * dt * np.arange(1, steps + 1)
    rate, drive_acc = np.full(steps, omega), np.zeros(steps)
    oscillates = speed is not None and bool(speed.amplitude) and bool(speed.order)
    if oscillates:
        angle, rate, drive_acc = speed.angle(dt * np.arange(1, steps + 1))
        theta = theta_grid[0] + angle
    local = theta[None, :] - np.asarray(phases, dtype=float)[:, None]
    lift, d1, _ = cam.evaluate(local)
    r = periodic(ratio, theta_grid)(local)
    arm_grid = np.zeros(grid) if friction_arm is None else friction_arm
    arm = periodic(arm_grid, theta_grid)(local)
    cosa, sina = np.cos(axes), np.sin(axes)
    gx, gy = r * cosa[:, None], r * sina[:, None]
    lob = Lobes(lift, d1 * rate, gx, gy, d1, arm, r, cosa, sina, float(turn), drive_acc)
    return lob, theta, oscillates


class _FrictionPath:
    """How the march takes each contact's friction coefficient (see :func:`march_coupled`):
    from tables in the current load (and film), corrected after every revolution by the
    table's error at its loads, or from the contact model on the previous revolution's loads
    (lagged); :meth:`record` is the kernel's :data:`.records.Friction`."""

    def __init__(self, theta_grid, theta, phases, ratio, friction, friction_table, film):
        from .film import film_state

        self.theta_grid, self.theta, self.phases, self.ratio = theta_grid, theta, phases, ratio
        self.friction, self.friction_table, self.film = friction, friction_table, film
        n_lobes, steps = len(phases), theta.size
        local = theta[None, :] - np.asarray(phases, dtype=float)[:, None]
        self.grid_mu = None
        ln_first, ln_step = 0.0, 1.0
        if friction_table is not None:
            levels = FRICTION_LEVELS
            ln_first, ln_step = math.log(levels[0]), math.log(levels[1] / levels[0])
            self.grid_mu = np.asarray(friction_table(levels), dtype=float)   # (levels, grid)
            self.mu = np.stack([np.array([np.interp(local[j], theta_grid, row,
                                                    period=2.0 * math.pi)
                                          for row in self.grid_mu]) for j in range(n_lobes)])
        else:
            self.mu = np.zeros((n_lobes, 1, steps))
        self.fs = film_state(film, theta_grid, local, n_lobes, theta_grid.size)
        if film is not None:
            ln_first = math.log(film.levels[0])
            ln_step = math.log(film.levels[1] / film.levels[0])
        self.ln = (ln_first, ln_step)
        # the table's error at the last revolution's loads, when the exact law is also given
        self.corr = np.zeros((n_lobes, steps))

    def record(self):
        fs = self.fs
        return Friction(self.mu, self.corr, self.ln[0], self.ln[1], self.film is not None,
                        self.film is not None and self.film.squeeze, fs["unit"],
                        fs["exponent"], fs["speed"], fs["table"], fs["col"], fs["ln_r0"],
                        fs["d_ln_r"])

    def drag(self, arm_grid, turn):
        """The friction of the warm start: (coefficient table in the lobe's frame, load
        levels, friction arm, turn, whether the levels are cam-level), or None."""
        if self.grid_mu is not None:
            return (self.grid_mu, FRICTION_LEVELS, arm_grid, turn, False)
        if self.film is not None:
            one = int(np.argmin(np.abs(np.log(self.fs["ratios"]))))
            return (self.film.table[one], self.film.levels, arm_grid, turn, True)
        return None

    def lagged_start(self, start):
        """The lagged coefficient on the start's loads (no table, the law alone)."""
        from camtrain.dynamics.train import CAM

        if self.friction is None or self.friction_table is not None:
            return
        at = self.theta_grid[None, :] - np.asarray(self.phases, dtype=float)[:, None]
        self.grid_mu = self.friction(np.interp(at, start.theta,
                                               np.maximum(start.contact_force[CAM], 0.0),
                                               period=2.0 * math.pi))
        self._lag()

    def _lag(self):
        self.mu = self._spread(self.grid_mu)[:, None, :]

    def _spread(self, rows):
        """Grid rows (shaft frame) at every step's angle."""
        return np.array([periodic(rows[j], self.theta_grid)(self.theta)
                         for j in range(len(self.phases))])

    def after(self, loads, films):
        """Correct the tables (or lag the coefficient) after a revolution."""
        from .film import film_table_error

        if self.film is not None:
            # correct the table by its error at this revolution's loads and films
            self.corr = self._spread(film_table_error(self.film, loads, films, self.ratio,
                                                      self.theta_grid, self.phases))
        elif self.friction is not None and self.friction_table is not None:
            # correct the table by its error at this revolution's loads: the coefficient is
            # the contact model's own at the periodic state, and follows the load in between
            exact = self.friction(loads)
            tabled = table_at(self.grid_mu, FRICTION_LEVELS, loads,
                              own_columns(self.theta_grid, self.phases))
            error = np.where(loads >= FRICTION_LEVELS[0], exact - tabled, 0.0)
            self.corr = self._spread(error)
        elif self.friction is not None:  # the coefficient on this revolution's loads
            self.grid_mu = self.friction(loads)
            self._lag()


def _start(asm, lob, path, cam, train, forces, hub, start, lobes, friction_arm):
    """The march's :data:`.records.State`: at rest with the valves seated, or from the single
    train's periodic response ``start`` (:func:`.start.warm_start`; with lash adjusters its
    quiet start, which throws no follower off its cam: one that left its cam would pump its
    adjuster up); ``forces`` = (the constant forces, M^-1 of the system), ``lobes`` = (phases,
    ratio, axes, omega)."""
    from .start import warm_start

    f0, minv = forces
    phases, ratio, axes, omega = lobes
    n, n_lobes = asm.M.shape[0], len(phases)
    q, v, acc = np.zeros(n), np.zeros(n), np.zeros(n)  # at rest: the start-up transient decays
    act_c = np.zeros(n_lobes, dtype=bool)
    act_s = np.ones(n_lobes, dtype=bool)
    if start is not None:
        grid = path.theta_grid.size
        arm_grid = np.zeros(grid) if friction_arm is None else friction_arm
        drag = path.drag(arm_grid, float(lob.turn))
        q, v, acc, act_c, act_s = warm_start(
            start, cam, path.theta_grid, phases, ratio, axes, train, asm.M, asm.K, asm.C, f0,
            omega, asm, lob.b[:, -1], lob.bd[:, -1], lob.gx[:, -1], lob.gy[:, -1],
            lob.gphi[:, -1], drag, hub, quiet=train.series is not None)
    hp = np.zeros((n_lobes, 4))
    if train.series is not None:      # every chamber at rest: the supply pressure, no flow
        hp[:, 0] = train.series.adjuster.supply_pressure
        if start is not None:
            adjusters_start(asm, train, start, path.theta_grid, phases, (q, v, acc, hp), minv)
    return State(q, v, acc, act_c, act_s, np.zeros(n_lobes), np.zeros(n_lobes),
                 path.fs["h"], hp, hp.copy())


def _start_loads(state, lob, train, asm) -> np.ndarray:
    """Every closed cam contact's load k delta + c delta' in the state (inputs at the
    state's angle, the revolution's last step), never a pull."""
    from camtrain.dynamics.train import CAM

    q, v = state.q, state.v
    kc, cc, offc = train.uni_k[CAM], train.uni_c[CAM], train.uni_offset[CAM]
    b, bd, gx, gy, gphi = (a[:, -1] for a in (lob.b, lob.bd, lob.gx, lob.gy, lob.gphi))
    d = b + offc - q[asm.ifol] + gx * q[asm.ix] + gy * q[asm.iy] + gphi * q[asm.iphi]
    dd = bd - v[asm.ifol] + gx * v[asm.ix] + gy * v[asm.iy] + gphi * v[asm.iphi]
    return np.where(state.act_c, np.maximum(kc * d + cc * dd, 0.0), 0.0)
