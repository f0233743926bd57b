"""Deck sections of roller followers and of the arms of pivoted followers (docs/mechanism_roller.md).

* ``[mechanism.roller]``: a follower whose face is a roller (``mechanism.follower = "roller"``;
  its radius is ``mechanism.follower_radius``): crown radius, roller mass.
* ``[mechanism.layout]``: a finger follower or rocker drawn by positions (pivot, roller centre,
  valve-pad centre, valve direction) instead of Dyson's A, B, D, kappa, lambda.
* ``[mechanism.arm]``: the valve pad and the pivot of a finger follower or rocker (pad radius
  and shape, friction coefficients, pivot radius).

Part of the valve-train deck schema (camtrain.deck.schema); no physics imported.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal, NamedTuple

from camtrain.deck.fields import When, option, quantity
from camtrain.errors import Problem

#: |roller centre| may differ from base radius + roller radius by this much [m] (the print
#: precision of a drawing in mm to three decimals)
LAYOUT_TOLERANCE = 1.0e-6


@dataclass(frozen=True, kw_only=True)
class RollerFace:
    """The follower face is a roller (mechanism.follower = "roller"); its radius is
    mechanism.follower_radius. The kinematics are those of the non-rotating roller (the roller
    centre follows the cam's offset curve); the roller's rotation is a contact effect."""

    crown_radius: float | None = quantity(
        "Crown radius of a crowned roller, the transverse radius R_y of an elliptical contact; "
        "omit for a straight roller (line contact)", "mm", default=None, gt=0)
    mass: float = quantity(
        "Roller mass with its share of the pin, carried at the roller centre: a finger's or "
        "rocker's moment of inertia about its pivot gains mass x A^2 (a roller tappet's or "
        "lifter's roller belongs in masses.valve_side); a 17.5 mm roller with its needles: "
        "about 0.012", "kg", default=0.0, ge=0, applies="finger, rocker", example=0.012)


@dataclass(frozen=True, kw_only=True)
class Layout:
    """A finger follower or rocker drawn by positions, valve closed (follower on the base
    circle), cam centre at the origin, any fixed x-y axes in the plane of the cam; replaces
    mechanism.A, B, D, kappa and lambda."""

    pivot: tuple[float, ...] = quantity(
        "Pivot centre U [x, y]: the lash adjuster's ball (finger follower) or the rocker shaft",
        "mm", min_items=2, max_items=2, example=[-32.0, -29.0])
    roller_centre: tuple[float, ...] = quantity(
        "Roller centre (centre of curvature of the face on the cam) Q [x, y]; it must lie at "
        "cam.base_radius + mechanism.follower_radius from the cam centre", "mm",
        min_items=2, max_items=2, example=[0.0, -25.75])
    pad_centre: tuple[float, ...] = quantity(
        "Centre of curvature of the valve pad V [x, y]", "mm", min_items=2, max_items=2,
        example=[20.0, -28.0])
    valve_direction: float = quantity(
        "Direction in which the valve opens, counterclockwise from the +x axis", "deg",
        gt=-360, lt=360, example=-90.0)


@dataclass(frozen=True, kw_only=True)
class ArmContacts:
    """The valve pad and the pivot of a finger follower or rocker: sliding, load, Hertz stress
    and friction at the pad (a second contact, on the flat valve tip), friction torque at the
    pivot (a ball socket or the rocker shaft)."""

    pad_radius: float = quantity(
        "Radius of the valve pad (finger pad or rocker's elephant foot) on the flat valve tip; "
        "its centre is the pad centre (B from the pivot)", "mm", gt=0, example=12.0)
    pad_shape: Literal["cylindrical", "spherical"] = option(
        "cylindrical pad (line contact of pad_width) or spherical (elephant foot: point "
        "contact)", default="cylindrical")
    pad_width: float | None = quantity(
        "Width of a cylindrical pad on the valve tip (line-contact length)", "mm", default=None,
        gt=0, example=5.5, applies="pad_shape = cylindrical")
    pad_friction: float = quantity(
        "Friction coefficient at the valve pad (boundary/mixed sliding on the valve tip)", "-",
        ge=0, lt=1, example=0.1)
    pivot_radius: float = quantity(
        "Pivot friction radius: ball-socket radius of a finger follower, shaft radius of a "
        "rocker", "mm", gt=0, example=4.0)
    pivot_friction: float = quantity(
        "Friction coefficient of the pivot: torque = coefficient x pivot reaction x radius "
        "(coefficient pivot model)", "-", ge=0, lt=1, example=0.1)
    pivot_model: Literal["coefficient", "journal"] = option(
        "Pivot friction: coefficient (Coulomb: coefficient x reaction x radius) or journal (a "
        "rocker shaft as a plain journal bearing of diameter 2 pivot_radius: hydrodynamic "
        "Couette torque at the arm's speed under the pivot reaction)", default="coefficient")
    pivot_length: float | None = quantity(
        "Length of the rocker shaft's bearing (journal pivot model)", "mm", default=None,
        gt=0, applies="pivot_model = journal")
    pivot_clearance: float | None = quantity(
        "Radial clearance of the rocker shaft's bearing (journal pivot model)", "µm",
        default=None, gt=0, applies="pivot_model = journal")
    pivot_viscosity: float | None = quantity(
        "Oil viscosity in the rocker shaft's bearing; omit for lubricant.viscosity", "Pa·s",
        default=None, gt=0, applies="pivot_model = journal")
    pivot_film: Literal["short", "finite"] = option(
        "Film model of the rocker shaft's bearing: short (Ocvirk) or finite (the finite-length "
        "Reynolds film's steady curve)", default="short", applies="pivot_model = journal")

    schema_rules = (When("pad_shape", ("cylindrical",), require=("pad_width",)),
                    When("pad_shape", ("spherical",), forbid=("pad_width",)),
                    When("pivot_model", ("journal",),
                         require=("pivot_length", "pivot_clearance")))

    def problems(self, path: str) -> list[Problem]:
        if self.pivot_model == "journal":
            for name, what in (("pivot_length", "the shaft bearing's length in mm"),
                               ("pivot_clearance", "its radial clearance in µm")):
                if getattr(self, name) is None:
                    return [Problem(f"{path}.{name}", "is required with pivot_model = journal",
                                    None, what)]
            if self.pivot_clearance >= self.pivot_radius:
                return [Problem(f"{path}.pivot_clearance", "is larger than the shaft radius",
                                f"{self.pivot_clearance * 1e6:g} µm", "a few µm to tens of µm")]
        if self.pad_shape == "cylindrical" and self.pad_width is None:
            return [Problem(f"{path}.pad_width", "is required for a cylindrical pad", None,
                            "the pad width in mm", "or set pad_shape = \"spherical\"")]
        if self.pad_shape == "spherical" and self.pad_width is not None:
            return [Problem(f"{path}.pad_width", "applies to a cylindrical pad only",
                            f"{self.pad_width * 1e3:g} mm", "no value")]
        return []


class Dyson(NamedTuple):
    """Dyson's pivot geometry (Ball 1988 App A) in SI units and radians."""

    A: float
    B: float
    D: float
    kappa: float
    lam: float
    branch: int | None = None   # sign of gamma_B + lambda (None: Ball's choice)


def _wrapped(angle: float) -> float:
    return math.pi - (math.pi - angle) % (2.0 * math.pi)


def dyson_from_layout(layout: Layout) -> Dyson:
    """A, B, D, kappa, lambda from the drawn positions: axes turned so that the pivot lies on
    +x (Dyson's frame), then Q = U + A e(pi + lambda + gamma_B), V = U + B e(pi + gamma_B) and
    the valve opening along (cos kappa, -sin kappa) (camtrain.mechanisms.pivot_geometry)."""
    ux, uy = layout.pivot
    turn = math.atan2(uy, ux)
    qx, qy = layout.roller_centre
    vx, vy = layout.pad_centre
    to_q = math.atan2(qy - uy, qx - ux)
    to_v = math.atan2(vy - uy, vx - ux)
    base_angle = _wrapped(to_q - turn - math.pi)       # gamma_B + lambda, drawn
    return Dyson(A=math.hypot(qx - ux, qy - uy), B=math.hypot(vx - ux, vy - uy),
                 D=math.hypot(ux, uy), kappa=_wrapped(turn - layout.valve_direction),
                 lam=_wrapped(to_q - to_v), branch=1 if base_angle >= 0.0 else -1)


def layout_problems(layout: Layout, path: str, base_radius: float,
                    roller_radius: float | None) -> list[Problem]:
    """The drawn positions must be distinct and the roller must touch the base circle."""
    points = {"pivot": layout.pivot, "roller_centre": layout.roller_centre,
              "pad_centre": layout.pad_centre}
    if math.hypot(*layout.pivot) == 0.0:
        return [Problem(f"{path}.pivot", "is at the cam centre", [0.0, 0.0],
                        "a pivot away from the cam centre")]
    for name in ("roller_centre", "pad_centre"):
        p = points[name]
        if math.hypot(p[0] - layout.pivot[0], p[1] - layout.pivot[1]) == 0.0:
            return [Problem(f"{path}.{name}", "coincides with the pivot",
                            [v * 1e3 for v in p], "a point away from the pivot")]
    if roller_radius is None:
        return []
    reach = math.hypot(*layout.roller_centre)
    expected = base_radius + roller_radius
    if abs(reach - expected) > LAYOUT_TOLERANCE:
        return [Problem(f"{path}.roller_centre",
                        f"is {reach * 1e3:.4f} mm from the cam centre: the roller (radius "
                        f"{roller_radius * 1e3:g} mm) must touch the base circle (radius "
                        f"{base_radius * 1e3:g} mm) with the valve closed",
                        [round(v * 1e3, 6) for v in layout.roller_centre],
                        f"{expected * 1e3:.4f} mm from the cam centre (within 0.001 mm)")]
    return []
