"""A lift law given as a B-spline: the kind ``camtrain design`` writes (docs/design.md).

The lift over the event is the B-spline (de Boor 2001, *A Practical Guide to Splines*, ch. IX)

    l(theta) = sum_i c_i B_{i,k}(theta; t)

of degree k on the knot vector t (cam angle from the nose), with coefficients c_i; outside
[t_0, t_last] the follower is on the base circle. Degree 5 with simple interior knots is the
classic quintic lift of the acceleration-spline construction (the acceleration a cubic spline,
the jerk continuous: Norton 2009, *Cam Design and Manufacturing Handbook*, 2nd ed.).
A B-spline of degree k is C^(k-1) across a simple interior knot; at the ends (knots of
multiplicity k+1) the lift and its first m derivatives meet the base circle without a step when
the first and last m+1 coefficients are zero.
"""
from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from camtrain.lift import _checks as chk
from camtrain.lift.base import MM, TWO_PI, LiftLaw


class SplineLift(LiftLaw):
    """Lift as a B-spline of ``degree`` on ``knots`` [rad] with ``coefficients`` [m].

    The knot vector is the full one (len(coefficients) + degree + 1 values, non-decreasing),
    its end knots repeated degree + 1 times so that the lift at the ends is the end coefficient,
    which must be zero (within 1 um): the lift starts and ends on the base circle.
    """

    form = "spline"

    def __init__(self, knots: Sequence[float], coefficients: Sequence[float], degree: int = 5,
                 *, path: str = "lift") -> None:
        from scipy.interpolate import BSpline

        base = f"{path}.{self.form}"
        k = int(chk.scalar(degree, f"{base}.degree", minimum=1, maximum=9))
        t = chk.vector(knots, f"{base}.knots", min_len=2 * k + 2, kind="angle")
        c = chk.vector(coefficients, f"{base}.coefficients", min_len=k + 1, kind="length")
        if t.size != c.size + k + 1:
            raise chk.fail(f"{base}.knots", f"has {t.size} values for {c.size} coefficients of "
                           f"degree {k}", None, f"{c.size + k + 1} knots (coefficients + degree"
                           " + 1)")
        if np.any(np.diff(t) < 0.0):
            raise chk.fail(f"{base}.knots", "must not decrease", None, "non-decreasing angles")
        if np.any(t[:k + 1] != t[0]) or np.any(t[-k - 1:] != t[-1]):
            raise chk.fail(f"{base}.knots", f"must repeat each end knot degree + 1 = {k + 1} "
                           "times", None, "a clamped knot vector")
        if not (t[0] < 0.0 < t[-1]) or t[-1] - t[0] >= TWO_PI:
            raise chk.fail(f"{base}.knots", "must span the nose (0 deg) and less than one "
                           "revolution", [chk.shown(t[0], "angle"), chk.shown(t[-1], "angle")],
                           "first knot < 0 < last knot, span < 360 deg")
        if abs(c[0]) > 1e-6 or abs(c[-1]) > 1e-6:
            raise chk.fail(f"{base}.coefficients", "must start and end at zero lift (the base "
                           "circle)", [chk.shown(c[0], "length"), chk.shown(c[-1], "length")],
                           "first and last coefficient 0 mm")
        self.degree, self.knots, self.coefficients = k, t, c
        self._spline = BSpline(t, c, k, extrapolate=False)
        fine = np.linspace(t[0], t[-1], 4001)
        low = float(np.min(self._spline(fine)))
        if low < -1e-6:
            raise chk.fail(f"{base}.coefficients", "give a negative lift", chk.shown(low, "length"),
                           "a lift >= 0 over the event")

    @property
    def opening_angle(self) -> float:
        return float(self.knots[0])

    @property
    def closing_angle(self) -> float:
        return float(self.knots[-1])

    def _kinematics(self, theta):
        inside = theta <= self.knots[-1]
        out = [np.zeros_like(theta) for _ in range(4)]
        if not np.any(inside):
            return tuple(out)
        x = theta[inside]
        out[0][inside] = self._spline(x)
        for n in (1, 2, 3):
            if n <= self.degree:
                out[n][inside] = self._spline(x, nu=n)
        return tuple(np.nan_to_num(v) for v in out)

    def joints(self) -> list[tuple[float, str]]:
        inner = np.unique(self.knots[self.degree + 1:-self.degree - 1])
        out = [(float(self.knots[0]), "opening end (base circle)")]
        out += [(float(a), f"knot {i + 1}") for i, a in enumerate(inner)]
        out.append((float(self.knots[-1]), "closing end (base circle)"))
        return out

    @property
    def max_lift(self) -> float:
        theta = np.linspace(self.knots[0], self.knots[-1], 8001)
        return float(np.max(self._spline(theta)))

    def in_deck_units(self) -> dict:
        """The deck section ``[lift.spline]`` of this law (knots in deg, coefficients in mm)."""
        return {"degree": self.degree,
                "knots": [float(f"{v:.12g}") for v in np.degrees(self.knots)],
                "coefficients": [float(f"{v:.12g}") for v in self.coefficients / MM]}
