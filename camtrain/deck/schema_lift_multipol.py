"""Ball's multipol lift: ``[lift.multipol]`` and its segments.

Part of the deck schema: a deferred section of ``Lift`` (schema_lift.py), imported when a
deck has it.
"""
from __future__ import annotations

from dataclasses import dataclass

from camtrain.deck.fields import option, quantity, section
from camtrain.errors import Problem


@dataclass(frozen=True, kw_only=True)
class Segment:
    """One multipol segment: l = l_start + sum_{k=1..5} C_k (theta/theta_T)^k."""

    length: float = quantity("Segment length theta_T", "deg", gt=0, lt=360)
    coefficients: tuple[float, ...] = quantity("Coefficients C1..C5", "mm", min_items=1,
                                               max_items=5)
    start_lift: float | None = quantity(
        "Lift at the start of the segment; omit to continue from the previous segment (the "
        "first starts at the ramp height)", "mm", default=None, ge=0)


@dataclass(frozen=True, kw_only=True)
class Multipol:
    """Ball's multipol: up to 5 polynomial segments from the end of the opening ramp to the nose."""

    segments: tuple[Segment, ...] = section("Segments, from the end of the opening ramp "
                                            "toward the nose", required=True)
    closing_segments: tuple[Segment, ...] | None = section(
        "Segments of the closing half, from the end of the closing ramp toward the nose (only "
        "when the lift is not symmetric)")
    max_order: int = quantity("Maximum order of the polynomials", "-", default=5, ge=1, le=5)
    check_continuity: bool = option(
        "Stop when lift, velocity or acceleration jump at a joint (the jumps are always "
        "reported)", default=True)
    tolerance: float = quantity(
        "Allowed velocity or acceleration step at a joint, as a fraction of its peak (lift steps "
        "are limited to 1 µm)", "-", default=0.005, gt=0, lt=1)

    def problems(self, path: str) -> list[Problem]:
        out = []
        for name in ("segments", "closing_segments"):
            segs = getattr(self, name)
            if segs is not None and not 1 <= len(segs) <= 5:
                out.append(Problem(f"{path}.{name}", f"has {len(segs)} segments", None,
                                   "1 to 5 segments"))
        return out
