"""Deck section ``[camshaft.flexibility]``: the elastic camshaft (Teodorescu et al. 2005 §2.6).

Part of the deck schema. The shaft's stations come from the bearing, lobe and drive positions
already in ``[camshaft]``; this section gives the shaft section, material, bearing and drive
stiffness, damping and the resolution (extra stations per span).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import option, quantity
from camtrain.errors import Problem
from camtrain.units import mm_text


@dataclass(frozen=True, kw_only=True)
class CamshaftFlexibility:
    """The camshaft as an elastic shaft: bending in two planes between its bearings and torsion
    from its drive (Teodorescu et al. 2005 §2.6), periodic response order by order."""

    diameter: float = quantity("Outer diameter of the shaft between the lobes", "mm", gt=0,
                               example=24.0)
    bore: float = quantity("Bore of a hollow shaft; 0 = solid", "mm", default=0.0, ge=0)
    modulus: float = quantity("Young's modulus of the shaft", "GPa", default=210.0, gt=0)
    shear_modulus: float = quantity("Shear modulus of the shaft", "GPa", default=80.0, gt=0)
    density: float = quantity("Density of the shaft material", "kg/m³", default=7850.0, gt=0)
    lobe_mass: float = quantity("Mass of one lobe added at its station (beyond the shaft)",
                                "kg", default=0.0, ge=0)
    lobe_inertia: float = quantity("Polar inertia of one lobe about the shaft axis", "kg·m²",
                                   default=0.0, ge=0)
    bearing_stiffness: float | None = quantity(
        "Radial stiffness of every bearing support; omit for rigid supports", "N/mm",
        default=None, gt=0)
    bearing_damping: float = quantity("Radial damping of every bearing support", "N·s/m",
                                      default=0.0, ge=0)
    damping_ratio: float = quantity(
        "Damping ratio of the first bending and the first torsional mode (stiffness "
        "proportional)", "%", default=2.0, ge=0, lt=100)
    drive_stiffness: float | None = quantity(
        "Torsional stiffness of the drive (belt or chain) between the crankshaft and the drive "
        "station; omit for a drive held rigidly at the mean speed (Teodorescu's gear)", "N·m/rad",
        default=None, gt=0)
    drive_inertia: float = quantity("Polar inertia of the pulley, sprocket or gear", "kg·m²",
                                    default=0.0, ge=0)
    speed_amplitude: float = quantity(
        "Amplitude of the drive speed oscillation (Williams 2013 App A6, eq. A6.5); 0 = "
        "constant speed", "rpm", default=0.0, ge=0)
    speed_order: int = quantity("Order of the drive speed oscillation per camshaft revolution",
                                "-", default=2, ge=1, le=100)
    split: Literal["elastic", "determinate", "equal_share"] = option(
        "How the bearings share the shaft loads: elastic (this shaft), determinate (simply "
        "supported bays, Ball 1988 §6.3: today's camshaft bearings) or equal_share (rigid shaft "
        "on equal bearings, Teodorescu et al. 2005)", default="elastic")
    response: Literal["dynamic", "quasi_static"] = option(
        "dynamic: inertia and damping at every order; quasi_static: a static shaft at every "
        "angle", default="dynamic")
    coupling: Literal["one_way", "two_way"] = option(
        "one_way: the shaft answers the loads of the deck's train; two_way (needs [dynamics]): "
        "every lobe drives its own elastic train, whose cam input the shaft's motion changes, "
        "iterated with the shaft to a common periodic state (converges for a shaft stiff "
        "against the cam contact; docs/camshaft_dynamics.md)", default="one_way")
    coupling_tolerance: float = quantity(
        "Relative change of the lobes' motion (displacement, twist) between two passes of the "
        "shaft/train iteration that counts as converged", "-", default=1e-4, gt=0, lt=0.1)
    coupling_passes: int = quantity("Most passes of the shaft/train iteration", "-", default=30,
                                    ge=1, le=500)
    coupling_solver: Literal["monolithic", "staggered", "waveform"] = option(
        "two_way coupling: monolithic (trains and shaft marched together in time), staggered "
        "(marched in turn within every time step: the shaft under each contact's predicted "
        "load, then the trains with the shaft's motion prescribed) or waveform (whole "
        "revolutions of the trains and the shaft's periodic answer in turn, to a common "
        "periodic state: converges only for a shaft stiff against the cam contact)",
        default="monolithic")
    coupling_predictor: Literal["linear", "constant"] = option(
        "Staggered solver: the contact load the shaft carries in a step's first pass, "
        "extrapolated from the last two steps (linear: a second-order splitting error where "
        "the load is smooth) or the last step's (constant: first order)", default="linear")
    coupling_iterations: int = quantity(
        "Staggered solver: passes of a step at most, each predicting the load the last "
        "produced, until the two agree within 1e-6 of the largest load (strongly coupled: "
        "the monolithic step but where a contact opens or closes). 1: a single pass, loosely "
        "coupled, whose linear predictor goes unstable on a shaft whose modes the step does "
        "not resolve", "-", default=10, ge=1, le=50)
    coupling_method: Literal["quasi_newton", "aitken", "fixed"] = option(
        "Waveform solver: acceleration of the shaft/train iteration: quasi_newton (IQN-ILS, "
        "least-squares inverse Jacobian), aitken (adaptive relaxation) or fixed (constant "
        "relaxation)", default="quasi_newton")
    coupling_preconditioner: Literal["interface_newton", "none"] = option(
        "Waveform solver: interface_newton (each pass's update is a Newton step of the "
        "linear shaft and trains, cam contacts closed: it holds the iteration where the "
        "contact drives a lightly damped shaft mode) or none (the raw residual)",
        default="interface_newton")
    coupling_start: Literal["rigid", "monolithic"] = option(
        "Waveform solver's start: rigid (the shaft's answer to every train's load on a "
        "rigid shaft) or monolithic (the monolithic march's periodic state: the waveform "
        "passes then check and refine it, and coupling_start_gap reports how far they moved)",
        default="rigid")
    relaxation: float = quantity(
        "Relaxation of the lobe loads in the first pass of the shaft/train iteration; later "
        "passes adapt it (Aitken)", "-", default=0.5, gt=0, le=1)
    nodes_per_span: int = quantity(
        "Extra stations between neighbouring bearing, lobe and drive stations (resolution)", "-",
        default=2, ge=0, le=50)

    def problems(self, path: str) -> list[Problem]:
        if self.bore >= self.diameter:
            return [Problem(f"{path}.bore", "is not smaller than the shaft diameter",
                            mm_text(self.bore), f"< diameter ({mm_text(self.diameter)})")]
        if (self.coupling == "two_way" and self.coupling_solver == "waveform"
                and self.speed_amplitude > 0):
            return [Problem(f"{path}.coupling_solver", "the waveform solver runs at constant "
                            "speed: a drive speed oscillation needs a time-marched solver",
                            "waveform", '"monolithic" or "staggered" (or speed_amplitude = 0)')]
        return []
