"""Exponential-polynomial lift fit of Lim et al. (1983), as used by Ball (1988) §5.3.

    l(theta) = lift_scale * exp(a0 + a1 theta + ... + am theta^m),   theta in rad from the nose

An exponential never reaches zero, so the event ends where the fitted lift falls to ``cutoff``;
beyond that the follower is on the base circle. Two blends are offered:

* ``"shift"`` (default): l = k (f - cutoff) with k = f(0) / (f(0) - cutoff). Lift is continuous
  at the cut-off and the nose lift is exactly the fitted one; velocity, acceleration and jerk
  step there by k f', k f'', k f''' (for the Rover fit with the default 1e-4 mm cut-off: 5.6e-5
  mm/deg and 2.9e-5 mm/deg^2, against peaks of 0.28 mm/deg and 1.3e-2 mm/deg^2; see
  ``joint_jumps``). Elsewhere the lift sits below the fit by cutoff * (1 - l/l_nose) < 1e-4 mm.
* ``"hard"``: l = f inside the event, so the fit is reproduced exactly, at the price of a lift step
  equal to the cut-off at both ends.
"""
from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.polynomial import polynomial as P

from camtrain.lift import _checks as chk
from camtrain.lift.base import TWO_PI, LiftLaw

# Rover 2300 inlet cam fitted by Lim et al. (1983); Ball (1988) §5.3: lift in mm, theta in rad
ROVER_2300 = (2.317111, -0.8104e-3, -1.526837, -0.1552985, -1.789897, 0.1171634, -0.2422081)

BLENDS = ("shift", "hard")


def exp_poly_lift(theta: np.ndarray, coefficients: Sequence[float], lift_scale: float = 1e-3):
    """The fitted function itself, lift_scale * exp(sum a_k theta^k) (Ball 1988 §5.3), [m].

    No cut-off; for comparing with published values of the fit.
    """
    return lift_scale * np.exp(P.polyval(np.asarray(theta, dtype=float), coefficients))


class ExpPolyLift(LiftLaw):
    """Exponential-polynomial lift with a base-circle cut-off (Lim et al. 1983; Ball 1988 §5.3).

    Parameters (SI)
    ---------------
    coefficients : a0, a1, ... of the exponent polynomial in theta [rad] (ln of lift/lift_scale);
        theta follows the camtrain convention (from the nose, increasing with time), which is
        also Ball's phi
    lift_scale : length unit the fit was made in [m]; 1e-3 for the published mm fits
    cutoff : lift [m] below which the follower is on the base circle (default 1e-7 m = 1e-4 mm)
    blend : "shift" (continuous lift, small derivative steps) or "hard" (exact fit, lift step)
    path : deck prefix for error messages
    """

    form = "exp_poly"

    def __init__(self, coefficients: Sequence[float], *, lift_scale: float = 1e-3,
                 cutoff: float = 1e-7, blend: str = "shift", path: str = "lift") -> None:
        base = f"{path}.{self.form}"
        a = chk.vector(coefficients, f"{base}.coefficients", min_len=3, max_len=20)
        self.lift_scale = chk.scalar(lift_scale, f"{base}.lift_scale", "length", minimum=0.0,
                                     strict=True)
        c = chk.scalar(cutoff, f"{base}.cutoff", "length", minimum=0.0, strict=True)
        if blend not in BLENDS:
            raise chk.fail(f"{base}.blend", "is not a known cut-off blend", blend,
                           " or ".join(BLENDS))
        self.coefficients, self.cutoff, self.blend = a, c, blend
        self._da = [P.polyder(a, k) for k in (1, 2, 3)]
        # the nose is the maximum of the exponent; search one revolution around theta = 0
        grid = np.linspace(-np.pi, np.pi, 7201)
        expo = P.polyval(grid, a)
        i = int(np.argmax(expo))
        if expo[i] > np.log(1.0 / self.lift_scale):          # more than a metre of lift
            raise chk.fail(f"{base}.coefficients", "give an implausible lift of more than 1 m",
                           None, "a fit in the units of lift_scale")
        level = np.log(c / self.lift_scale)
        if expo[i] <= level:
            raise chk.fail(f"{base}.cutoff", "is above the peak of the fitted lift",
                           chk.shown(c, "length"),
                           f"less than {chk.shown(self.lift_scale * np.exp(expo[i]), 'length')} mm")
        above = expo > level
        lo = i - np.argmin(above[i::-1]) if not above[0] else None
        hi = i + np.argmin(above[i:]) if not above[-1] else None
        if lo is None or hi is None or np.any(above[:lo]) or np.any(above[hi:]):
            raise chk.fail(f"{base}.coefficients",
                           "give a lift that does not return to the base circle once per "
                           "revolution", None,
                           f"a single lift event falling below the {chk.shown(c, 'length')} mm "
                           "cut-off within +-180 deg of the nose")
        from scipy.optimize import brentq  # only exp_poly decks pay for scipy.optimize

        f = lambda t: P.polyval(t, a) - level  # noqa: E731
        self._open = brentq(f, grid[lo], grid[lo + 1], xtol=1e-14)
        self._close = brentq(f, grid[hi - 1], grid[hi], xtol=1e-14)
        if self._close - self._open >= TWO_PI:
            raise chk.fail(f"{base}.cutoff", "makes the event longer than one cam revolution (mm)",
                           chk.shown(c, "length"))
        self.nose_lift = float(exp_poly_lift(0.0, a, self.lift_scale))
        self._gain = self.nose_lift / (self.nose_lift - c) if blend == "shift" else 1.0

    @classmethod
    def rover_2300(cls, **kwargs) -> ExpPolyLift:
        """Rover 2300 inlet cam (Lim et al. 1983 coefficients, Ball 1988 §5.3): nose 10.1463 mm."""
        return cls(ROVER_2300, **kwargs)

    @property
    def opening_angle(self) -> float:
        return float(self._open)

    @property
    def closing_angle(self) -> float:
        return float(self._close)

    def joints(self) -> list[tuple[float, str]]:
        return [(self.opening_angle, "opening cut-off"), (self.closing_angle, "closing cut-off")]

    def _kinematics(self, theta):
        out = [np.zeros_like(theta) for _ in range(4)]
        inside = theta <= self._close
        t = theta[inside]
        f = exp_poly_lift(t, self.coefficients, self.lift_scale)
        g1, g2, g3 = (P.polyval(t, d) for d in self._da)
        # derivatives of exp(g): f' = f g', f'' = f (g'' + g'^2), f''' = f (g''' + 3 g' g'' + g'^3)
        derivs = (f - (self.cutoff if self.blend == "shift" else 0.0), f * g1,
                  f * (g2 + g1 * g1), f * (g3 + 3.0 * g1 * g2 + g1 ** 3))
        for k in range(4):
            out[k][inside] = self._gain * derivs[k]
        return tuple(out)
