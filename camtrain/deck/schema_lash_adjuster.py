"""Deck section [dynamics.lash_adjuster]: a hydraulic lash adjuster in the elastic valve train
(docs/lash_adjusters.md). With it the adjuster is no longer a constant load: its plunger, its
high-pressure chamber (oil with free air), its leak-down annulus and its check valve are marched
with the train (camtrain.dynamics.hla). Every value no source gives must be flagged as assumed
where the deck sets it.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import option, quantity
from camtrain.errors import Problem


@dataclass(frozen=True, kw_only=True)
class LashAdjusterSection:
    """Hydraulic lash adjuster: plunger, chamber, leak-down annulus, check valve (typical
    values: plunger 8-13 mm, diametral clearance 5-20 µm, leak length 5-10 mm, chamber
    100-1000 mm³, oil modulus 1.4-1.8 GPa without air)."""

    location: Literal["auto", "follower", "pivot"] = option(
        "Where the adjuster sits: follower (in a bucket tappet or a push-rod lifter, between "
        "the follower and the stem or push rod), pivot (under the pivot of an end-pivoted finger "
        "follower, referred to the valve by the lever ratio), auto (pivot for a finger, follower "
        "otherwise)", default="auto")
    plunger_diameter: float = quantity("Plunger diameter", "mm", gt=0, example=11.0)
    radial_clearance: float = quantity("Radial clearance of the plunger in its body (half the "
                                       "diametral clearance)", "µm", ge=0, example=4.0)
    leak_length: float = quantity("Length of the leak-down annulus (plunger-body overlap)",
                                  "mm", gt=0, example=6.0)
    eccentricity: float = quantity(
        "Relative eccentricity of the plunger in its body (leak factor 1 + 1.5 e²)", "-",
        default=0.0, ge=0, le=1)
    viscosity: float | None = quantity(
        "Oil viscosity in the annulus; omit for lubricant.viscosity", "Pa·s", default=None, gt=0)
    chamber_volume: float = quantity("High-pressure chamber volume at full collapse", "mm³",
                                     gt=0, example=150.0)
    stroke: float = quantity("Plunger travel from full collapse to full extension", "mm", gt=0,
                             example=2.5)
    rest_extension: float = quantity(
        "Plunger extension from full collapse on the base circle", "mm", gt=0, example=0.6)
    plunger_mass: float = quantity("Plunger mass (its own frame)", "kg", gt=0, example=0.008)
    spring_rate: float = quantity("Plunger spring rate", "N/mm", default=3.0, ge=0)
    spring_preload: float = quantity("Plunger spring force at the rest extension", "N",
                                     default=10.0, ge=0)
    supply_pressure: float = quantity("Gallery (supply) pressure feeding the check valve, "
                                      "gauge; also the reservoir's", "bar", gt=0, example=2.5)
    check_valve: Literal["quasi_static", "ball"] = option(
        "Check valve model: quasi_static (sharp-edged orifice opening linearly above its "
        "cracking pressure, default) or ball (the ball's own dynamics: mass, spring, seat, lift "
        "stop; the cracking pressure follows from its preload)", default="quasi_static")
    cracking_pressure: float = quantity("Check valve cracking pressure (supply above chamber; "
                                        "quasi_static)", "kPa", default=2.0, ge=0)
    check_valve_area: float = quantity("Check valve flow area, fully open (quasi_static)",
                                       "mm²", default=1.5, gt=0)
    full_open_pressure: float = quantity(
        "Pressure drop above cracking at which the check valve is fully open (quasi_static)",
        "kPa", default=20.0, gt=0)
    discharge_coefficient: float = quantity("Check valve discharge coefficient", "-",
                                            default=0.6, gt=0, le=1)
    ball_mass: float = quantity("Check ball mass (ball; a 2.5 mm steel ball: 0.064 g)", "g",
                                default=0.064, gt=0)
    ball_spring_rate: float = quantity("Check ball spring rate (ball)", "N/mm", default=0.1,
                                       gt=0)
    ball_preload: float = quantity("Check ball spring force on its seat (ball; cracking "
                                   "pressure = preload / seat area)", "N", default=0.0063, ge=0)
    seat_diameter: float = quantity("Check valve seat bore (ball: pressure area and curtain "
                                    "pi d lift)", "mm", default=2.0, gt=0)
    ball_lift: float = quantity("Check ball lift at its stop (ball)", "mm", default=0.3, gt=0)
    ball_damping_ratio: float = quantity(
        "Viscous damping ratio of the check ball on its spring (ball; 0: its losses are the "
        "inelastic seat and stop and the flow)", "-", default=0.0, ge=0)
    oil_density: float = quantity("Oil density", "kg/m³", default=850.0, gt=0)
    bulk_model: Literal["free_air_polytropic"] = option(
        "Effective bulk modulus of oil with free air: free_air_polytropic (liquid of constant "
        "modulus with polytropic free air; Merritt 1967)", default="free_air_polytropic")
    bulk_modulus: float = quantity("Bulk modulus of the oil without air", "GPa", default=1.6,
                                   gt=0)
    air_fraction: float = quantity("Free air in the chamber's oil, by volume at atmospheric "
                                   "pressure", "%", default=0.5, ge=0, lt=100)
    polytropic_index: float = quantity("Polytropic index of the air (1 isothermal, 1.4 "
                                       "adiabatic)", "-", default=1.0, ge=1, le=1.4)
    stop_stiffness: float = quantity("Stiffness of the stops at full collapse and full "
                                     "extension", "N/mm", default=2.0e5, gt=0)
    vapour_pressure: float = quantity("Lowest absolute chamber pressure (cavitation)", "kPa",
                                      default=2.0, gt=0)
    checking_height: float = quantity(
        "Valve lift at which the opening and closing are timed (against the constant-load "
        "adjuster's)", "mm", default=1.0, gt=0)
    chamber_scheme: Literal["backward_euler", "trapezoidal"] = option(
        "Time discretisation of the chamber's pressure: backward_euler (L-stable, first "
        "order, default: the chamber is stiff with the check valve open) or trapezoidal "
        "(second order, undamped stiff mode)", default="backward_euler")

    def problems(self, path: str) -> list[Problem]:
        out = []
        if self.rest_extension >= self.stroke:
            out.append(Problem(f"{path}.rest_extension", "must be less than the stroke",
                               f"{self.rest_extension * 1e3:g} mm",
                               f"below stroke = {self.stroke * 1e3:g} mm"))
        return out


def lash_adjuster_problems(deck) -> list[Problem]:
    """Checks of [dynamics.lash_adjuster] against the rest of a valve-train deck."""
    d = deck.dynamics
    h = None if d is None else d.lash_adjuster
    if h is None:
        return []
    path = "dynamics.lash_adjuster"
    out = []
    c = deck.clearance
    if c is None or not c.lash_adjuster:
        out.append(Problem("clearance.lash_adjuster", f"must be true with [{path}]", None,
                           "true"))
    if d.follower_mass == 0:
        out.append(Problem("dynamics.follower_mass", f"[{path}] needs a follower node (its "
                           "body)", 0.0, "the follower's mass in kg (> 0)"))
    if d.integrator != "newmark":
        out.append(Problem("dynamics.integrator", f"[{path}] is marched by the newmark "
                           "integrator only", d.integrator, "newmark"))
    if d.contact_model != "linear":
        out.append(Problem("dynamics.contact_model", f"[{path}] needs the linear cam contact",
                           d.contact_model, "linear"))
    if h.viscosity is None and getattr(deck, "lubricant", None) is None:
        out.append(Problem(f"{path}.viscosity", "is required without a [lubricant] section",
                           None, "the oil viscosity in Pa·s"))
    if h.location == "pivot" and deck.mechanism.type != "finger":
        out.append(Problem(f"{path}.location", "pivot applies to an end-pivoted finger "
                           "follower", "pivot", "follower or auto"))
    return out
