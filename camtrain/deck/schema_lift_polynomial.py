"""The general polynomial (polydyne) lift: ``[lift.polynomial]``.

Part of the deck schema: a deferred section of ``Lift`` (schema_lift.py), imported when a
deck has it.
"""
from __future__ import annotations

from dataclasses import dataclass

from camtrain.deck.fields import quantity
from camtrain.errors import Problem


@dataclass(frozen=True, kw_only=True)
class Polynomial:
    """General polynomial (polydyne): l = max_lift (1 - sum C_n (phi/phi_T)^n) over |phi| <= phi_T."""

    half_period: float = quantity("Half period phi_T", "deg", gt=0, lt=180)
    max_lift: float = quantity("Lift at the nose above the ramp", "mm", gt=0)
    exponents: tuple[float, ...] = quantity("Exponents n (e.g. 2, 8, 14, 20, 26)", "-", gt=0,
                                            le=200, min_items=1, max_items=20)
    coefficients: tuple[float, ...] | None = quantity(
        "Dimensionless coefficients C_n (sum 1); omit for the polydyne (zero lift, velocity "
        "and higher derivatives at the ends)", "-", default=None, min_items=1, max_items=20)

    def problems(self, path: str) -> list[Problem]:
        if self.coefficients is not None and len(self.exponents) != len(self.coefficients):
            return [Problem(f"{path}.coefficients", f"has {len(self.coefficients)} values but "
                            f"exponents has {len(self.exponents)}", None, "one per exponent")]
        return []
