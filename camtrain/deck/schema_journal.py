"""The geometry fields of a plain journal bearing, declared once for every deck kind that has
journal bearings: the stand-alone bearing deck (``[bearing]``), the camshaft bearings
(``[[camshaft.bearings]]``) and the engine's big-ends and mains (``[bearings.big_end]``,
``[bearings.main]``). Each section takes these fields (with an example of its own, so its
template stays a realistic deck) and the checks they share.

The fields stay flat in each section (a deck writes ``diameter = 25.0`` in its bearing, not in
a sub-table), so a section calls the field functions rather than nesting a geometry table.
"""
from __future__ import annotations

from camtrain.deck.fields import quantity
from camtrain.errors import Problem
from camtrain.units import mm_text


def diameter_field(example: float):
    return quantity("Journal diameter d", "mm", gt=0, example=example)


def length_field(example: float):
    return quantity("Overall bearing length b, groove included", "mm", gt=0, example=example)


def clearance_field(example: float):
    return quantity("Radial clearance c", "mm", gt=0, example=example)


def groove_width_field():
    """The central groove of a bearing that is either ungrooved or fully grooved (the engine's
    bearings, with their ``grooving`` option, describe their groove width themselves)."""
    return quantity("Width of a full circumferential central groove; 0 = ungrooved", "mm",
                    default=0.0, ge=0)


def bearing_geometry_problems(bearing, path: str) -> list[Problem]:
    """Checks shared by every journal-bearing section: the groove must be shorter than the
    bearing, the clearance far below the journal radius."""
    out = []
    if bearing.groove_width >= bearing.length:
        out.append(Problem(f"{path}.groove_width", "is not shorter than the bearing",
                           mm_text(bearing.groove_width), f"< length ({mm_text(bearing.length)})"))
    if bearing.clearance >= 0.5 * bearing.diameter:
        out.append(Problem(f"{path}.clearance", "is larger than the journal radius",
                           mm_text(bearing.clearance), "a radial clearance << d/2"))
    return out
