"""Deck section [design]: the valve events and limits `camtrain design` builds a lift law from.

Part of the valve-train deck (schema.py); a run ignores it. Angles are cam degrees from the nose
(the maximum-lift position, docs/lift.md) unless ``angle_basis = "crank"``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import option, quantity
from camtrain.errors import Problem


@dataclass(frozen=True, kw_only=True)
class Design:
    """Valve events and limits for `camtrain design` (docs/design.md)."""

    max_lift: float = quantity("Maximum lift, at the nose", "mm", gt=0, example=9.4)
    angle_basis: Literal["cam", "crank"] = option(
        "Basis of the event angles: cam degrees, or crank degrees (twice the cam angle)",
        default="cam")
    checking_heights: tuple[float, ...] = quantity(
        "Checking heights at which the opening and closing angles are given", "mm", gt=0,
        min_items=1, max_items=4, example=[1.0])
    opening_angles: tuple[float, ...] = quantity(
        "Angle before the nose at which the opening flank passes each checking height", "deg",
        gt=0, lt=180, min_items=1, max_items=4, example=[50.0])
    closing_angles: tuple[float, ...] | None = quantity(
        "Angle after the nose at which the closing flank passes each checking height; omit for "
        "the opening angles (symmetric events)", "deg", default=None, gt=0, lt=180,
        min_items=1, max_items=4)
    ramp_height: float = quantity("Opening ramp height (lift at the end of the ramp)", "mm",
                                  default=0.0, ge=0, example=0.3)
    ramp_velocity: float | None = quantity(
        "Velocity of the opening ramp's constant-velocity part (or give ramp_length)",
        "mm/deg", default=None, gt=0)
    ramp_length: float | None = quantity(
        "Opening ramp duration, from the base circle to the ramp height (or give "
        "ramp_velocity)", "deg", default=None, gt=0, lt=90)
    closing_ramp_height: float | None = quantity("Closing ramp height; omit for the opening "
                                                 "value", "mm", default=None, ge=0)
    closing_ramp_velocity: float | None = quantity(
        "Closing ramp velocity (magnitude); omit for the opening value", "mm/deg",
        default=None, gt=0)
    closing_ramp_length: float | None = quantity("Closing ramp duration; omit for the opening "
                                                 "value", "deg", default=None, gt=0, lt=90)
    max_acceleration: float | None = quantity(
        "Largest positive lift acceleration allowed (per cam degree squared)", "mm/deg²",
        default=None, gt=0)
    max_deceleration: float | None = quantity(
        "Largest negative lift acceleration allowed, as a magnitude", "mm/deg²", default=None,
        gt=0)
    max_jerk: float | None = quantity("Largest jerk magnitude allowed", "mm/deg³",
                                      default=None, gt=0)
    symmetric: bool = option("Design one flank and mirror it (needs equal opening and closing "
                             "events)", default=False)
    spans: int = quantity("Knot spans of the spline over the event (resolution of the design)",
                          "-", default=40, ge=8, le=400)
    lift_tolerance: float = quantity("Tolerance on the lift at each event", "mm",
                                     default=0.001, gt=0)
    angle_tolerance: float = quantity("Tolerance on the angle of each checking-height event",
                                      "deg", default=0.05, gt=0)

    def problems(self, path: str) -> list[Problem]:
        out = []
        n = len(self.checking_heights)
        if len(self.opening_angles) != n:
            out.append(Problem(f"{path}.opening_angles", f"has {len(self.opening_angles)} "
                               f"values for {n} checking heights", None, "one per height"))
        if self.closing_angles is not None and len(self.closing_angles) != n:
            out.append(Problem(f"{path}.closing_angles", f"has {len(self.closing_angles)} "
                               f"values for {n} checking heights", None, "one per height"))
        if any(h >= self.max_lift for h in self.checking_heights):
            out.append(Problem(f"{path}.checking_heights", "must lie below the maximum lift",
                               None, "heights < max_lift"))
        if self.ramp_height > 0.0 and (self.ramp_velocity is None) == (self.ramp_length is None):
            out.append(Problem(f"{path}.ramp_velocity", "give exactly one of ramp_velocity and "
                               "ramp_length for a ramp", None, "one of the two"))
        if self.symmetric and (self.closing_angles not in (None, self.opening_angles) or any(
                getattr(self, f"closing_{f}") is not None
                for f in ("ramp_height", "ramp_velocity", "ramp_length"))):
            out.append(Problem(f"{path}.symmetric", "is true but closing events differ from "
                               "the opening ones", None, "no closing_* fields, or symmetric = "
                               "false"))
        return out
