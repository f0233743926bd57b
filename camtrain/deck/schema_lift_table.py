"""A lift given as data points: ``[lift.table]``.

Part of the deck schema: a deferred section of ``Lift`` (schema_lift.py), imported when a
deck has it.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import ExactlyOne, Together, option, quantity
from camtrain.errors import Problem


@dataclass(frozen=True, kw_only=True)
class Table:
    """Lift given as discrete data points (angle from maximum lift, lift)."""

    angle_unit: Literal["deg", "rad"] = option("Unit of the inline angles: deg or rad",
                                               default="deg")
    angles: tuple[float, ...] | None = quantity(
        "Cam angles from the maximum-lift position, increasing (in angle_unit)", "-",
        default=None, min_items=8)
    lifts: tuple[float, ...] | None = quantity("Lift at each angle", "mm", default=None,
                                               min_items=8)
    file: str | None = option(
        "CSV file with a header 'angle_deg,lift_mm' (or angle_rad / lift_m) instead of "
        "angles and lifts; a path relative to the deck", default=None)
    dataset: Literal["pinto_inlet_cam", "pinto_inlet_valve", "zeta_intake",
                     "zeta_exhaust"] | None = option(
        "A lift table shipped with camtrain instead: pinto_inlet_cam (Ball 1988 App E), "
        "pinto_inlet_valve (App E converted to valve lift through the datum geometry), "
        "zeta_intake, zeta_exhaust (Yang 1992 App C)", default=None)
    symmetric: bool = option("Mirror the data about the maximum-lift position", default=False)
    derivative: Literal["smoothing_spline", "central_difference"] = option(
        "How derivatives are taken: smoothing_spline (robust to 4-decimal data) or "
        "central_difference (as Ball 1988, sensitive to data error)",
        default="smoothing_spline")
    smoothing: float | None = quantity(
        "Smoothing level of the spline relative to the data precision; omit for the automatic "
        "choice (1)", "-", default=None, ge=0)
    noise: float | None = quantity(
        "Measurement noise (standard deviation) of the lifts; omit for printed step / sqrt(12)", "mm",
        default=None, gt=0)

    schema_rules = (ExactlyOne((("angles", "lifts"), ("file",), ("dataset",))),
                    Together(("angles", "lifts")))

    def problems(self, path: str) -> list[Problem]:
        has_inline = self.angles is not None or self.lifts is not None
        sources = [has_inline, self.file is not None, self.dataset is not None]
        if sum(sources) != 1:
            return [Problem(path, "give exactly one source of data points", None,
                            "angles and lifts, or file, or dataset")]
        if has_inline and (self.angles is None or self.lifts is None):
            return [Problem(path, "angles and lifts must be given together")]
        if has_inline and len(self.angles) != len(self.lifts):
            return [Problem(f"{path}.lifts", f"has {len(self.lifts)} values but angles has "
                            f"{len(self.angles)}", None, "one lift per angle")]
        return []
