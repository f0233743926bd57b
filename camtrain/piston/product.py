"""The piston assembly's product: gas, ring films and friction of one cylinder over a cycle."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.piston.gas import GasSolution
from camtrain.piston.pack import PackSolution


@dataclass(frozen=True)
class PistonFriction:
    """Piston assembly of one cylinder at one engine speed (SI).

    ``theta`` [rad] crank grid from firing TDC over one cycle (no end point); ``omega``
    [rad/s]; ``liner_speed`` [m/s] (+ towards the crankcase); ``gas`` the inter-ring gas
    solution (its own grid, end point included); ``pack`` every ring's film after each pass;
    ``ring_force`` [N] per compression ring (top first) on the ring, along +x, of the final
    pass; ``ocr_force`` and ``skirt_force`` [N] (None when not modelled); ``ring_power``,
    ``ocr_power``, ``skirt_power`` [W] cycle means; ``power`` [W] the assembly's total;
    ``cylinders`` how many identical assemblies the engine has; ``power_divisor`` the cycle
    angle the powers are averaged over [rad] (4 pi time mean; 2 pi Yang's printed eq. 5.32).
    """

    theta: np.ndarray
    omega: float
    liner_speed: np.ndarray
    gas: GasSolution
    pack: PackSolution
    ring_force: tuple
    ocr_force: np.ndarray | None
    skirt_force: np.ndarray | None
    ring_power: tuple
    ocr_power: float
    skirt_power: float | None
    cylinders: int
    power_divisor: float

    @property
    def power(self) -> float:
        """Friction power of one piston assembly [W]: rings + OCR + skirt."""
        return float(sum(self.ring_power) + self.ocr_power + (self.skirt_power or 0.0))

    @property
    def engine_power(self) -> float:
        """Friction power of every piston assembly of the engine [W]."""
        return self.cylinders * self.power
