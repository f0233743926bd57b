"""The exponential-polynomial lift fit: ``[lift.exp_poly]``.

Part of the deck schema: a deferred section of ``Lift`` (schema_lift.py), imported when a
deck has it.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import option, quantity


@dataclass(frozen=True, kw_only=True)
class ExpPoly:
    """Exponential-polynomial fit (Lim et al. 1983): l = exp(a0 + a1 phi + ...), phi in rad, l in mm."""

    coefficients: tuple[float, ...] = quantity("Coefficients a0, a1, ... (phi in rad, lift in mm)",
                                               "-", min_items=3, max_items=20)
    cutoff: float = quantity("Lift below which the valve is taken as closed (base circle)", "mm",
                             default=1e-4, gt=0)
    blend: Literal["shift", "hard"] = option(
        "Cut-off treatment: shift (lift continuous, nose exact) or hard (raw fit above the "
        "cut-off, a small step at it)", default="shift")
