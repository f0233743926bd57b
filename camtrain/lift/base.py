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

from abc import ABC, abstractmethod
from dataclasses import dataclass
from typing import ClassVar

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


# --------------------------------------------------------------------------------------------
# Lift laws: the common interface every lift family implements.
# --------------------------------------------------------------------------------------------

TWO_PI = 2.0 * np.pi
MM = 1.0e-3                 # metres per millimetre
DEG = np.pi / 180.0         # radians per degree


def per_degree(value: float, order: int) -> float:
    """Convert a lift derivative of ``order`` from m/rad^order to mm/deg^order (for messages)."""
    return float(value) / MM * DEG ** order


@dataclass(frozen=True)
class JointJump:
    """Jump (right-hand minus left-hand limit) of lift and derivatives at one joint of a law.

    ``angle`` in rad (the convention above); jumps in m, m/rad, m/rad^2, m/rad^3.
    """

    angle: float
    label: str
    lift: float
    d1: float
    d2: float
    d3: float

    def in_mm_deg(self) -> dict[str, float]:
        """The same jump in the units the sources print: deg, mm, mm/deg, mm/deg^2, mm/deg^3."""
        return {"angle_deg": self.angle / DEG, "lift_mm": self.lift / MM,
                "d1_mm_per_deg": per_degree(self.d1, 1), "d2_mm_per_deg2": per_degree(self.d2, 2),
                "d3_mm_per_deg3": per_degree(self.d3, 3)}

    def describe(self) -> str:
        e = self.in_mm_deg()
        return (f"{self.label} at {e['angle_deg']:.3f} deg: lift {e['lift_mm']:+.3e} mm, "
                f"velocity {e['d1_mm_per_deg']:+.3e} mm/deg, acceleration "
                f"{e['d2_mm_per_deg2']:+.3e} mm/deg^2, jerk {e['d3_mm_per_deg3']:+.3e} mm/deg^3")


class LiftLaw(ABC):
    """A periodic lift law: lift and three derivatives for any cam angle (SI, the convention above).

    Subclasses define the event between ``opening_angle`` (< closing) and ``closing_angle``; outside
    it the follower is on the base circle (lift and derivatives exactly zero). ``_kinematics``
    receives angles already mapped into ``[opening_angle, opening_angle + 2 pi)``, so an event that
    straddles +-pi needs no special care.
    """

    form: ClassVar[str] = ""

    @property
    @abstractmethod
    def opening_angle(self) -> float:
        """Cam angle [rad] where the lift leaves the base circle (start of the opening ramp)."""

    @property
    @abstractmethod
    def closing_angle(self) -> float:
        """Cam angle [rad] where the lift returns to the base circle."""

    @property
    def event_angle(self) -> float:
        """Cam angle [rad] spanned by the event, ramps included."""
        return self.closing_angle - self.opening_angle

    @property
    def max_lift(self) -> float:
        """Peak lift [m] (ramps included), from a fine evaluation unless a law knows it exactly."""
        theta = np.linspace(self.opening_angle, self.closing_angle, 4001)
        return float(np.max(self._kinematics(theta)[0]))

    @abstractmethod
    def _kinematics(self, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray,
                                                      np.ndarray]:
        """Lift, d1, d2, d3 at angles in ``[opening_angle, opening_angle + 2 pi)``."""

    def joints(self) -> list[tuple[float, str]]:
        """Angles [rad] and names of the places where the law changes piece (for jump reports)."""
        return []

    def evaluate(self, theta: np.ndarray) -> LiftCurve:
        """Lift and derivatives at the cam angles ``theta`` [rad] (any values; periodic 2 pi)."""
        theta = np.asarray(theta, dtype=float)
        if not np.all(np.isfinite(theta)):
            raise ValueError("cam angles passed to a lift law must be finite")
        local = self.opening_angle + np.mod(theta - self.opening_angle, TWO_PI)
        lift, d1, d2, d3 = self._kinematics(local)
        return LiftCurve(theta.copy(), lift, d1, d2, d3)

    def joint_jumps(self) -> list[JointJump]:
        """Jump of lift, velocity, acceleration and jerk at every joint of the law.

        One-sided limits are taken 1e-10 rad either side of the joint; that perturbs a lift jump
        by at most 2e-10 * |d1| (< 1e-11 m for any real cam), far below anything reported.
        Laws with closed-form pieces override this with exact end values.
        """
        out = []
        for angle, label in self.joints():
            eps = 1e-10 * max(1.0, abs(angle))
            left = self.evaluate(np.array([angle - eps]))
            right = self.evaluate(np.array([angle + eps]))
            out.append(JointJump(angle, label, *(float(getattr(right, k)[0] - getattr(left, k)[0])
                                                 for k in ("lift", "d1", "d2", "d3"))))
        return out


def evaluate_on_grid(law: LiftLaw, points: int = 360) -> LiftCurve:
    """Evaluate ``law`` on the uniform periodic grid ``angle_grid(points)`` (rad, [-pi, pi))."""
    return law.evaluate(angle_grid(points))
