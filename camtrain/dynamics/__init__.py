"""Valve-train dynamics: the elastic train in time (lumped masses, unilateral cam contact and
valve seat, spring surge chain), its integrators and its periodic state. See docs/dynamics.md."""
from camtrain.dynamics.excitation import CamInput, TimeBase, cam_input
from camtrain.dynamics.integrators import (
    INTEGRATORS,
    DynamicEvent,
    Settings,
    StepTooLarge,
    TrainResponse,
    auto_steps,
    march,
    stability_limit,
)
from camtrain.dynamics.train import (
    CAM,
    SEAT,
    Element,
    TrainModel,
    assemble_train,
    chain_end_mass,
    damping_from_ratio,
    rocker_equivalent_mass,
    series,
    surge_frequency,
    surge_frequency_discrete,
)

__all__ = ["cam_input", "CamInput", "TimeBase", "INTEGRATORS", "DynamicEvent", "Settings", "StepTooLarge",
           "TrainResponse", "auto_steps", "march", "stability_limit", "CAM", "SEAT", "Element",
           "TrainModel", "assemble_train", "chain_end_mass", "damping_from_ratio",
           "rocker_equivalent_mass", "series",
           "surge_frequency", "surge_frequency_discrete"]
