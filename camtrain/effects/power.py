"""Power effect: friction torque about the cam axis, total cam torque and friction power loss.

H(theta) = F r omega with r the arm of the friction force about the cam axis (Ball 1988 eq. 4.8;
r = r_B + l for a flat follower) and the cycle mean of eq. 4.9 (trapezoidal rule, spectrally
accurate on the periodic grid). The total torque adds the normal-load torque W e. A desmodromic
train reports both pairs (the closing pair as the result's ``closing`` component) and their sum.
The guide losses are the ``guides`` effect's.
"""
from __future__ import annotations

from camtrain.metric_rows import CaseMetric, at, one_case


def missing(deck) -> list[str]:
    return []


def reason(deck, planned) -> str:
    return "friction available"


def run(deck, inputs, res):
    from camtrain.components import MAIN, result_component
    from camtrain.contact.products import CamTorque, ContactFriction
    from camtrain.loads.product import ContactLoad
    from camtrain.mechanisms.base import TrainKinematics

    train, loads = inputs[TrainKinematics], inputs[ContactLoad]
    friction = inputs[ContactFriction]
    total, main = 0.0, None
    for component, load in loads.pairs():
        mean, torques = run_pair(train[component], load, friction[component].force, res,
                                 result_component(component))
        total += mean
        if component == MAIN:
            main = torques
    if len(loads.pairs()) > 1:
        res.add_metric("power_loss_total", total, "W", "cycle-mean friction power of "
                       "both cam/follower pairs of the desmodromic train")
    return CamTorque(*main, total_power=total)


def pair_torques(kin, load, force):
    """Friction torque F r, total cam torque W e + F r, friction power F r omega and contact
    dissipation F |V_s| per angle (Ball 1988 eq. 4.8), for a run or every case of a sweep batch
    ((cases, angles) arrays); ``load`` >= 0."""
    import numpy as np

    from camtrain.formulas.cycle import cam_torque, friction_torque

    tf = np.asarray(friction_torque(force, kin.friction_arm), dtype=float)
    total = np.asarray(cam_torque(load, kin.torque_arm_normal, force, kin.friction_arm),
                       dtype=float)
    return tf, total, tf * abs(kin.omega), force * np.abs(kin.sliding)


def power_metrics(theta, tf, power, dissipation, total, tag: str = "") -> list:
    """Peak friction torque and the cycle means of power, dissipation and cam torque (Ball eq.
    4.9), for a run or every case of a sweep batch (:class:`camtrain.metric_rows.CaseMetric`)."""
    import numpy as np

    from camtrain.formulas.cycle import cycle_mean

    i = np.abs(tf).argmax(axis=-1)
    return [
        CaseMetric("friction_torque_peak", at(tf, i), "N*m", "largest friction torque" + tag,
                   at(theta, i)),
        CaseMetric("power_loss_mean", cycle_mean(power), "W",
                   "cycle-mean friction power (Ball eq. 4.9)" + tag),
        CaseMetric("dissipation_mean", cycle_mean(dissipation), "W",
                   "cycle-mean contact dissipation F |V_s| (equals the above for flat "
                   "followers)" + tag),
        CaseMetric("cam_torque_mean", cycle_mean(total), "N*m", "cycle-mean camshaft torque"
                   + tag)]


def run_pair(kin, load, force, res, component: str | None = None):
    """Columns and metrics of one pair; returns its cycle-mean friction power [W] and its
    (cam torque, friction torque, power) arrays."""
    import numpy as np


    tag = f" ({component} pair)" if component else ""
    tf, total, power, dissipation = pair_torques(kin, np.maximum(load, 0.0), force)
    res.add_columns((
        ("friction_torque", tf, "N*m", "friction torque about the cam axis F r" + tag),
        ("cam_torque", total, "N*m", "total camshaft torque W e + F r" + tag),
        ("power_loss", power, "W", "friction power F r omega (Ball eq. 4.8)" + tag)),
        component)
    metrics = power_metrics(kin.theta, tf, power, dissipation, total, tag)
    res.add_metrics(one_case(metrics), component)
    return float(metrics[1].value), (total, tf, power)


def run_cases(deck, inputs, cases):
    """:func:`run` over a leading case axis (:class:`camtrain.assemble.cases.Cases`): the main
    pair's torques and friction power of every case, and the metrics."""
    from camtrain.contact.products import CamTorque, ContactFriction
    from camtrain.loads.product import ContactLoad
    from camtrain.mechanisms.base import TrainKinematics

    kin = inputs[TrainKinematics].main
    tf, total, power, dissipation = pair_torques(
        kin, inputs[ContactLoad].carried, inputs[ContactFriction].main.force)
    metrics = power_metrics(kin.theta, tf, power, dissipation, total)
    cases.add_metrics(metrics)
    return CamTorque(total, tf, power, total_power=metrics[1].value)
