"""The closing cam and follower of a desmodromic train: ``[mechanism.closing]``.

Part of the deck schema: a deferred section of ``Mechanism`` (schema.py), imported when a deck
has it.
"""
from __future__ import annotations

from dataclasses import dataclass

from camtrain.deck.fields import quantity


@dataclass(frozen=True, kw_only=True)
class ClosingPair:
    """The closing cam of a desmodromic train and its end-pivoted follower (Ball 1988 App F)."""

    A: float = quantity("A: pivot to the centre of curvature of the follower face", "mm",
                        gt=0, example=17.32)
    B: float = quantity("B: pivot to the valve-contact pad", "mm", gt=0, example=32.39)
    D: float = quantity("D: cam centre to pivot", "mm", gt=0, example=39.32)
    kappa: float = quantity("kappa: angle between OU and the direction of valve motion", "deg",
                            gt=-360, lt=360, example=-7.31)
    lambda_: float = quantity("lambda: angle VUQ", "deg", gt=-360, lt=360, example=9.41,
                              key="lambda")
    follower_radius: float = quantity("Follower face radius r_f", "mm", gt=0, example=20.0)
    base_radius: float = quantity("Base-circle radius of the closing cam", "mm", gt=0,
                                  example=25.0)
    width: float | None = quantity("Closing cam width", "mm", default=None, gt=0)
