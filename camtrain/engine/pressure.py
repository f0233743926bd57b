"""Cylinder-pressure tables against crank angle, interpolated periodically over the cycle.

Yang (1992) App. A.5/B.5 give pressure every 10 deg from 0 (firing TDC) to 710 deg; his program
computed the loads at the table angles and interpolated them linearly to 0.5 deg (§2.2).
Here the pressure itself is interpolated on the cycle, as a periodic cubic spline (default,
smooth loads) or piecewise linear (the seed's order of accuracy). Tables are gauge pressures
inside; an absolute table is turned into gauge by subtracting the crankcase pressure.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camtrain.errors import field_error

__all__ = ["PressureTable", "INTERPOLATIONS", "net_imep", "scaled"]

INTERPOLATIONS = ("periodic_cubic", "linear")


@dataclass(frozen=True)
class PressureTable:
    """One cylinder-pressure table over a cycle.

    Attributes:
        angle: crank angles from firing TDC [rad], increasing, spanning less than ``cycle``.
        pressure: cylinder pressure at those angles [Pa] (gauge unless ``absolute``).
        cycle: cycle angle [rad]: 4 pi (4-stroke) or 2 pi (2-stroke).
        absolute: True when ``pressure`` is absolute; ``crankcase`` is then subtracted.
        crankcase: crankcase (ambient) pressure [Pa] for absolute tables.
        name: deck path for messages.
    """

    angle: tuple
    pressure: tuple
    cycle: float = 4.0 * math.pi
    absolute: bool = False
    crankcase: float = 101325.0
    name: str = "engine.pressure"

    def __post_init__(self):
        th = np.asarray(self.angle, dtype=float)
        p = np.asarray(self.pressure, dtype=float)
        if th.ndim != 1 or th.size < 4 or p.shape != th.shape:
            raise field_error(f"{self.name}.pressure", "needs >= 4 values, one per angle",
                              (th.size, p.size))
        if not (np.all(np.isfinite(th)) and np.all(np.isfinite(p))):
            raise field_error(f"{self.name}.pressure", "angles and pressures must be finite")
        if np.any(np.diff(th) <= 0) or th[-1] - th[0] >= self.cycle - 1e-12:
            raise field_error(f"{self.name}.angle", "must increase and span less than a cycle",
                              (float(np.degrees(th[0])), float(np.degrees(th[-1]))),
                              f"a span < {math.degrees(self.cycle):g} deg")

    def gauge(self) -> np.ndarray:
        """Table values as gauge pressure [Pa]."""
        p = np.asarray(self.pressure, dtype=float)
        return p - self.crankcase if self.absolute else p

    def __call__(self, theta, interpolation: str = "periodic_cubic") -> np.ndarray:
        """Gauge pressure [Pa] at crank angles ``theta`` [rad] (any real values; periodic)."""
        th = np.asarray(self.angle, dtype=float)
        p = self.gauge()
        x = th[0] + np.mod(np.asarray(theta, dtype=float) - th[0], self.cycle)
        xs = np.append(th, th[0] + self.cycle)
        ps = np.append(p, p[0])
        if interpolation == "linear":
            return np.interp(x, xs, ps)
        if interpolation == "periodic_cubic":
            from scipy.interpolate import CubicSpline
            return CubicSpline(xs, ps, bc_type="periodic")(x)
        raise field_error("engine.solver.pressure_interpolation", "unknown interpolation",
                          interpolation, " or ".join(INTERPOLATIONS))


def net_imep(table: PressureTable, crank_radius: float, rod_length: float,
             interpolation: str = "periodic_cubic", step: float = math.radians(0.25)) -> float:
    r"""Net indicated mean effective pressure [Pa] of a diagram over its cycle,
    :math:`\oint p\, dV / V_d` with the slider-crank volume (per unit piston area:
    :math:`dx/d\theta = R \sin\theta\,[1 + R\cos\theta / \sqrt{L^2 - R^2 \sin^2\theta}]`,
    V_d / A = 2R). A constant pressure integrates to zero, so gauge and absolute tables give
    the same value. Trapezoidal rule on a periodic grid of ``step`` [rad]."""
    n = max(8, int(round(table.cycle / step)))
    th = table.angle[0] + np.arange(n) * (table.cycle / n)
    s = np.sin(th)
    dx = crank_radius * s * (1.0 + crank_radius * np.cos(th)
                             / np.sqrt(rod_length**2 - (crank_radius * s) ** 2))
    work = np.sum(table(th, interpolation) * dx) * (table.cycle / n)
    return float(work / (2.0 * crank_radius))


def scaled(table: PressureTable, factor: float) -> PressureTable:
    """The diagram with its gauge pressure multiplied by ``factor`` (an absolute table keeps
    its crankcase pressure)."""
    p = table.gauge() * factor
    if table.absolute:
        p = p + table.crankcase
    return PressureTable(table.angle, tuple(float(v) for v in p), table.cycle, table.absolute,
                         table.crankcase, table.name)
