"""Time integration of the lumped train to its periodic state over camshaft revolutions.

Three integrators (``INTEGRATORS``), all marching whole revolutions from rest on the base circle
until two successive revolutions agree at the grid samples to ``period_tol`` (relative to the
largest displacement), the contract of the journal-orbit march:

* ``newmark`` (default): average acceleration, unconditionally stable and second order; contact
  changes located inside the step (compiled kernel, :mod:`camtrain.dynamics._kernel`).
* ``central_difference``: Teodorescu et al. 2005 eq. 17, explicit; refused (``StepTooLarge``)
  when the step exceeds ``stability_factor`` x 2/omega_max, naming the stiffest element.
* ``lsoda`` / ``radau``: scipy's adaptive ``solve_ivp`` with terminal events on each contact's
  indicator and a restart with the other contact state (analytic Jacobian, ``max_step`` bounded
  so a step cannot jump over a short separation; the reference solution of the tests).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camtrain.dynamics.excitation import CamInput, TimeBase
from camtrain.dynamics.train import CAM, SEAT, TrainModel, static_state

__all__ = ["INTEGRATORS", "Settings", "TrainResponse", "DynamicEvent", "StepTooLarge",
           "march", "auto_steps", "stability_limit"]

INTEGRATORS = ("newmark", "central_difference", "lsoda", "radau")
EVENT_NAMES = {(CAM, 0): "contact_loss", (CAM, 1): "contact_regained",
               (SEAT, 0): "seat_lift", (SEAT, 1): "seat_impact"}


#: an open contact closes when its force would exceed this fraction of the spring preload.
#: Zero: a positive threshold pumps energy (the contact closes on a pre-compressed spring) and
#: turns round-off ringing on the base circle into a limit cycle.
CLOSE_THRESHOLD = 0.0


class StepTooLarge(ValueError):
    """An explicit step above the stability limit (message names the element)."""


@dataclass(frozen=True)
class Settings:
    """Resolution and method: ``substeps`` steps per grid interval (so that every grid angle is
    a step), ``cycles_max`` revolutions at most, ``period_tol`` relative change between
    revolutions for the periodic state; ``rtol``/``atol`` [m] and ``max_step`` [rad of cam] for
    the adaptive integrators; ``stability_factor`` kappa of the explicit guard."""

    integrator: str = "newmark"
    substeps: int = 20
    cycles_max: int = 20
    cycles_min: int = 2
    period_tol: float = 1e-6
    rtol: float = 1e-8
    atol: float = 1e-11
    max_step: float = math.radians(0.25)
    stability_factor: float = 0.8


@dataclass(frozen=True)
class DynamicEvent:
    """A contact change: ``kind`` (contact_loss, contact_regained, seat_lift, seat_impact), cam
    ``angle`` [rad] in (-pi, pi], ``time`` [s] from the start of the last revolution and the
    contact's closing speed ``speed`` [m/s] (delta'; at a seat impact the valve's speed)."""

    kind: str
    angle: float
    time: float
    speed: float


@dataclass(frozen=True)
class TrainResponse:
    """Periodic response on the cam grid (valve-referred, SI).

    ``u``, ``v``, ``a``: displacement [m], velocity [m/s], acceleration [m/s^2] of every node
    (n x grid); ``contact_force``: cam and seat force [N] (2 x grid); ``cam``: the cam input b,
    b', b'' on the grid; ``events`` of the last revolution in time order; ``cycles`` marched,
    ``converged``, the last revolution-to-revolution ``change``; ``cam_work`` [J] of the last
    revolution; ``steps`` per revolution; ``cut_switches`` steps where the switch budget ran out.
    """

    theta: np.ndarray
    time: np.ndarray
    u: np.ndarray
    v: np.ndarray
    a: np.ndarray
    contact_force: np.ndarray
    cam: tuple[np.ndarray, np.ndarray, np.ndarray]
    events: tuple[DynamicEvent, ...]
    cycles: int
    converged: bool
    change: float
    cam_work: float
    steps: int
    integrator: str
    cut_switches: int = 0
    #: a hydraulic lash adjuster's rows (records.H_ROWS x grid): chamber pressure [Pa, gauge],
    #: check-valve and leak flows [m^3/s], plunger extension [m], the volumes [m^3] through the
    #: check valve and the annulus over each sample's interval, the check ball's lift [m]; None
    #: without one
    hydraulic: np.ndarray | None = None
    #: a marched roller's speed on its pin [rad/s], sliding speed [m/s] and traction [N]
    #: (3 x grid), None without one
    roller: np.ndarray | None = None

    def events_of(self, kind: str) -> list[DynamicEvent]:
        return [e for e in self.events if e.kind == kind]


