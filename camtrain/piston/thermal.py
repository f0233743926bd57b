"""Liner temperature along the stroke and the oil's viscosity-temperature law (Yang 1992 §5.3,
App. D.3-D.4).

Yang gives the liner temperature at three places (the top ring's position at TDC, mid-stroke
and the top ring's position at BDC) and fits a quadratic through them; each ring's viscosity is
the oil's at the liner temperature where the ring is. The source prints two viscosity points
(0.009865 Pa s at 95 degC, 0.005123 Pa s at 135 degC) but no law: with two points ln eta is
linear in T (``exponential``; slope -0.01638 /degC for the Zeta oil), with three Vogel's
ln eta = A + B/(T + C) (``vogel``). Temperatures are in degC, as the source gives them.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

VISCOSITY_LAWS = ("exponential", "vogel")


def liner_temperature(travel, stroke: float, top: float, middle: float, bottom: float):
    """Liner temperature [degC] at ``travel`` [m] below the top ring's TDC position: the
    quadratic through (0, top), (stroke/2, middle), (stroke, bottom) (Yang §5.3, App. D.3)."""
    s = np.asarray(travel, dtype=float) / stroke
    # Lagrange form on the nodes 0, 1/2, 1 of the stroke fraction
    return (top * (2.0 * s - 1.0) * (s - 1.0) - 4.0 * middle * s * (s - 1.0)
            + bottom * s * (2.0 * s - 1.0))


@dataclass(frozen=True)
class ViscosityLaw:
    """eta(T) through measured points: ``temperatures`` [degC] and ``viscosities`` [Pa s].

    ``exponential``: ln eta linear in T through the first and last points (two points suffice;
    the source's reading). ``vogel``: ln eta = A + B/(T + C) through exactly three points.
    """

    temperatures: tuple
    viscosities: tuple
    law: str = "exponential"

    def __post_init__(self):
        if self.law not in VISCOSITY_LAWS:
            raise ValueError(f"unknown viscosity law {self.law!r}; expected one of "
                             f"{VISCOSITY_LAWS}")
        need = 2 if self.law == "exponential" else 3
        if len(self.temperatures) != len(self.viscosities) or len(self.temperatures) < need:
            raise ValueError(f"the {self.law} law needs at least {need} (T, eta) points")

    def vogel_constants(self) -> tuple[float, float, float]:
        """(A, B, C) of ln eta = A + B/(T + C) through the three points (closed form in C)."""
        (t1, t2, t3), (e1, e2, e3) = self.temperatures[:3], np.log(self.viscosities[:3])
        # (e1 - e2)/(e2 - e3) = [(t2 - t1)/((t1 + C)(t2 + C))] / [(t3 - t2)/((t2 + C)(t3 + C))]
        r = (e1 - e2) / (e2 - e3) * (t3 - t2) / (t2 - t1)
        # r (t1 + C) = t3 + C
        c = (t3 - r * t1) / (r - 1.0)
        b = (e1 - e2) / (1.0 / (t1 + c) - 1.0 / (t2 + c))
        return float(e1 - b / (t1 + c)), float(b), float(c)

    def __call__(self, temperature):
        """Viscosity [Pa s] at ``temperature`` [degC] (array or scalar)."""
        t = np.asarray(temperature, dtype=float)
        if self.law == "exponential":
            t1, t2 = self.temperatures[0], self.temperatures[-1]
            e1, e2 = self.viscosities[0], self.viscosities[-1]
            slope = math.log(e2 / e1) / (t2 - t1)
            return e1 * np.exp(slope * (t - t1))
        a, b, c = self.vogel_constants()
        return np.exp(a + b / (t + c))
