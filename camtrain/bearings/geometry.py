"""Plain journal bearing geometry and lubricant (SI), checked once at the boundary.

A fully (centrally) grooved bearing is two short lands of ``(length - groove_width)/2`` each.
Each land is a short bearing at the same eccentricity, so the film stiffness scales with
``2 land^3`` and the shear with ``2 land`` (Yang 1992 §2.4: grooved mains and camshaft bearings
use the sum of the two lands; Appendix B "18.30 (7.175)", Appendix C "17.0 (7.5)").
"""
from __future__ import annotations

from dataclasses import dataclass

from camtrain.errors import field_error

__all__ = ["JournalBearing"]


@dataclass(frozen=True)
class JournalBearing:
    """Geometry of one plain bearing.

    Attributes:
        diameter: journal diameter d [m].
        length: overall bearing length b [m] (groove included).
        clearance: radial clearance c [m].
        viscosity: effective dynamic viscosity eta [Pa s].
        groove_width: width of a full circumferential central groove [m]; 0 = ungrooved.
        name: label used in error messages (deck path prefix).
    """

    diameter: float
    length: float
    clearance: float
    viscosity: float
    groove_width: float = 0.0
    name: str = "bearing"

    def __post_init__(self):
        for attr in ("diameter", "length", "clearance", "viscosity"):
            v = getattr(self, attr)
            if not (isinstance(v, (int, float)) and v == v and 0.0 < v < float("inf")):
                raise field_error(f"{self.name}.{attr}", "must be a finite number > 0", v)
        g = self.groove_width
        if not (0.0 <= g < self.length):
            raise field_error(f"{self.name}.groove_width", "out of range", g,
                              f"0 <= groove_width < length ({self.length})")
        if self.clearance >= 0.5 * self.diameter:
            raise field_error(f"{self.name}.clearance", "larger than the journal radius",
                              self.clearance, "c << d/2", "radial clearance, in metres")

    @property
    def radius(self) -> float:
        return 0.5 * self.diameter

    @property
    def grooved(self) -> bool:
        return self.groove_width > 0.0

    @property
    def land(self) -> float:
        """Length of one land [m] (the whole length when ungrooved)."""
        return 0.5 * (self.length - self.groove_width) if self.grooved else self.length

    @property
    def shear_length(self) -> float:
        """Length that shears oil [m]: b, or the sum of the two lands."""
        return self.length - self.groove_width

    @property
    def b3(self) -> float:
        """Sum of land length cubed [m^3]: b^3 or 2 land^3."""
        return 2.0 * self.land ** 3 if self.grooved else self.length ** 3

    @property
    def stiffness(self) -> float:
        """k = eta r sum(b^3) / c^2 [N s]: film force = k K(eps) w (see mobility module)."""
        return self.viscosity * self.radius * self.b3 / self.clearance ** 2

    @property
    def shear_coefficient(self) -> float:
        """eta r^3 b_shear / c [N m s]: Couette power = this * J * (omega_j - omega_b)^2."""
        return self.viscosity * self.radius ** 3 * self.shear_length / self.clearance
