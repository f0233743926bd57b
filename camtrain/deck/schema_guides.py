"""The follower and valve guides: ``[guides]``.

Part of the deck schema: a deferred section of ``Deck`` (schema.py), imported when a deck has it.
"""
from __future__ import annotations

from dataclasses import dataclass

from camtrain.deck.fields import quantity
from camtrain.errors import Problem


@dataclass(frozen=True, kw_only=True)
class Guides:
    """Follower and valve-stem guides: full-film Couette shear losses (Yang 1992 §3.3.2)."""

    follower_diameter: float | None = quantity(
        "Follower (bucket) diameter in its bore; omit for a follower without a guide", "mm",
        default=None, gt=0, example=28.4, applies="flat, domed")
    follower_guide_length: float | None = quantity("Follower guide (bore) length", "mm",
                                                   default=None, gt=0, example=22.0,
                                                   applies="flat, domed")
    follower_guide_clearance: float | None = quantity(
        "Radial clearance between follower and bore", "mm", default=None, gt=0, example=0.024,
        applies="flat, domed")
    valve_stem_diameter: float = quantity("Valve stem diameter", "mm", gt=0, example=6.043)
    valve_guide_length: float = quantity("Valve guide length", "mm", gt=0, example=36.0)
    valve_guide_clearance: float = quantity("Radial clearance between valve stem and guide",
                                            "mm", gt=0, example=0.02)

    def problems(self, path: str) -> list[Problem]:
        given = [self.follower_diameter, self.follower_guide_length,
                 self.follower_guide_clearance]
        if any(v is None for v in given) and any(v is not None for v in given):
            return [Problem(f"{path}.follower_diameter", "the follower guide needs diameter, "
                            "guide length and clearance together", None, "all three or none")]
        return []
