"""Power effect: friction torque about the cam axis, total cam torque and friction power loss.

H(theta) = F r omega with r the arm of the friction force about the cam axis (Ball 1988 eq. 4.8;
r = r_B + l for a flat follower) and the cycle mean of eq. 4.9 (trapezoidal rule, spectrally
accurate on the periodic grid). The total torque adds the normal-load torque W e.
"""
from __future__ import annotations

import numpy as np

from camtrain.formulas import cam_torque, cycle_mean, friction_torque


def run(deck, state) -> None:
    kin = state.objects["kinematics"]
    load = np.maximum(state.objects["load"], 0.0)
    force = state.objects["friction"]
    res = state.result
    tf = np.asarray(friction_torque(force, kin.friction_arm), dtype=float)
    total = np.asarray(cam_torque(load, kin.torque_arm_normal, force, kin.friction_arm),
                       dtype=float)
    power = tf * abs(kin.omega)
    dissipation = force * np.abs(kin.sliding)
    res.add_column("friction_torque", tf, "N*m", "friction torque about the cam axis F r")
    res.add_column("cam_torque", total, "N*m", "total camshaft torque W e + F r")
    res.add_column("power_loss", power, "W", "friction power F r omega (Ball eq. 4.8)")
    i = int(np.argmax(np.abs(tf)))
    res.add_metric("friction_torque_peak", tf[i], "N*m", "largest friction torque", kin.theta[i])
    res.add_metric("power_loss_mean", cycle_mean(power), "W",
                   "cycle-mean friction power (Ball eq. 4.9)")
    res.add_metric("dissipation_mean", cycle_mean(dissipation), "W",
                   "cycle-mean contact dissipation F |V_s| (equals the above for flat followers)")
    res.add_metric("cam_torque_mean", cycle_mean(total), "N*m", "cycle-mean camshaft torque")
