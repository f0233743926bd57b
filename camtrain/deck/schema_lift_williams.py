"""Williams' acceleration-based lift curves: ``[lift.williams_elementary]``
and ``[lift.williams_low_jerk]``.

Part of the deck schema: a deferred section of ``Lift`` (schema_lift.py), imported when a
deck has it.
"""
from __future__ import annotations

from dataclasses import dataclass

from camtrain.deck.fields import quantity, section


@dataclass(frozen=True, kw_only=True)
class ElementaryHalf:
    """One half of Williams' elementary curve (Williams 2013 ch 2)."""

    durations: tuple[float, ...] = quantity(
        "Section lengths T0..T4: ramp, rise to A, constant A, fall to 0, quarter sine", "deg",
        ge=0, min_items=5, max_items=5)
    ramp_lift: float = quantity("Lift at the end of the ramp", "mm", ge=0)


@dataclass(frozen=True, kw_only=True)
class WilliamsElementary:
    """Williams' elementary acceleration-based lift curve; A and F are solved for."""

    max_lift: float = quantity("Maximum valve lift", "mm", gt=0)
    opening: ElementaryHalf = section("Opening half", required=True)
    closing: ElementaryHalf | None = section("Closing half; omit for a symmetric curve")


@dataclass(frozen=True, kw_only=True)
class LowJerkHalf:
    """One half of Williams' low-jerk curve (Williams 2013 ch 3, Fig 3.2, App 1)."""

    durations: tuple[float, ...] = quantity("Section lengths T0..T12 (T11, the polynomial, > 0)",
                                            "deg", ge=0, min_items=13, max_items=13)
    fractions: tuple[float, ...] = quantity(
        "Fractions eps0..eps6 (eps0 of the ramp acceleration, eps1..eps6 of A)", "-",
        min_items=7, max_items=7)
    lam: float = quantity("lambda: fraction of F at the start of the polynomial", "-")
    p: float = quantity("First index of the polynomial section (> 1)", "-", gt=1)
    q: float = quantity("Second index of the polynomial section (> 1, not p)", "-", gt=1)
    ramp_lift: float = quantity("Lift at the end of the ramp (end of T1)", "mm", ge=0)


@dataclass(frozen=True, kw_only=True)
class WilliamsLowJerk:
    """Williams' low-jerk acceleration-based lift curve; A and F are solved for."""

    max_lift: float = quantity("Maximum valve lift", "mm", gt=0)
    nose_deceleration: float = quantity("Deceleration F0 at the nose", "mm/deg²", gt=0)
    opening: LowJerkHalf = section("Opening half", required=True)
    closing: LowJerkHalf | None = section("Closing half; omit for a symmetric curve")
