"""Constant-velocity opening and closing ramps (Ball 1988 §2.2.2, template fields of Fig 4.5).

A ramp takes up the valve clearance: the lift rises linearly from the base circle to the ramp
height over the ramp length, so the velocity is constant on the ramp and steps from zero where it
leaves the base circle (an acceleration impulse Ball accepts; Williams 2013 §1.2.1 recommends
smooth ramps, which his laws build in). Heights in m, lengths in rad.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.lift import _checks as chk


@dataclass(frozen=True)
class Ramps:
    """Opening and closing ramp heights [m] and lengths [rad].

    ``None`` for a closing value means "same as the opening ramp"; ``None`` for the opening
    length is only meaningful for laws that can derive it (multipol: height / start velocity).
    """

    opening_height: float = 0.0
    opening_length: float | None = 0.0
    closing_height: float | None = None
    closing_length: float | None = None

    def resolved(self, path: str = "lift", *, allow_auto: bool = False) -> Ramps:
        """Validated copy with the closing ramp filled in from the opening one where omitted."""
        base = f"{path}.ramps"
        oh = chk.scalar(self.opening_height, f"{base}.opening_height", "length", minimum=0.0)
        ch = oh if self.closing_height is None else chk.scalar(
            self.closing_height, f"{base}.closing_height", "length", minimum=0.0)
        lengths = []
        for name, value, fallback in (("opening_length", self.opening_length, None),
                                      ("closing_length", self.closing_length, "opening")):
            if value is None and fallback == "opening":
                value = lengths[0]
            if value is None:
                if not allow_auto:
                    raise chk.fail(f"{base}.{name}", "is required for this lift form", None,
                                   "a length in deg >= 0")
                lengths.append(None)
                continue
            lengths.append(chk.scalar(value, f"{base}.{name}", "angle", minimum=0.0))
        for side, h, ln in (("opening", oh, lengths[0]), ("closing", ch, lengths[1])):
            if ln is not None and ln == 0.0 and h > 0.0:
                raise chk.fail(f"{base}.{side}_length", "is zero but the ramp has a height",
                               0.0, "a length in deg > 0",
                               f"a {chk.shown(h, 'length')} mm ramp of zero length is a step "
                               "in lift; give its length or set the height to 0")
        return Ramps(oh, lengths[0], ch, lengths[1])


def ramp_kinematics(theta: np.ndarray, start: float, length: float,
                    height: float, rising: bool) -> tuple[np.ndarray, np.ndarray]:
    """Lift and velocity on a constant-velocity ramp (Ball 1988 §2.2.2).

    The ramp spans ``[start, start + length]``; it rises from 0 to ``height`` if ``rising``
    (opening) or falls from ``height`` to 0 (closing). Acceleration and jerk on it are zero.
    """
    slope = height / length if length > 0.0 else 0.0
    if rising:
        return slope * (theta - start), np.full_like(theta, slope)
    return slope * (start + length - theta), np.full_like(theta, -slope)
