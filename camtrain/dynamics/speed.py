"""The highest camshaft speed without separation, by a bracketed search over the periodic
response (the elastic counterpart of the rigid train's closed-form bounce speed, Williams 2013
eq. 1.36 / Ball 1988 §4.2.3.2).

A speed "separates" when the cam loses the follower during the lift event. The search first
brackets the threshold (growing or shrinking the speed by ``factor`` from a start) and then
bisects until the bracket is narrower than ``rtol`` of its upper end. It assumes one threshold
(separation at every speed above it), which holds near the first separation; the evaluated
speeds are returned so a reader can see the bracket.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

__all__ = ["NoThreshold", "SpeedSearch", "first_separation_speed"]


class NoThreshold(ValueError):
    """No bracket found: ``crossed_everywhere`` when every speed tried crossed the threshold
    (separated), otherwise none did. The message words it for separation; a caller searching
    another threshold words it from the flag."""

    def __init__(self, crossed_everywhere: bool):
        self.crossed_everywhere = crossed_everywhere
        super().__init__("no separation threshold found: "
                         + ("the train separates at every speed tried" if crossed_everywhere
                            else "the train never separates at the speeds tried"))


@dataclass(frozen=True)
class SpeedSearch:
    """``omega`` [rad/s]: the bracket's lower end (the highest speed found without separation);
    ``upper`` the lowest with; ``angle`` [rad] of the first loss at ``upper``; ``evaluations``
    (speed, separated) in the order run."""

    omega: float
    upper: float
    angle: float | None
    evaluations: tuple[tuple[float, bool], ...]


def first_separation_speed(separates: Callable[[float], tuple[bool, float | None]],
                           start: float, *, rtol: float = 2e-3, factor: float = 1.25,
                           max_evaluations: int = 60) -> SpeedSearch:
    """Bracket and bisect the speed where ``separates(omega) -> (separated, angle)`` turns
    True. Raises :class:`NoThreshold` (a ValueError) when no bracket is found within
    ``max_evaluations``."""
    evals: list[tuple[float, bool]] = []

    def check(w):
        sep, angle = separates(w)
        evals.append((w, sep))
        return sep, angle

    sep, angle = check(start)
    lo, hi, hi_angle = (None, start, angle) if sep else (start, None, None)
    w = start
    while (lo is None or hi is None) and len(evals) < max_evaluations:
        w = w / factor if lo is None else w * factor
        sep, angle = check(w)
        if sep:
            hi, hi_angle = w, angle
        else:
            lo = w
        if w < 1e-6 * start or w > 1e6 * start:
            break
    if lo is None or hi is None:
        raise NoThreshold(crossed_everywhere=lo is None)
    while (hi - lo) > rtol * hi and len(evals) < max_evaluations:
        mid = math.sqrt(lo * hi)
        sep, angle = check(mid)
        if sep:
            hi, hi_angle = mid, angle
        else:
            lo = mid
    return SpeedSearch(lo, hi, hi_angle, tuple(evals))
