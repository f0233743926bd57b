"""The B-spline lift that camtrain design writes: ``[lift.spline]``.

Part of the deck schema: a deferred section of ``Lift`` (schema_lift.py), imported when a
deck has it.
"""
from __future__ import annotations

from dataclasses import dataclass

from camtrain.deck.fields import quantity
from camtrain.errors import Problem


@dataclass(frozen=True, kw_only=True)
class Spline:
    """Lift as a B-spline over the event (the form camtrain design writes; docs/design.md)."""

    degree: int = quantity("Degree of the B-spline (5: quintic lift, cubic acceleration, "
                           "continuous jerk)", "-", default=5, ge=1, le=9)
    knots: tuple[float, ...] = quantity(
        "Full knot vector, cam angles from the nose, non-decreasing, each end repeated "
        "degree + 1 times (coefficients + degree + 1 values)", "deg", min_items=4)
    coefficients: tuple[float, ...] = quantity(
        "B-spline coefficients; the first and last are 0 (the base circle)", "mm", min_items=2)

    def problems(self, path: str) -> list[Problem]:
        if len(self.knots) != len(self.coefficients) + self.degree + 1:
            return [Problem(f"{path}.knots", f"has {len(self.knots)} values for "
                            f"{len(self.coefficients)} coefficients of degree {self.degree}",
                            None, f"{len(self.coefficients) + self.degree + 1} knots")]
        return []
