"""The cam's displacement input in time: the rigid valve lift as a function of cam angle,
interpolated between the grid angles, and the camshaft's time base.

The lift l(theta) and its derivatives l', l'' are known on the run's periodic angle grid (the
kinematics). Between grid angles the input is the quintic Hermite interpolant matching l, l',
l'' at both ends: C2, exact for quintics, error O(h^6), so the cam acceleration the train feels
is continuous and the grid values are reproduced exactly.

Time base: constant speed, theta = theta0 + w t, or Williams' (2013, App A6, eqs A6.5-A6.7 with
the omega Omega correction of the reference notes) oscillating camshaft speed
theta' = w + w_hat sin(Omega t), Omega = order * w, so that
b'' = l''(theta) theta'^2 + l'(theta) w_hat Omega cos(Omega t).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["CamInput", "TimeBase"]


@dataclass(frozen=True)
class TimeBase:
    """Camshaft angle against time: mean speed ``omega`` [rad/s], oscillation amplitude
    ``amplitude`` [rad/s] at ``order`` x the camshaft speed (0: constant speed), the speed
    w + amplitude sin(order (w t) + phase)."""

    omega: float
    amplitude: float = 0.0
    order: int = 0
    #: phase of the oscillation at t = 0 [rad]: order x (start angle - the grid's first
    #: angle), so that the oscillation is tied to the cam angle, not to where a march starts
    phase: float = 0.0

    @property
    def period(self) -> float:
        """One camshaft revolution [s] (the oscillation is periodic in it: integer order)."""
        return 2.0 * math.pi / self.omega

    def angle(self, t):
        """(theta - theta0, theta', theta'') at times t [s]."""
        t = np.asarray(t, dtype=float)
        if self.amplitude == 0.0 or self.order == 0:
            return self.omega * t, np.full(t.shape, self.omega), np.zeros(t.shape)
        big = self.order * self.omega
        a, p = self.amplitude, self.phase
        return (self.omega * t + a / big * (math.cos(p) - np.cos(big * t + p)),
                self.omega + a * np.sin(big * t + p), a * big * np.cos(big * t + p))

    def starting_at(self, theta0: float, theta_first: float) -> TimeBase:
        """This time base for a march that starts (t = 0) at cam angle ``theta0`` of a grid
        whose first angle is ``theta_first``: the oscillation keeps its phase against the
        cam angle (speed w + amplitude sin(order (theta - theta_first)) at mean angle
        theta)."""
        if self.amplitude == 0.0 or self.order == 0:
            return self
        return TimeBase(self.omega, self.amplitude, self.order,
                        self.phase + self.order * (theta0 - theta_first))


@dataclass(frozen=True)
class CamInput:
    """Periodic quintic Hermite interpolant of the lift on a uniform grid over 2 pi.

    ``theta`` [rad] (uniform, no duplicate end point), ``lift`` [m], ``d1`` [m/rad],
    ``d2`` [m/rad^2]; optionally the contact geometry a nonlinear cam contact needs on the same
    grid: the cam's radius of curvature ``radius`` [m] and the load ratio ``ratio`` W/F_valve.
    """

    theta: np.ndarray
    lift: np.ndarray
    d1: np.ndarray
    d2: np.ndarray
    radius: np.ndarray | None = None
    ratio: np.ndarray | None = None

    def geometry(self, theta):
        """(radius, ratio) at any angles [rad] (periodic linear interpolation); empty arrays
        when the input carries no geometry."""
        if self.radius is None:
            return np.zeros(0), np.zeros(0)
        x = np.mod(np.asarray(theta, dtype=float) - self.theta[0], 2.0 * math.pi)
        grid = self.theta - self.theta[0]
        ratio = self.ratio if self.ratio is not None else np.ones_like(self.radius)
        return (np.interp(x, grid, self.radius, period=2.0 * math.pi),
                np.interp(x, grid, ratio, period=2.0 * math.pi))

    @property
    def step(self) -> float:
        return 2.0 * math.pi / self.theta.size

    def evaluate(self, theta):
        """(l, l', l'') at any angles [rad] (periodic)."""
        theta = np.asarray(theta, dtype=float)
        h = self.step
        x = np.mod(theta - self.theta[0], 2.0 * math.pi) / h
        i = np.minimum(np.floor(x).astype(np.int64), self.theta.size - 1)
        t = x - i
        j = (i + 1) % self.theta.size
        y0, y1 = self.lift[i], self.lift[j]
        v0, v1 = self.d1[i] * h, self.d1[j] * h
        a0, a1 = self.d2[i] * h * h, self.d2[j] * h * h
        # quintic Hermite basis on [0, 1]
        t2, t3 = t * t, t * t * t
        t4, t5 = t3 * t, t3 * t2
        h0 = 1 - 10 * t3 + 15 * t4 - 6 * t5
        h1 = t - 6 * t3 + 8 * t4 - 3 * t5
        h2 = 0.5 * (t2 - 3 * t3 + 3 * t4 - t5)
        h3 = 0.5 * (t3 - 2 * t4 + t5)
        h4 = -4 * t3 + 7 * t4 - 3 * t5
        h5 = 10 * t3 - 15 * t4 + 6 * t5
        d_h0 = -30 * t2 + 60 * t3 - 30 * t4
        d_h1 = 1 - 18 * t2 + 32 * t3 - 15 * t4
        d_h2 = 0.5 * (2 * t - 9 * t2 + 12 * t3 - 5 * t4)
        d_h3 = 0.5 * (3 * t2 - 8 * t3 + 5 * t4)
        d_h4 = -12 * t2 + 28 * t3 - 15 * t4
        d_h5 = -d_h0
        dd_h0 = -60 * t + 180 * t2 - 120 * t3
        dd_h1 = -36 * t + 96 * t2 - 60 * t3
        dd_h2 = 0.5 * (2 - 18 * t + 36 * t2 - 20 * t3)
        dd_h3 = 0.5 * (6 * t - 24 * t2 + 20 * t3)
        dd_h4 = -24 * t + 84 * t2 - 60 * t3
        dd_h5 = -dd_h0
        lift = h0 * y0 + h1 * v0 + h2 * a0 + h3 * a1 + h4 * v1 + h5 * y1
        d1 = (d_h0 * y0 + d_h1 * v0 + d_h2 * a0 + d_h3 * a1 + d_h4 * v1 + d_h5 * y1) / h
        d2 = (dd_h0 * y0 + dd_h1 * v0 + dd_h2 * a0 + dd_h3 * a1 + dd_h4 * v1
              + dd_h5 * y1) / (h * h)
        return lift, d1, d2

    def geometry_at(self, theta: float) -> tuple[float, float]:
        """(radius, ratio) at one angle, in plain floats (the adaptive right-hand side)."""
        h = 2.0 * math.pi / self.theta.size
        x = ((theta - float(self.theta[0])) % (2.0 * math.pi)) / h
        i = min(int(x), self.theta.size - 1)
        t = x - i
        j = (i + 1) % self.theta.size
        radius = float(self.radius[i]) * (1.0 - t) + float(self.radius[j]) * t
        if self.ratio is None:
            return radius, 1.0
        return radius, float(self.ratio[i]) * (1.0 - t) + float(self.ratio[j]) * t

    def at(self, theta: float) -> tuple[float, float, float]:
        """(l, l', l'') at one angle, in plain floats (the adaptive integrators' right-hand
        side calls this once per evaluation: no array overhead)."""
        h = 2.0 * math.pi / self.theta.size
        x = ((theta - float(self.theta[0])) % (2.0 * math.pi)) / h
        i = min(int(x), self.theta.size - 1)
        t = x - i
        j = (i + 1) % self.theta.size
        y0, y1 = float(self.lift[i]), float(self.lift[j])
        v0, v1 = float(self.d1[i]) * h, float(self.d1[j]) * h
        a0, a1 = float(self.d2[i]) * h * h, float(self.d2[j]) * h * h
        t2 = t * t
        t3 = t2 * t
        t4 = t3 * t
        t5 = t4 * t
        lift = ((1 - 10 * t3 + 15 * t4 - 6 * t5) * y0 + (t - 6 * t3 + 8 * t4 - 3 * t5) * v0
                + 0.5 * (t2 - 3 * t3 + 3 * t4 - t5) * a0 + 0.5 * (t3 - 2 * t4 + t5) * a1
                + (-4 * t3 + 7 * t4 - 3 * t5) * v1 + (10 * t3 - 15 * t4 + 6 * t5) * y1)
        dh0 = -30 * t2 + 60 * t3 - 30 * t4
        d1 = (dh0 * (y0 - y1) + (1 - 18 * t2 + 32 * t3 - 15 * t4) * v0
              + 0.5 * (2 * t - 9 * t2 + 12 * t3 - 5 * t4) * a0
              + 0.5 * (3 * t2 - 8 * t3 + 5 * t4) * a1 + (-12 * t2 + 28 * t3 - 15 * t4) * v1) / h
        ddh0 = -60 * t + 180 * t2 - 120 * t3
        d2 = (ddh0 * (y0 - y1) + (-36 * t + 96 * t2 - 60 * t3) * v0
              + 0.5 * (2 - 18 * t + 36 * t2 - 20 * t3) * a0 + 0.5 * (6 * t - 24 * t2 + 20 * t3) * a1
              + (-24 * t + 84 * t2 - 60 * t3) * v1) / (h * h)
        return lift, d1, d2

    def in_time(self, t, base: TimeBase, theta0: float):
        """Cam input b, b', b'' [m, m/s, m/s^2] at times t for a start angle theta0."""
        dtheta, rate, accel = base.angle(t)
        lift, d1, d2 = self.evaluate(theta0 + dtheta)
        return lift, d1 * rate, d2 * rate * rate + d1 * accel


def cam_input(theta, lift, d1, d2, base_circle: float = 0.0, *, radius=None,
              ratio=None) -> CamInput:
    """The cam input from the rigid valve lift on the grid, with the lift below ``base_circle``
    [m] (the base-circle tolerance of the lift data, plus any lash that the caller handles
    separately) taken as the base circle: b = max(l - tol, 0). Ripple of a smoothed lift table
    below the tolerance would otherwise make a zero-lash contact chatter on the base circle."""
    lift = np.asarray(lift, dtype=float)
    on = lift > base_circle
    geometry = {}
    if radius is not None:
        geometry = {"radius": np.asarray(radius, dtype=float),
                    "ratio": None if ratio is None else np.asarray(ratio, dtype=float)}
    return CamInput(np.asarray(theta, dtype=float), np.where(on, lift - base_circle, 0.0),
                    np.where(on, d1, 0.0), np.where(on, d2, 0.0), **geometry)
