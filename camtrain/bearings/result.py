"""Outputs of a journal-bearing calculation: one record of SI arrays on the load-diagram grid."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["JournalOrbit"]


@dataclass(frozen=True)
class JournalOrbit:
    """Journal-centre orbit and losses over one load cycle.

    Arrays are sampled at ``angle`` (the load-diagram grid). Angles are in radians in the
    bush-fixed frame of the load components, counter-clockwise positive.

    Attributes:
        angle: load-diagram angle [rad].
        time: time from the start of the cycle [s].
        load_x, load_y: load on the film [N].
        eps_x, eps_y: eccentricity-ratio vector (bush centre -> journal centre) [-].
        eccentricity: |eps| [-], always < 1.
        attitude: angle from the load direction to the line of centres [rad], in (-pi, pi].
        position: direction of the line of centres (= direction of minimum film) [rad].
        h_min: minimum film thickness c (1 - eps) [m]; its angle is ``position``.
        power_shear: Couette shear power [W] (Yang 1992 eq. 1.21/1.22 in 1.20).
        power_squeeze: translatory term W . V in the frame turning at wbar [W] (Yang eq. 1.23);
            0 when the journal sits still in that frame.
        power: the power selected by ``terms`` [W].
        method: "mobility-exact", "mobility-booker" or "steady".
        film: "pi" or "2pi" (the shear film used for power).
        cycles: cycles marched (1 for the steady method).
        periodicity_error: max |eps(cycle k) - eps(cycle k-1)| on the grid at the end [-].
        converged: True when periodicity_error <= the requested tolerance.
        period: duration of one load cycle [s].
    """

    angle: np.ndarray
    time: np.ndarray
    load_x: np.ndarray
    load_y: np.ndarray
    eps_x: np.ndarray
    eps_y: np.ndarray
    eccentricity: np.ndarray
    attitude: np.ndarray
    position: np.ndarray
    h_min: np.ndarray
    power_shear: np.ndarray
    power_squeeze: np.ndarray
    power: np.ndarray
    method: str
    film: str
    cycles: int
    periodicity_error: float
    converged: bool
    period: float

    @property
    def mean_power(self) -> float:
        """Time-mean power over the cycle [W] (trapezoid on the periodic grid)."""
        return _cycle_mean(self.time, self.power, self.period)

    @property
    def mean_power_shear(self) -> float:
        return _cycle_mean(self.time, self.power_shear, self.period)

    @property
    def max_eccentricity(self) -> float:
        return float(np.max(self.eccentricity))

    @property
    def min_film(self) -> float:
        """Smallest h_min over the cycle [m]."""
        return float(np.min(self.h_min))

    @property
    def min_film_angle(self) -> float:
        """Load-diagram angle at which the smallest film occurs [rad]."""
        return float(self.angle[int(np.argmin(self.h_min))])

    @property
    def min_film_position(self) -> float:
        """Bush-frame direction of the smallest film [rad]."""
        return float(self.position[int(np.argmin(self.h_min))])


def _cycle_mean(t: np.ndarray, y: np.ndarray, period: float) -> float:
    if t.size == 1 or period <= 0.0:
        return float(y[0])
    tt = np.append(t, t[0] + period)
    yy = np.append(y, y[0])
    return float(np.trapezoid(yy, tt) / period)
