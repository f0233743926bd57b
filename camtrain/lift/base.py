"""The lift curve every mechanism consumes, and the one cam-angle convention of camtrain.

Angle convention (used everywhere inside camtrain):

* ``theta`` is the **cam** angle in radians, measured from the maximum-lift (nose) position;
* it increases with time for a cam turning at constant speed (theta = omega * t), so negative
  angles are the opening flank and positive angles the closing flank;
* one revolution is represented on the grid ``[-pi, pi)``; lift laws are periodic;
* crank angle = 2 x cam angle for a four-stroke engine; the timing offset (where the nose sits in
  the engine cycle) is applied only when lobes are combined on a camshaft.

Derivatives are with respect to the cam angle in radians (m/rad, m/rad^2, m/rad^3); multiply by
omega, omega^2, omega^3 for time derivatives.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def angle_grid(points: int) -> np.ndarray:
    """Uniform cam-angle grid of ``points`` values over one revolution, [-pi, pi), in radians.

    The grid always contains theta = 0 (the nose) when ``points`` is even.
    """
    if points < 8:
        raise ValueError(f"angle grid needs at least 8 points, got {points}")
    return -np.pi + 2.0 * np.pi * np.arange(points) / points


@dataclass(frozen=True)
class LiftCurve:
    """Lift and its derivatives on a cam-angle grid (SI: m and radians).

    Attributes
    ----------
    theta : cam angle [rad], convention of this module
    lift : lift [m]
    d1, d2, d3 : first, second, third derivative of lift w.r.t. theta [m/rad^k]
    """

    theta: np.ndarray
    lift: np.ndarray
    d1: np.ndarray
    d2: np.ndarray
    d3: np.ndarray

    def __post_init__(self) -> None:
        n = self.theta.shape
        for name in ("lift", "d1", "d2", "d3"):
            if getattr(self, name).shape != n:
                raise ValueError(f"LiftCurve.{name} has shape {getattr(self, name).shape}, "
                                 f"theta has {n}")

    @property
    def max_lift(self) -> float:
        return float(np.max(self.lift))
