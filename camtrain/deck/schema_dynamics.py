"""Deck section [dynamics]: the elastic valve train in time (docs/dynamics.md). Part of the deck
schema; with it the plan takes the dynamic contact load instead of the rigid train's.

The rigid train's data stay where they are ([spring], [masses], [clearance]); this section adds
what makes the train elastic: where the masses sit, the stiffness and damping of each element,
the valve seat, the spring's own mass (surge) and the integrator's knobs. Stiffnesses and masses
are referred to the valve (a push rod's along its own axis: the rocker ratio refers it).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import option, quantity, section
from camtrain.deck.schema_lash_adjuster import LashAdjusterSection, lash_adjuster_problems
from camtrain.errors import Problem

INTEGRATOR_NAMES = ("newmark", "central_difference", "lsoda", "radau")


@dataclass(frozen=True, kw_only=True)
class Dynamics:
    """Elastic valve train: lumped masses and stiffnesses, unilateral cam contact and valve seat,
    spring surge (Teodorescu et al. 2005 §2.5). Every value no source gives must be flagged as
    assumed where the deck sets it."""

    follower_mass: float = quantity(
        "Mass lumped at the cam side, referred to the valve (bucket; tappet + push rod x "
        "(D1/D2)^2 for a push-rod train); it is taken out of masses.valve_side, so the rigid "
        "train keeps its total mass. 0: one node (cam contact in series with the train)",
        "kg", default=0.0, ge=0, example=0.054)
    contact_model: Literal["linear", "hertz_line"] = option(
        "Cam contact spring: linear (contact_stiffness), or hertz_line (the Hertz line "
        "contact's own nonlinear load-approach relation from the materials, the cam width and "
        "the radii; needs a curved follower and a convex cam)", default="linear")
    contact_stiffness: float | None = quantity(
        "Cam/follower contact stiffness (linear unilateral spring; required by the linear "
        "contact model)", "N/mm", default=None, gt=0, example=2.0e5)
    follower_stiffness: float | None = quantity(
        "Stiffness of the follower or tappet (hydraulic lash adjuster) in series with the "
        "contact; omit for rigid", "N/mm", default=None, gt=0)
    pushrod_stiffness: float | None = quantity(
        "Push-rod stiffness along its axis (referred to the valve by the rocker arm ratio); "
        "omit for rigid", "N/mm", default=None, gt=0, applies="pushrod")
    rocker_stiffness: float | None = quantity(
        "Rocker (or finger) bending stiffness at the valve; omit for rigid", "N/mm",
        default=None, gt=0, applies="finger, rocker, pushrod")
    stem_stiffness: float | None = quantity(
        "Valve stem (and bucket) stiffness between the follower and the valve head; omit for "
        "rigid (with follower_mass > 0 a stem, rocker or push-rod stiffness is required)",
        "N/mm", default=None, gt=0, example=2.0e4)
    seat_stiffness: float = quantity(
        "Valve seat stiffness (unilateral: the valve rests on it with the spring preload)",
        "N/mm", gt=0, example=2.0e5)
    damping_ratio: float = quantity(
        "Damping ratio of the contact and of every element between masses (c: 2 zeta "
        "sqrt(k m))", "-", default=0.05, ge=0, lt=1)
    seat_damping_ratio: float | None = quantity(
        "Damping ratio of the valve seat; omit for damping_ratio", "-", default=None, ge=0,
        lt=1)
    spring_damping_ratio: float = quantity(
        "Damping ratio of the valve spring (single rate: on the valve node; chain: modal, "
        "first surge mode)", "-", default=0.02, ge=0, lt=1)
    contact_damping: float | None = quantity(
        "Viscous damping of the cam contact as a value (with the train in series when "
        "there is no follower mass); replaces damping_ratio there", "N·s/m", default=None, ge=0)
    link_damping: float | None = quantity(
        "Viscous damping of the follower-valve link (push rod, rocker, stem in series) as a "
        "value; replaces damping_ratio there", "N·s/m", default=None, ge=0)
    seat_damping: float | None = quantity(
        "Viscous damping of the valve seat as a value; replaces seat_damping_ratio", "N·s/m",
        default=None, ge=0)
    spring_damping: float | None = quantity(
        "Viscous damping of the valve spring as a value (chain: end to end, each element N "
        "times it); replaces spring_damping_ratio", "N·s/m", default=None, ge=0)
    spring_elements: int = quantity(
        "Elements of the valve-spring chain (spring surge); 0: a single rate with a third of "
        "the spring mass in masses.valve_side", "-", default=0, ge=0, le=256)
    spring_mass: float | None = quantity(
        "Mass of the valve spring (needed with spring_elements > 0; then masses.valve_side "
        "still holds a third of it, which the chain replaces)", "kg", default=None, gt=0,
        example=0.035)
    speed_oscillation: float = quantity(
        "Amplitude of an oscillation of the camshaft speed (Williams 2013 App A6); 0: "
        "constant speed", "rpm", default=0.0, ge=0)
    speed_oscillation_order: int = quantity(
        "Order of the speed oscillation (cycles per camshaft revolution)", "-", default=2,
        ge=1, le=64)
    integrator: Literal["newmark", "central_difference", "lsoda", "radau"] = option(
        "Time integrator: newmark (average acceleration, default), central_difference "
        "(Teodorescu's explicit scheme), lsoda or radau (scipy, adaptive reference)",
        default="newmark")
    steps_per_degree: float | None = quantity(
        "Time steps per degree of cam (fixed-step integrators); omit for automatic: the "
        "shortest natural period / steps_per_period", "-", default=None, gt=0, le=1e5)
    steps_per_period: float = quantity(
        "Steps per shortest natural period of the train when steps_per_degree is omitted", "-",
        default=20.0, ge=4, le=1000)
    cycles_max: int = quantity("Most camshaft revolutions marched to reach the periodic state",
                               "-", default=20, ge=2, le=1000)
    period_tol: float = quantity(
        "Periodic state: largest change of any displacement between two revolutions, "
        "relative to the largest displacement", "-", default=1e-6, gt=0, lt=0.1)
    rtol: float = quantity("Relative tolerance of the adaptive integrators", "-",
                           default=1e-8, gt=0, lt=0.01)
    atol: float = quantity("Absolute displacement tolerance of the adaptive integrators", "µm",
                           default=1e-5, gt=0)
    max_step: float = quantity("Largest step of the adaptive integrators", "deg", default=0.25,
                               gt=0, le=5)
    stability_factor: float = quantity(
        "Central difference: the step may be at most this fraction of 2/omega_max", "-",
        default=0.8, gt=0, le=1)
    roller: Literal["marched", "after"] = option(
        "A deck with [roller]: marched (the roller's speed on its pin is a state of the "
        "elastic train's march, driven by the marched contact force: backward Euler in the "
        "Newmark step; newmark integrator only; the roller effect then takes that speed as "
        "the run's roller speed) or after (only the roller effect solves it, from the "
        "train's load after the march)", default="marched")
    roller_load_levels: int = quantity(
        "Load levels of the marched roller's traction and pin-torque tables, from 0 to "
        "3 x the rigid train's largest load, uniform and linear in the square root of the load",
        "-", default=17, ge=3, le=201, example=17)
    roller_table_points: int = quantity(
        "Sliding speeds (and roller speeds) of the marched roller's traction and pin-torque "
        "tables, clustered at zero sliding", "-", default=101, ge=21, le=100001, example=101)
    lash_adjuster: LashAdjusterSection | None = section(
        "Hydraulic lash adjuster marched with the train (plunger, chamber, leak-down, check "
        "valve); without it a lash adjuster is clearance.adjuster_load, a constant force")

    def problems(self, path: str) -> list[Problem]:
        out = []
        if self.spring_elements == 1:
            out.append(Problem(f"{path}.spring_elements", "a chain needs at least 2 elements",
                               1, "0 (single rate) or 2 or more"))
        if self.contact_model == "linear" and self.contact_stiffness is None:
            out.append(Problem(f"{path}.contact_stiffness", "is required with contact_model = "
                               "linear", None, "the contact stiffness in N/mm, or contact_model "
                               "= \"hertz_line\""))
        if self.contact_model == "hertz_line" and self.contact_stiffness is not None:
            out.append(Problem(f"{path}.contact_stiffness", "is not used with contact_model = "
                               "hertz_line (the contact's own stiffness follows from the "
                               "materials and radii)", self.contact_stiffness,
                               "no value, or contact_model = \"linear\""))
        if self.link_damping is not None and self.follower_mass == 0:
            out.append(Problem(f"{path}.link_damping", "needs a follower node (without one the "
                               "link is in series with the contact: use contact_damping)",
                               self.link_damping, "no value, or follower_mass > 0"))
        if self.follower_mass > 0 and all(k is None for k in (
                self.stem_stiffness, self.rocker_stiffness, self.pushrod_stiffness)):
            out.append(Problem(f"{path}.stem_stiffness", "is required with follower_mass > 0 "
                               "(the follower node needs a spring to the valve node)", None,
                               "the stem stiffness in N/mm (or rocker_stiffness, "
                               "pushrod_stiffness), or follower_mass = 0 for one node"))
        if self.spring_elements > 0 and self.spring_mass is None:
            out.append(Problem(f"{path}.spring_mass", "is required with spring_elements > 0",
                               None, "the spring's mass in kg"))
        return out


def dynamics_problems(deck) -> list[Problem]:
    """Checks of [dynamics] against the rest of a valve-train deck (masses, spring, mechanism)."""
    d = deck.dynamics
    if d is None:
        return []
    out = []
    if deck.spring is None or deck.masses is None:
        out.append(Problem("dynamics", "needs the rigid train's data", None,
                           "[spring] and [masses] sections"))
        return out
    if deck.mechanism.type == "desmodromic":
        out.append(Problem("dynamics", "does not model a desmodromic train yet", None,
                           "no [dynamics] section for mechanism.type = desmodromic"))
    if deck.spring.progressive_quadratic or deck.spring.progressive_cubic:
        out.append(Problem("spring.progressive_quadratic", "a progressive spring is not "
                           "modelled by [dynamics] yet", None, "a linear spring (0)"))
    third = d.spring_mass / 3.0 if d.spring_elements > 0 else 0.0
    left = deck.masses.valve_side - d.follower_mass - third
    if left <= 0.0:
        out.append(Problem("dynamics.follower_mass", "leaves no mass at the valve",
                           f"{d.follower_mass:g} kg", f"less than masses.valve_side minus a "
                           f"third of the spring mass ({deck.masses.valve_side - third:g} kg)"))
    c = deck.clearance
    if c is not None and c.lash_adjuster and c.adjuster_load > 0 and d.follower_mass == 0:
        out.append(Problem("dynamics.follower_mass", "a lash adjuster's load needs a follower "
                           "node", 0.0, "the follower's mass in kg (> 0)"))
    shaft = getattr(getattr(deck, "camshaft", None), "flexibility", None)
    if (d.contact_model == "hertz_line" and shaft is not None
            and getattr(shaft, "coupling", "one_way") == "two_way"):
        out.append(Problem("dynamics.contact_model", "hertz_line is not modelled by the two-way "
                           "coupled camshaft yet", "hertz_line", "linear"))
    if (shaft is not None and getattr(shaft, "coupling", "one_way") == "two_way"
            and getattr(deck, "lubricant", None) is None):
        out.append(Problem("lubricant", "is required with camshaft.flexibility.coupling = "
                           "two_way (every lobe's contact friction enters the coupled march)",
                           None, "a [lubricant] section"))
    if (shaft is not None and getattr(shaft, "coupling", "one_way") == "two_way"
            and d.speed_oscillation > 0):
        out.append(Problem("dynamics.speed_oscillation", "with two_way coupling every lobe "
                           "turns with the camshaft's drive: its oscillation is "
                           "camshaft.flexibility.speed_amplitude",
                           f"{d.speed_oscillation * 30.0 / 3.141592653589793:g} rpm",
                           "0 (and speed_amplitude, speed_order in [camshaft.flexibility])"))
    roller = getattr(deck, "roller", None)
    if (roller is not None and roller.pin != "locked" and shaft is not None
            and getattr(shaft, "coupling", "one_way") == "two_way"):
        out.append(Problem("camshaft.flexibility.coupling", "the two-way coupled march takes "
                           "the cam contact's sliding friction: a turning roller's traction is "
                           "not in it", "two_way", "one_way with a [roller] section (or "
                           "roller.pin = \"locked\")"))
    hla = getattr(d, "lash_adjuster", None)
    if (hla is not None and hla.check_valve == "ball" and shaft is not None
            and getattr(shaft, "coupling", "one_way") == "two_way"):
        out.append(Problem("dynamics.lash_adjuster.check_valve", "the two-way coupled march's "
                           "chambers take the quasi-static check valve (the march carries "
                           "each chamber's pressure and flows, not the ball's lift and speed)",
                           "ball", "quasi_static, or camshaft.flexibility.coupling = one_way"))
    if (roller is not None and d.roller == "marched" and roller.pin != "locked"
            and d.integrator != "newmark"):
        out.append(Problem("dynamics.integrator", "the roller's speed is marched by the newmark "
                           "integrator only", d.integrator,
                           "newmark, or dynamics.roller = \"after\""))
    if d.pushrod_stiffness is not None and deck.mechanism.type != "pushrod":
        out.append(Problem("dynamics.pushrod_stiffness", "applies to a push-rod train only",
                           None, "no value"))
    return out + lash_adjuster_problems(deck)
