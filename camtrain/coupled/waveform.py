"""The waveform solver: every lobe's train marched to its periodic state on the shaft's lobe
motion, the shaft's periodic answer to the trains' loads, passes of the two until the lobes'
motion agrees (block Gauss-Seidel over whole revolutions, Teodorescu et al. 2005 §2.6, §4;
accelerated and preconditioned as :mod:`.relaxation` and :mod:`.interface` describe). Its
iteration is :func:`.relaxation.waveform_relaxation` over :meth:`Waveform.one_pass`."""
from __future__ import annotations

import math

import numpy as np

from .problem import CoupledResult

LABEL = "waveform iteration"


def solve(problem) -> CoupledResult:
    return Waveform(problem).solve()


class Waveform:
    """One pass maps the lobes' motion (displacement along the follower axis and twist per
    lobe, rows scaled alike) to the shaft's motion under the trains' loads; each train starts
    from its state of the previous pass (fewer revolutions)."""

    def __init__(self, problem):
        self.problem = problem
        self.responses = [None] * problem.lobes
        self.scale = np.ones(2)

    def shaft(self, loads):
        """The shaft's answer to every lobe's cam-level load (lobes, n; shaft frame)."""
        from camtrain.camshaft import shift_curve

        from .lobes import shaft_answer, shaft_loads

        p = self.problem
        own = [np.maximum(shift_curve(loads[j], -g), 0.0) for j, g in enumerate(p.phases)]
        forces, torques, _ = shaft_loads(p, own)
        return shaft_answer(p, forces, torques)

    def trains(self, along, twist):
        """Every lobe's train marched on its lobe's motion: its cam-level load (shaft frame)."""
        from camtrain.camshaft import shift_curve
        from camtrain.dynamics import CamInput, march

        from .relaxation import lobe_input_perturbation

        p = self.problem
        cam, new = p.cam, []
        for j, g in enumerate(p.phases):
            delta, d1, d2 = lobe_input_perturbation(shift_curve(along[j], -g),
                                                    shift_curve(twist[j], -g), p.ratio,
                                                    p.kin.valve_d1)
            moved = CamInput(cam.theta, cam.lift + delta, cam.d1 + d1, cam.d2 + d2)
            self.responses[j] = march(p.train, moved, p.base, p.settings,
                                      start=self.responses[j])
            new.append(shift_curve(self.responses[j].contact_force[0] * p.ratio, g))
        return np.array(new)

    def motion(self, out):
        """Each lobe's displacement along its follower axis [m] and its twist [rad]."""
        axes = self.problem.axes
        along = (out.deflection_x * np.cos(axes)[:, None]
                 + out.deflection_y * np.sin(axes)[:, None])
        return along, out.twist

    def one_pass(self, x):
        n = self.problem.lobes
        loads = self.trains(x[:n] * self.scale[0], x[n:] * self.scale[1])
        along, twist = self.motion(self.shaft(loads))
        return np.vstack([along / self.scale[0], twist / self.scale[1]])

    def start(self):
        """The first motion (the shaft's answer to the rigid trains' loads, or to the
        monolithic march's) and that march's loads, or None."""
        from camtrain.camshaft import shift_curve

        from .monolithic import marched

        p = self.problem
        if p.coupling.start == "monolithic":
            loads = marched(p, staggered=False, answer=False)
            return self.motion(self.shaft(loads)), loads
        rigid = np.array([shift_curve(np.maximum(p.rigid_load, 0.0), g) for g in p.phases])
        return self.motion(self.shaft(rigid)), None

    def solve(self) -> CoupledResult:
        from .relaxation import waveform_relaxation

        p, c, n = self.problem, self.problem.coupling, self.problem.lobes
        (along0, twist0), marched = self.start()
        # rows scaled so a pass's change weighs displacement and twist alike
        self.scale = np.array([max(float(np.max(np.abs(along0))), 1e-15),
                               max(float(np.max(np.abs(twist0))), 1e-15)])
        precondition = None
        if c.preconditioner == "interface_newton":
            precondition = interface_newton(p)
        start = np.vstack([along0 / self.scale[0], twist0 / self.scale[1]])
        if precondition is not None and marched is None:
            # the start is the pass from the rigid shaft's motion (zero): its Newton step
            start = precondition(start)
        state = waveform_relaxation(self.one_pass, start, tol=c.tolerance,
                                    max_iterations=c.passes, relaxation=c.relaxation,
                                    method=c.method, precondition=precondition)
        loads = self.trains(state.motion[:n] * self.scale[0], state.motion[n:] * self.scale[1])
        return CoupledResult(loads, self._accelerations(), self.shaft(loads), LABEL,
                             state.iterations, state.change, state.converged,
                             start_gap=_gap(loads, marched), separations=self._separations())

    def _accelerations(self):
        from camtrain.camshaft import shift_curve

        p = self.problem
        return [shift_curve(self.responses[j].a[p.train.valve], g)
                for j, g in enumerate(p.phases)]

    def _separations(self):
        """Per lobe, the shaft angles where its cam loses the follower while the valve is in
        flight (a landing on the seat is not a separation)."""
        from camtrain.dynamics.findings import findings

        return tuple(tuple(math.remainder(s.loss + g, 2 * math.pi)
                           for s in findings(self.responses[j]).separations if s.in_flight)
                     for j, g in enumerate(self.problem.phases))


def _gap(loads, marched):
    """Largest difference of any lobe's load to the march the iteration started from, over
    the largest marched load (None without)."""
    if marched is None:
        return None
    return float(np.max(np.abs(loads - marched))) / max(float(np.max(marched)), 1e-300)


def interface_newton(problem):
    """The waveform pass's linear Jacobian on the lobes' motion along their follower axes
    (:mod:`.interface`): shaft receptance between the lobes (both planes, projected on the
    axes) times each train's dynamic contact stiffness, R^2 g."""
    from camtrain.camshaft.flexible_response import lobe_receptance

    from .interface import contact_stiffness
    from .interface import interface_newton as newton

    p = problem
    orders = np.arange(p.theta.size // 2 + 1)
    plane = lobe_receptance(p.shaft.beam, p.shaft.lobe_nodes, p.omega, orders)
    along = plane * np.cos(p.axes[:, None] - p.axes[None, :])[None]
    r2 = float(np.mean(p.ratio)) ** 2
    train = contact_stiffness(p.train, p.omega, orders) * r2
    # the load pushes the lobe away from its follower: -S G
    return newton(-along * train[:, None, None], slice(0, p.lobes))
