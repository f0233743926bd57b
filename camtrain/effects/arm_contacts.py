"""Arm contacts effect: the valve pad and the pivot of a finger follower or rocker.

Physics: :mod:`camtrain.mechanisms.arm_contacts` (pad sliding speed on the valve tip, pad load
from the arm's moment balance, pad Hertz stress, pivot reaction and friction torque). The powers
are per valve train and are not included in ``power_loss_mean`` (the cam contact's).
"""
from __future__ import annotations

from camtrain.metric_rows import CaseMetric, one_case

PIVOTED = ("finger", "rocker")


def missing(deck) -> list[str]:
    if deck.mechanism.type not in PIVOTED:
        return ["a finger follower or rocker (mechanism.type)"]
    return [] if deck.mechanism.arm is not None else ["[mechanism.arm] section"]


def reason(deck, planned) -> str:
    arm = deck.mechanism.arm
    pivot = "ball socket" if deck.mechanism.type == "finger" else "rocker shaft"
    if arm.pivot_model == "journal":
        how = f"as a plain journal bearing ({arm.pivot_film} film, hydrodynamic)"
    else:
        how = f"friction {arm.pivot_friction:g} x reaction x radius"
    return (f"[mechanism.arm] given: {arm.pad_shape} valve pad (sliding, Hertz, friction "
            f"{arm.pad_friction:g}) and {pivot} {how}")


def arm_metrics(arm, theta) -> list:
    """Cycle-mean powers and the peaks of the pad and pivot (CaseMetric rows)."""
    import numpy as np

    from camtrain.formulas import cycle_mean

    pad, pivot = cycle_mean(arm.pad_friction_power), cycle_mean(arm.pivot_friction_power)
    i, j = int(np.argmax(arm.pad_max_pressure)), int(np.argmax(np.abs(arm.pad_sliding_speed)))
    return [
        CaseMetric("pad_power_mean", pad, "W", "cycle-mean friction power at the valve pad"),
        CaseMetric("pivot_power_mean", pivot, "W", "cycle-mean friction power at the pivot"),
        CaseMetric("arm_power_mean", pad + pivot, "W", "cycle-mean pad and pivot friction "
                   "power, one valve train (not included in power_loss_mean)"),
        CaseMetric("pad_pressure_max", arm.pad_max_pressure[i], "Pa",
                   "largest Hertz pressure at the valve pad", theta[i]),
        CaseMetric("pad_sliding_speed_max", abs(arm.pad_sliding_speed[j]), "m/s",
                   "largest sliding speed of the pad on the valve tip", theta[j]),
        CaseMetric("pivot_reaction_max", float(np.max(arm.pivot_reaction)), "N",
                   "largest pivot reaction", theta[int(np.argmax(arm.pivot_reaction))]),
    ]


_COLUMNS = (
    ("pad_sliding_speed", "m/s", "sliding speed of the arm over the valve tip at the pad"),
    ("pad_travel", "m", "pad contact position across the valve tip from its base-circle place"),
    ("pad_load", "N", "normal load at the valve pad (the arm's moment balance)"),
    ("pad_max_pressure", "Pa", "Hertz maximum pressure at the valve pad"),
    ("pad_friction_power", "W", "friction power at the valve pad"),
    ("pivot_reaction", "N", "pivot reaction on the arm (cam and pad forces)"),
    ("pivot_friction_torque", "N*m", "pivot friction torque (coefficient x reaction x radius, "
     "or the rocker shaft's journal-bearing torque)"),
    ("pivot_friction_power", "W", "friction power at the pivot"),
)


def pivot_bearing(deck):
    """The rocker shaft as a :class:`camtrain.bearings.JournalBearing` (pivot_model =
    journal), or None for the Coulomb pivot."""
    from camtrain.bearings import JournalBearing
    from camtrain.errors import field_error

    arm = deck.mechanism.arm
    if arm.pivot_model != "journal":
        return None
    if deck.mechanism.type != "rocker":
        raise field_error("mechanism.arm.pivot_model", "a journal pivot is a rocker's shaft; "
                          "a finger follower pivots in a ball socket", arm.pivot_model,
                          "coefficient")
    eta = arm.pivot_viscosity
    if eta is None and deck.lubricant is not None:
        eta = deck.lubricant.viscosity
    if eta is None:
        raise field_error("mechanism.arm.pivot_viscosity", "is needed for a journal pivot "
                          "without a [lubricant] section", None, "the shaft oil's viscosity")
    return JournalBearing(2.0 * arm.pivot_radius, arm.pivot_length, arm.pivot_clearance, eta,
                          name="rocker shaft")


def run(deck, inputs, res):
    from camtrain.assemble.mechanism import body_inertia, pivot_geometry, pivot_kind
    from camtrain.contact.model import modulus
    from camtrain.loads import ContactLoad
    from camtrain.mechanisms import TrainKinematics
    from camtrain.mechanisms.arm_contacts import arm_contacts

    kin, load = inputs[TrainKinematics].main, inputs[ContactLoad]
    mech, arm = deck.mechanism, deck.mechanism.arm
    geometry = pivot_geometry(mech, deck.cam.base_radius, pivot_kind(mech))
    out = arm_contacts(kin, geometry, load.load, mu=load.mu,
                       follower_inertia=body_inertia(deck)["follower_inertia"],
                       pad_radius=arm.pad_radius, pad_shape=arm.pad_shape,
                       pad_width=arm.pad_width, pad_friction=arm.pad_friction,
                       pivot_radius=arm.pivot_radius, pivot_friction=arm.pivot_friction,
                       reduced_modulus=modulus(deck), pivot_bearing=pivot_bearing(deck),
                       pivot_film=arm.pivot_film)
    res.add_columns([(name, getattr(out, name), unit, text) for name, unit, text in _COLUMNS])
    res.add_metrics(one_case(arm_metrics(out, kin.theta)))
    return out
