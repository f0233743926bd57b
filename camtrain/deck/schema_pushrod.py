"""The push rod and rocker of a push-rod train: ``[mechanism.pushrod]``.

Part of the deck schema: a deferred section of ``Mechanism`` (schema.py), imported when a deck
has it.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import When, option, quantity
from camtrain.errors import Problem


@dataclass(frozen=True, kw_only=True)
class Pushrod:
    """Rocker and push rod between the valve and the follower on the cam (Williams 2013 ch 11)."""

    layout: Literal["simple", "four_bar"] = option(
        "simple: push rod on a translating tappet; four_bar: push rod on a pivoted finger "
        "follower (mechanism.A, D, follower_radius describe that follower)", default="simple")
    rocker_pushrod_arm: float = quantity("Rocker arm on the push-rod side, D1", "mm", gt=0,
                                         example=35.0)
    rocker_valve_arm: float = quantity("Rocker arm on the valve side, D2", "mm", gt=0,
                                       example=50.0)
    rocker_arm_angle: float = quantity("Angle between the two rocker arms, alpha_0", "deg",
                                       default=0.0, gt=-90, lt=90, example=10.0)
    valve_axis_angle: float = quantity("Angle between the vertical and the valve axis, gamma",
                                       "deg", default=0.0, gt=-60, lt=60, example=15.0)
    perpendicular_lift_fraction: float = quantity(
        "Fraction of the maximum valve lift at which the valve arm is perpendicular to the "
        "valve axis", "-", default=0.5, ge=0, le=1)
    pushrod_length: float = quantity("Push-rod length D_PR", "mm", gt=0, example=200.0)
    pushrod_cg_fraction: float = quantity(
        "Distance of the push rod's centre of mass from its lower end, as a fraction of its "
        "length", "-", default=0.5, ge=0, le=1)
    tappet_axis_distance: float | None = quantity(
        "Horizontal distance from the rocker pivot to the tappet axis, x_bar", "mm",
        default=None, gt=0, example=43.3, applies="layout = simple")
    rocker_pivot_x: float | None = quantity(
        "Rocker pivot position relative to the follower pivot, horizontal (a)", "mm",
        default=None, applies="layout = four_bar")
    rocker_pivot_y: float | None = quantity(
        "Rocker pivot position relative to the follower pivot, vertical (b)", "mm",
        default=None, applies="layout = four_bar")
    follower_pushrod_arm: float | None = quantity(
        "Follower pivot to push-rod joint, e", "mm", default=None, gt=0,
        applies="layout = four_bar")
    closure: Literal[-1, 1] = option("Side of the line follower pivot - rocker tip on which "
                                     "the push-rod joint lies", default=-1)
    branch: Literal[-1, 1] = option("Assembly branch of the follower on the cam side",
                                    default=1)

    schema_rules = (
        When("layout", ("simple",), require=("tappet_axis_distance",)),
        When("layout", ("four_bar",),
             require=("rocker_pivot_x", "rocker_pivot_y", "follower_pushrod_arm")))

    def problems(self, path: str) -> list[Problem]:
        if self.layout == "simple" and self.tappet_axis_distance is None:
            return [Problem(f"{path}.tappet_axis_distance", "is required for layout = simple",
                            None, "a distance in mm")]
        if self.layout == "four_bar":
            return [Problem(f"{path}.{n}", "is required for layout = four_bar", None, "mm")
                    for n in ("rocker_pivot_x", "rocker_pivot_y", "follower_pushrod_arm")
                    if getattr(self, n) is None]
        return []
