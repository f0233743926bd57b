"""Every event and limit of a design, measured on a lift law: met or not, and by how much.

The measurements read the lift law itself (any law, not only a designed spline), in the units
of the events (mm, cam deg): the crossing angles of each checking height are roots of
l(theta) - h on the flank (brentq between grid points of 0.01 deg), the peak and the limits
come from a 0.01 deg grid refined by the law's exact values.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.design.construct import RAMP_RISE, Events
from camtrain.lift.base import DEG, MM, LiftLaw


@dataclass(frozen=True)
class Item:
    """One event or limit: target (or limit), value found, how far inside (positive: met)."""

    name: str
    kind: str           # "event" or "limit"
    target: float
    value: float
    unit: str
    margin: float       # event: tolerance - |miss|; limit: limit - value
    tolerance: float = 0.0

    @property
    def met(self) -> bool:
        return self.margin >= 0.0

    def row(self) -> list:
        miss = self.value - self.target
        return [self.kind, self.name, f"{self.target:.6g}", f"{self.value:.6g}",
                f"{miss:+.3g}" if self.kind == "event" else f"{self.margin:+.3g}",
                f"{self.tolerance:.3g}" if self.kind == "event" else "",
                self.unit, "met" if self.met else "NOT MET"]


HEADER = ["kind", "item", "target or limit", "designed", "miss (event) or margin (limit)",
          "tolerance", "unit", "status"]


def _crossing(law: LiftLaw, h: float, side: int) -> float:
    """Angle [deg from the nose, > 0] where the flank on ``side`` (-1 opening) passes h [mm]."""
    from scipy.optimize import brentq

    grid = np.arange(0.0, 180.0, 0.01)
    lift = law.evaluate(side * grid * DEG).lift / MM
    below = np.nonzero(lift < h)[0]
    if below.size == 0:
        return float("nan")
    i = int(below[0])
    return float(brentq(lambda a: law.evaluate(np.array([side * a * DEG])).lift[0] / MM - h,
                        grid[i - 1], grid[i], xtol=1e-10))


def measure(ev: Events, law: LiftLaw, lift_tol: float, angle_tol: float) -> list[Item]:
    """Events and limits of ``ev`` measured on ``law`` (tolerances in mm and deg)."""
    theta = np.arange(-180.0, 180.0, 0.01)
    curve = law.evaluate(theta * DEG)
    lift = curve.lift / MM
    d2, d3 = curve.d2 / MM * DEG ** 2, curve.d3 / MM * DEG ** 3
    items = [_event("maximum lift", ev.max_lift, float(lift.max()), "mm", lift_tol),
             _event("angle of maximum lift", 0.0, float(theta[np.argmax(lift)]), "deg",
                    max(angle_tol, 0.01))]
    for side, flank, word in ((-1, ev.opening, "opening"), (1, ev.closing, "closing")):
        for h, a in zip(flank.heights, flank.angles, strict=True):
            items.append(_event(f"{word} angle at {h:g} mm", a, _crossing(law, h, side), "deg",
                                angle_tol))
        v, length = flank.ramp()
        if length > 0.0:
            end = _crossing(law, flank.ramp_height, side)
            constant = flank.ramp_height * (1 - RAMP_RISE) / v
            span = np.linspace(end, end + constant, 21)
            vel = np.abs(law.evaluate(side * span * DEG).d1) / MM * DEG
            start = law.opening_angle if side < 0 else law.closing_angle
            items.append(_event(f"{word} ramp duration to {flank.ramp_height:g} mm", length,
                                abs(start / DEG) - end, "deg", angle_tol))
            items.append(_event(f"{word} ramp velocity (mean of its constant part)", v,
                                float(vel.mean()), "mm/deg", 0.01 * v))
    for name, limit, value, unit in (
            ("largest acceleration", ev.max_acceleration, float(d2.max()), "mm/deg²"),
            ("largest deceleration", ev.max_deceleration, float(-d2.min()), "mm/deg²"),
            ("largest jerk magnitude", ev.max_jerk, float(np.abs(d3).max()), "mm/deg³")):
        if limit is not None:
            items.append(Item(name, "limit", limit, value, unit, limit - value))
    items.append(Item("lift above the maximum", "limit", ev.max_lift, float(lift.max()), "mm",
                      ev.max_lift + lift_tol - float(lift.max())))
    return items


def _event(name: str, target: float, value: float, unit: str, tol: float) -> Item:
    miss = abs(value - target) if np.isfinite(value) else np.inf
    return Item(name, "event", target, value, unit, tol - miss, tol)


def continuity(law: LiftLaw) -> dict[str, float]:
    """Largest jump of lift [mm], velocity [mm/deg], acceleration [mm/deg²] and jerk
    [mm/deg³] over every joint of the law (knots and base-circle ends)."""
    jumps = [j.in_mm_deg() for j in law.joint_jumps()]
    keys = {"lift_mm": "lift", "d1_mm_per_deg": "velocity", "d2_mm_per_deg2": "acceleration",
            "d3_mm_per_deg3": "jerk"}
    return {name: max((abs(j[k]) for j in jumps), default=0.0) for k, name in keys.items()}