def stability_limit(model: TrainModel, factor: float = 1.0) -> float:
    """Largest stable explicit step [s]: factor x 2 / omega_max (contacts closed)."""
    return factor * 2.0 / model.omega_max()


def auto_steps(model: TrainModel, base: TimeBase, grid: int, per_period: float = 20.0,
               steps_per_degree: float | None = None) -> int:
    """Substeps per grid interval: the shortest natural period / ``per_period``, or the given
    ``steps_per_degree`` (the step never exceeds one grid interval)."""
    if steps_per_degree is not None:
        per_rev = steps_per_degree * 360.0
    else:
        t_min = 2.0 * math.pi / model.omega_max()
        per_rev = base.period / (t_min / per_period)
    return max(1, math.ceil(per_rev / grid))


def _start_index(lift: np.ndarray) -> int:
    """Grid index in the middle of the longest dwell (lift at its minimum): the train starts
    there at rest."""
    low = lift <= lift.min() + 1e-9 * max(1.0, float(np.ptp(lift)))
    n = lift.size
    best, best_len = 0, -1
    shift = int(np.argmin(low)) if not low.all() else 0
    i = 0
    rolled = np.roll(low, -shift)
    while i < n:
        if rolled[i]:
            j = i
            while j < n and rolled[j]:
                j += 1
            if j - i > best_len:
                best, best_len = (shift + (i + j) // 2) % n, j - i
            i = j
        else:
            i += 1
    return best


def march(model: TrainModel, cam: CamInput, base: TimeBase, settings: Settings,
          start: TrainResponse | None = None) -> TrainResponse:
    """Periodic response of ``model`` driven by ``cam`` (see the module docstring). ``start``:
    a periodic response under a nearby input (e.g. the previous pass of an iteration); the
    fixed-step march then starts from its state at the start angle instead of from rest, and
    needs fewer revolutions (still at least ``cycles_min``)."""
    if settings.integrator not in INTEGRATORS:
        raise ValueError(f"unknown integrator {settings.integrator!r}")
    if model.roller is not None and settings.integrator != "newmark":
        raise ValueError("the roller's spin is marched by the newmark integrator only")
    grid = cam.theta.size
    sub = int(settings.substeps)
    steps = grid * sub
    dt = base.period / steps
    if settings.integrator == "central_difference":
        limit = stability_limit(model, settings.stability_factor)
        if dt > limit:
            e = model.stiffest()
            raise StepTooLarge(
                f"central-difference step {dt * 1e6:.3g} µs is above its stability limit "
                f"{limit * 1e6:.3g} µs (kappa {settings.stability_factor:g} x 2/omega_max); the "
                f"stiffest element is the {e.name} ({e.k:.4g} N/m on {e.mass:.4g} kg, "
                f"{e.omega / (2 * math.pi):.4g} Hz): use at least "
                f"{math.ceil(base.period / limit / 360.0)} steps per degree or the newmark "
                "integrator")
    i0 = _start_index(cam.lift)
    theta0 = float(cam.theta[i0])
    base = base.starting_at(theta0, float(cam.theta[0]))
    t = np.arange(steps + 1) * dt
    b, bd, bdd = cam.in_time(t, base, theta0)
    inputs = np.zeros((2, steps + 1))
    rates = np.zeros((2, steps + 1))
    inputs[CAM], rates[CAM] = b, bd
    geometry = _geometry(model, cam, base, t, theta0)
    if settings.integrator in ("newmark", "central_difference"):
        runner = _FixedStep(model, inputs, rates, dt, sub, settings.integrator, geometry)
        runner.spin_on(theta0 + base.angle(t)[0])
        if start is not None and settings.integrator == "newmark":
            runner.u = np.array(start.u[:, i0], dtype=float)
            runner.v = np.array(start.v[:, i0], dtype=float)
            runner.a = np.array(start.a[:, i0], dtype=float)
            runner.act = start.contact_force[:, i0] > 0.0
            if start.hydraulic is not None and model.series is not None:
                from camtrain.dynamics.hla import chamber_from

                chamber_from(runner.hp, start.hydraulic, i0)
            if start.roller is not None and model.roller is not None:
                runner.wr[:] = start.roller[:, i0]
    else:
        from camtrain.dynamics.adaptive import Adaptive

        runner = Adaptive(model, cam, base, theta0, dt * sub, grid, settings)
    previous = None
    change = math.inf
    for cycle in range(1, settings.cycles_max + 1):
        out = runner.revolution()
        if previous is not None:
            change = _change(out, previous, model.roller is not None)
            if change <= settings.period_tol and cycle >= settings.cycles_min:
                break
        previous = (out[0].copy(), out[8][0].copy() if len(out) > 8 else None)
    u, v, a, f, events, work, cut = out[:7]
    hydraulic = out[7] if len(out) > 7 and model.series is not None else None
    spin = out[8] if len(out) > 8 and model.roller is not None else None
    # sample r is grid index (i0 + r + 1) % grid: roll into grid order
    sample_t = (np.arange(grid) + 1) * dt * sub
    dyn_events = []
    for time, kind, speed in events:
        angle = theta0 + float(base.angle(np.array([time]))[0][0])
        angle = (angle + math.pi) % (2 * math.pi) - math.pi
        dyn_events.append(DynamicEvent(EVENT_NAMES[(kind // 2, kind % 2)], angle, time, speed))
    samples = {"time": sample_t[None, :], "u": u, "v": v, "a": a, "f": f,
               "cam": np.vstack((b[sub::sub], bd[sub::sub], bdd[sub::sub]))}
    if hydraulic is not None:
        samples["hla"] = hydraulic
    if spin is not None:
        samples["roller"] = spin
    if base.amplitude and base.order:
        # samples are uniform in time, not in angle: carry them onto the grid angles
        angle = theta0 + base.angle(sample_t)[0]
        on_grid = {k: samples_to_grid(val, angle, cam.theta) for k, val in samples.items()}
    else:
        order = (np.arange(grid) - i0 - 1) % grid   # sample r is grid angle (i0 + r + 1) % grid
        on_grid = {k: val[:, order] for k, val in samples.items()}
    return TrainResponse(theta=cam.theta, time=on_grid["time"][0], u=on_grid["u"],
                         v=on_grid["v"], a=on_grid["a"], contact_force=on_grid["f"],
                         cam=tuple(on_grid["cam"]), events=tuple(dyn_events), cycles=cycle,
                         converged=change <= settings.period_tol, change=change, cam_work=work,
                         steps=steps, integrator=settings.integrator, cut_switches=cut,
                         hydraulic=on_grid.get("hla"), roller=on_grid.get("roller"))


def _change(out, previous, spin: bool) -> float:
    """The largest change between two revolutions: of any displacement relative to the largest
    displacement and, with a marched roller, of its speed relative to its largest speed."""
    scale = max(float(np.max(np.abs(out[0]))), 1e-12)
    change = float(np.max(np.abs(out[0] - previous[0]))) / scale
    if spin:
        w = out[8][0]
        scale = max(float(np.max(np.abs(w))), 1e-12)
        change = max(change, float(np.max(np.abs(w - previous[1]))) / scale)
    return change


def revolution_from(model: TrainModel, cam: CamInput, base: TimeBase, substeps: int,
                    u0, v0, active, theta0: float = 0.0):
    """One Newmark revolution from a given state (displacements ``u0`` [m], velocities ``v0``
    [m/s], contact states ``active`` (cam, seat)) at cam angle ``theta0`` [rad]: the test of an
    undamped periodic cycle starts from a known periodic state instead of rest.

    Returns (u, v, a, contact forces) at the grid samples, the events and the cam work [J]."""
    grid = cam.theta.size
    steps = grid * int(substeps)
    dt = base.period / steps
    base = base.starting_at(theta0, float(cam.theta[0]))
    t = np.arange(steps + 1) * dt
    b, bd, _ = cam.in_time(t, base, theta0)
    inputs = np.zeros((2, steps + 1))
    rates = np.zeros((2, steps + 1))
    inputs[CAM], rates[CAM] = b, bd
    runner = _FixedStep(model, inputs, rates, dt, int(substeps), "newmark",
                        _geometry(model, cam, base, t, theta0))
    runner.u = np.array(u0, dtype=float)
    runner.v = np.array(v0, dtype=float)
    runner.act = np.array(active, dtype=np.bool_)
    force = model.preload - model.stiffness @ runner.u - model.damping @ runner.v
    if model.cam_law is not None:
        raise ValueError("revolution_from marches a linear cam contact")
    for j in range(2):
        if runner.act[j]:
            i = model.uni_node[j]
            force[i] += (model.uni_k[j] * (inputs[j, 0] - runner.u[i] + model.uni_offset[j])
                         + model.uni_c[j] * (rates[j, 0] - runner.v[i]))
    runner.a = force / model.mass
    u, v, a, f, events, work = runner.revolution()[:6]
    return u, v, a, f, events, work


def _geometry(model: TrainModel, cam: CamInput, base: TimeBase, t, theta0: float):
    """The kernel's contact-law arguments (law, constants, cam radius and load ratio at the step
    times t): law 0 and empty arrays for a linear cam contact."""
    if model.cam_law is None:
        return 0, np.zeros(5), np.zeros(0), np.zeros(0)
    if cam.radius is None:
        raise ValueError("a Hertz cam contact needs the cam's radius of curvature in its input")
    radius, ratio = cam.geometry(theta0 + base.angle(t)[0])
    return 1, model.cam_law.as_array(), radius, ratio


def samples_to_grid(rows: np.ndarray, angle: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Rows sampled at increasing ``angle`` (one revolution) interpolated (linear, periodic) at
    the grid angles ``theta``."""
    wrapped = np.mod(angle - theta[0], 2.0 * math.pi)
    return np.array([np.interp(theta - theta[0], wrapped, row, period=2.0 * math.pi)
                     for row in rows])


class _FixedStep:
    """Newmark or central difference over one revolution per call (compiled kernel)."""

    def __init__(self, model, inputs, rates, dt, stride, integrator, geometry=None):
        from camtrain.dynamics import _kernel

        self.geometry = geometry or (0, np.zeros(5), np.zeros(0), np.zeros(0))
        self.kernel = _kernel
        self.model, self.inputs, self.rates, self.dt, self.stride = (model, inputs, rates, dt,
                                                                     stride)
        self.explicit = integrator == "central_difference"
        n = model.size
        u0, act = static_state(model)
        self.u = u0.copy()
        self.v = np.zeros(n)
        self.a = np.zeros(n)
        self.u_prev = u0.copy()
        self.act = act.astype(np.bool_)   # the valve rests on its seat
        self.psi_prev = np.where(act, model.uni_k * 1e-9, 0.0)
        self.thr = np.full(2, CLOSE_THRESHOLD * max(model.spring_preload, 1.0))
        from camtrain.dynamics.hla import march_record

        self.hla, self.hp = march_record(model, u0)
        if model.series is not None and self.explicit:
            raise ValueError("the hydraulic lash adjuster's chamber is marched by the newmark "
                             "integrator only")
        from camtrain.dynamics.spin import no_roller

        self.spin = no_roller()
        self.wr = np.zeros(3)

    def spin_on(self, angles) -> None:
        """The roller's record at the step angles [rad] of a revolution (a model with a roller),
        its speed started at pure rolling at the first of them."""
        from camtrain.dynamics.spin import spin_record, spin_start

        if self.model.roller is None:
            return
        self.spin = spin_record(self.model.roller, angles)
        self.wr[:] = spin_start(self.spin)

    def revolution(self):
        from camtrain.dynamics.records import (
            H_ROWS,
            CamLaw,
            Inputs,
            Marched,
            Train,
            TrainState,
            unilateral,
        )

        m = self.model
        grid = (self.inputs.shape[1] - 1) // self.stride
        n = m.size
        cap = 10_000
        out = Marched(np.empty((n, grid)), np.empty((n, grid)), np.empty((n, grid)),
                      np.empty((2, grid)), np.empty(cap), np.empty(cap, dtype=np.int64),
                      np.empty(cap), np.zeros((len(H_ROWS), grid)), np.zeros((3, grid)))
        train = Train(m.mass, m.stiffness, m.damping, m.preload, m.uni_node, self.thr,
                      self.hla)
        inputs = Inputs(self.inputs, self.rates, self.dt, self.stride, 0.0)
        if self.explicit:   # v and a: the explicit scheme's work arrays
            state = TrainState(self.u, np.empty(n), np.empty(n), self.act, self.u_prev,
                               self.psi_prev, self.hp, self.wr)
            from camtrain.dynamics._explicit import central_difference_march as march
        else:
            state = TrainState(self.u, self.v, self.a, self.act, self.u, self.psi_prev, self.hp,
                               self.wr)
            march = self.kernel.newmark_march
        spin = () if self.explicit else (self.spin,)    # the roller marched by newmark only
        nev, work, cut = march(train, unilateral(m), CamLaw(*self.geometry), inputs, state, out,
                               *spin)
        nev = min(nev, cap)
        events = list(zip(out.ev_t[:nev].tolist(), out.ev_kind[:nev].tolist(),
                          out.ev_rate[:nev].tolist(), strict=True))
        return out.u, out.v, out.a, out.f, events, work, cut, out.h, out.r


def bilateral(model: TrainModel, contacts=(CAM, SEAT)) -> TrainModel:
    """The train with the listed contacts made permanent (bilateral) and the others removed:
    a linear system for free-vibration and modal checks."""
    from dataclasses import replace

    k, c = model.stiffness.copy(), model.damping.copy()
    for j in contacts:
        i = model.uni_node[j]
        k[i, i] += model.uni_k[j]
        c[i, i] += model.uni_c[j]
    zero = np.zeros_like(model.uni_k)
    return replace(model, stiffness=k, damping=c, uni_k=zero, uni_c=zero.copy())


def free_vibration(model: TrainModel, u0: np.ndarray, dt: float, steps: int,
                   integrator: str = "newmark") -> np.ndarray:
    """Displacements [m] (n x steps) of the linear part of ``model`` released from ``u0`` at
    rest without external force (unilateral contacts of zero stiffness stay open)."""
    from camtrain.dynamics import _kernel

    n = model.size
    inputs = np.zeros((2, steps + 1))
    u = np.array(u0, dtype=float)
    v = np.zeros(n)
    a = -(model.stiffness @ u) / model.mass
    act = np.zeros(2, dtype=np.bool_)
    from camtrain.dynamics.hla import no_adjuster
    from camtrain.dynamics.records import Inputs, Marched, Train, TrainState, linear_law, unilateral
    from camtrain.dynamics.spin import no_roller

    out = Marched(np.empty((n, steps)), np.empty((n, steps)), np.empty((n, steps)),
                  np.empty((2, steps)), np.empty(1), np.empty(1, dtype=np.int64), np.empty(1),
                  np.zeros((4, steps)), np.zeros((3, steps)))
    train = Train(model.mass, model.stiffness, model.damping, np.zeros(n), model.uni_node,
                  np.zeros(2), no_adjuster())
    drive = Inputs(inputs, inputs, dt, 1, 0.0)
    if integrator == "central_difference":
        u_prev = u - dt * v + 0.5 * dt * dt * a
        state = TrainState(u, np.empty(n), np.empty(n), act, u_prev, np.zeros(2), np.zeros(4),
                           np.zeros(3))
        from camtrain.dynamics._explicit import central_difference_march

        central_difference_march(train, unilateral(model), linear_law(), drive, state, out)
    else:
        state = TrainState(u, v, a, act, u, np.zeros(2), np.zeros(4), np.zeros(3))
        _kernel.newmark_march(train, unilateral(model), linear_law(), drive, state, out,
                              no_roller())
    return out.u
