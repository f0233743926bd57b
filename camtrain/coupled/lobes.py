"""What every coupled solver does with the lobes' loads (:mod:`camtrain.coupled`): the contact
model's friction at every angle of every lobe, the forces and torques each lobe puts on the
shaft, and the shaft's answer to them."""
from __future__ import annotations

import numpy as np

__all__ = ["LobeFriction", "shaft_loads", "shaft_answer"]


class LobeFriction:
    """The contact model's friction coefficient of the problem's lobes (the deck's film and
    friction law at every angle): :meth:`coefficients` under given loads, :meth:`table` under
    constant load levels."""

    def __init__(self, problem):
        self.problem = problem

    def own_frame(self, loads):
        """Cam-level loads of every lobe in its own angle frame."""
        from camtrain.camshaft import shift_curve

        p = self.problem
        return [np.maximum(shift_curve(loads[j] * 1.0, -g), 0.0) * p.ratio
                for j, g in enumerate(p.phases)]

    def coefficients(self, loads):
        """Coefficient (lobes, n; shaft frame) under valve-referred ``loads`` (shaft frame)."""
        from camtrain.camshaft import shift_curve

        p = self.problem
        mu = []
        for j, w in enumerate(self.own_frame(loads)):
            force = p.contact.solve(p.kin, w).force
            coefficient = np.divide(force, w, out=np.zeros_like(w), where=w > 0)
            mu.append(shift_curve(coefficient, p.phases[j]))
        return np.array(mu)

    def table(self, levels):
        """Coefficient under each constant valve-referred load level (levels, n; own frame)."""
        p = self.problem
        mu = []
        for level in levels:
            w = level * p.ratio
            force = p.contact.solve(p.kin, w).force
            mu.append(np.divide(force, w, out=np.zeros_like(w), where=w > 0))
        return np.array(mu)


def shaft_loads(problem, own):
    """Every lobe's force (fx, fy) and torque on the shaft (shaft frame) and its load in the
    shaft frame, from its cam-level load ``own[j]`` in its own angle frame (the contact's
    friction from the contact model)."""
    from camtrain.camshaft import lobe_force, shift_curve
    from camtrain.formulas import cam_torque

    kin, turn = problem.kin, problem.turn
    arm_sign = np.sign(np.where(kin.friction_arm == 0, 1.0, kin.friction_arm))
    forces, torques, loads = [], [], []
    for j, (g, w) in enumerate(zip(problem.phases, own, strict=True)):
        fr = problem.contact.solve(kin, w).force
        torque = cam_torque(w, kin.torque_arm_normal, fr, kin.friction_arm)
        forces.append(lobe_force(shift_curve(w, g), shift_curve(-turn * fr * arm_sign, g),
                                 problem.axes[j]))
        torques.append(shift_curve(np.asarray(torque, dtype=float), g))
        loads.append(shift_curve(w, g))
    return forces, np.array(torques), np.array(loads)


def shaft_answer(problem, forces, torques):
    """The shaft's answer to its lobes' forces ((fx, fy) per lobe), their torques and the
    drive's hub load from the summed torque."""
    from camtrain.camshaft import shaft_forces
    from camtrain.camshaft.elastic import shaft_answer as answer

    o = problem.options
    positions, fx, fy = shaft_forces(problem.shaft.lobe_positions, forces, torques.sum(axis=0),
                                     o.drive)
    return answer(problem.shaft, positions, fx, fy, torques, problem.omega, split=o.split,
                  response=o.response, overhang=o.overhang,
                  speed_amplitude=o.speed_amplitude, speed_order=o.speed_order,
                  theta=problem.theta)
