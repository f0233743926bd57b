"""Lift given as discrete data points (Ball 1988 §4.2.1; Williams 2013 App 2; Yang 1992 App C).

Differentiating a table printed to a few decimals amplifies its rounding error: with 1 deg steps
and 4-decimal millimetres, Ball's central second difference carries about 0.2 mm/rad^2 of noise
(sqrt(6) sigma / h^2), which Ball himself warns about. Two methods are offered:

* ``"spline"`` (default): a periodic smoothing spline of degree 5 (scipy ``make_splrep``), so
  lift, velocity, acceleration and jerk are all continuous. The smoothing level follows from the
  data precision: rounding to a step q leaves uniform errors of standard deviation
  sigma = q / sqrt(12), and the spline may depart from the n points by sum (residual^2) <= n sigma^2
  (times ``smoothing``; 0 interpolates).
* ``"central"``: Ball's central differences at the data points, kept to reproduce his numbers
  (values between data points are interpolated linearly).

The table is closed over the revolution with base-circle zeros at the table's own spacing; the
event is the span between the last zero before the lift starts and the first zero after it ends,
and outside it lift and derivatives are exactly zero. Where the data itself has a step in
acceleration (a constant-velocity flank meeting a constant-acceleration one, as in the Zeta
tables), every smooth fit overshoots near the step; ``noise_estimate`` covers noise only.
"""
from __future__ import annotations

import warnings
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from camtrain.lift import _checks as chk
from camtrain.lift.base import DEG, MM, TWO_PI, LiftLaw, per_degree
from camtrain.lift.datasets import LiftTable, decimal_quantum, load_csv, load_dataset

METHODS = ("spline", "central")
_ALIASES = {"smoothing_spline": "spline", "central_difference": "central"}


@dataclass(frozen=True)
class TableNoise:
    """Noise of a table and of its derivatives (SI; RMS over the points of the event).

    lift_quantum : printed lift step [m]; lift_sigma : noise assumed for the data [m];
    residual_rms : RMS of fit minus data [m] (0 for central differences);
    d1, d2, d3 : RMS noise of the derivatives [m/rad^k] propagated from ``lift_sigma``
    (analytically for central differences, by refitting perturbed data for the spline).
    """

    method: str
    lift_quantum: float
    lift_sigma: float
    residual_rms: float
    d1: float
    d2: float
    d3: float

    def in_mm_deg(self) -> dict[str, float]:
        return {"lift_sigma_mm": self.lift_sigma / MM, "residual_rms_mm": self.residual_rms / MM,
                "d1_mm_per_deg": per_degree(self.d1, 1), "d2_mm_per_deg2": per_degree(self.d2, 2),
                "d3_mm_per_deg3": per_degree(self.d3, 3)}


def central_differences(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, ...]:
    """Three-point central differences on a periodic grid (Ball 1988 §4.2.1).

    ``x`` increasing over less than one period 2 pi, ``y`` the values. First and second
    derivatives use the non-uniform three-point formulas (the textbook central difference on a
    uniform grid); the third derivative is the central difference of the second, which on a
    uniform grid is the five-point (y[i+2] - 2y[i+1] + 2y[i-1] - y[i-2]) / 2h^3.
    """
    def d(values):
        xm, xp = np.roll(x, 1), np.roll(x, -1)
        xm[0] -= TWO_PI
        xp[-1] += TWO_PI
        h1, h2 = x - xm, xp - x
        vm, vp = np.roll(values, 1), np.roll(values, -1)
        first = (-h2 / (h1 * (h1 + h2)) * vm + (h2 - h1) / (h1 * h2) * values
                 + h1 / (h2 * (h1 + h2)) * vp)
        second = 2.0 * (vm / (h1 * (h1 + h2)) - values / (h1 * h2) + vp / (h2 * (h1 + h2)))
        return first, second

    d1, d2 = d(y)
    d3, _ = d(d2)
    return d1, d2, d3


class TableLift(LiftLaw):
    """Lift from data points with derivatives by smoothing spline or central differences.

    Parameters (SI)
    ---------------
    angles : cam angles [rad], the camtrain convention, strictly increasing
    lift : lift [m] at those angles, returning to the base circle (0) at both ends
    symmetric : the table gives one flank only (angles all >= 0 or all <= 0); it is mirrored
    method : "spline" (default) or "central" (also accepted: "smoothing_spline",
        "central_difference")
    noise : standard deviation of the data error [m]; default lift_quantum / sqrt(12)
    smoothing : multiplier of the automatic smoothing level (1 or None = residuals at the noise
        level, 0 = interpolate); larger is smoother
    degree : spline degree, 3 or 5 (5 gives a continuous jerk)
    lift_quantum : printed lift step [m]; default detected from the decimals of the data
    base_tolerance : largest lift [m] accepted as "on the base circle" at the table ends
    path : deck prefix for error messages
    """

    form = "table"

    def __init__(self, angles: Sequence[float], lift: Sequence[float], *,
                 symmetric: bool = False, method: str = "spline", noise: float | None = None,
                 smoothing: float | None = 1.0, degree: int = 5, lift_quantum: float | None = None,
                 base_tolerance: float = 1e-6, path: str = "lift") -> None:
        base = f"{path}.{self.form}"
        a = chk.vector(angles, f"{base}.angles", min_len=5)
        y = chk.vector(lift, f"{base}.lifts", min_len=a.size, max_len=a.size)
        self._check_increasing(a, f"{base}.angles")
        if symmetric:
            a, y = self._mirror(a, y, f"{base}.angles")
        method = _ALIASES.get(method, method)
        if method not in METHODS:
            raise chk.fail(f"{base}.derivative", "is not a known derivative method", method,
                           " or ".join(METHODS))
        if degree not in (3, 5):
            raise chk.fail(f"{base}.degree", "is not a supported spline degree", degree, "3 or 5")
        tol = chk.scalar(base_tolerance, f"{base}.base_tolerance", "length", minimum=0.0)
        if a[-1] - a[0] >= TWO_PI:
            raise chk.fail(f"{base}.angles", "span one revolution or more (deg)",
                           chk.shown(a[-1] - a[0], "angle"), "a span < 360 deg")
        if y.min() < -tol:
            i = int(np.argmin(y))
            raise chk.fail(f"{base}.lifts", f"is negative at {chk.shown(a[i], 'angle')} deg",
                           chk.shown(y[i], "length"), "lift >= 0 mm",
                           "a desmodromic closing cam's lift is negated before use")
        for end, i in (("first", 0), ("last", -1)):
            if abs(y[i]) > tol:
                raise chk.fail(f"{base}.lifts", f"does not return to the base circle: the {end} "
                               f"point ({chk.shown(a[i], 'angle')} deg) is lifted",
                               chk.shown(y[i], "length"),
                               f"at most {chk.shown(tol, 'length')} mm at both ends",
                               "extend the table onto the base circle or remove a base-circle "
                               "offset")
        q = (decimal_quantum(y / MM) * MM if lift_quantum is None
             else chk.scalar(lift_quantum, f"{base}.lift_quantum", "length", minimum=0.0))
        self.lift_quantum = q
        self.sigma = q / np.sqrt(12.0) if noise is None else chk.scalar(
            noise, f"{base}.noise", "length", minimum=0.0)
        self.smoothing = 1.0 if smoothing is None else chk.scalar(
            smoothing, f"{base}.smoothing", minimum=0.0)
        self.method, self.degree = method, degree
        self.source = ""
        self.angles, self.lift = a, y
        # the event: from the last base-circle point before the lift to the first one after it
        lifted = np.flatnonzero(y > max(q / 2.0, 1e-12))
        if lifted.size == 0:
            raise chk.fail(f"{base}.lifts", "is zero everywhere", None, "a lift event")
        self._open = float(a[max(lifted[0] - 1, 0)])
        self._close = float(a[min(lifted[-1] + 1, a.size - 1)])
        # close the revolution with base-circle zeros at the table spacing
        h = float(np.median(np.diff(a)))
        pad = np.arange(a[-1] + h, a[0] + TWO_PI - 0.5 * h, h)
        self._x = np.concatenate((a, pad))
        self._y = np.concatenate((y, np.zeros(pad.size)))
        self._h = h
        if method == "spline":
            self._spline = self._fit(self._y)
            self.fit_note = self._last_fit_note
        else:
            self.fit_note = ""
            self._cd = central_differences(self._x, self._y)

    # ------------------------------------------------------------------ construction helpers
    @staticmethod
    def _check_increasing(a: np.ndarray, path: str) -> None:
        step = np.diff(a)
        bad = np.flatnonzero(step <= 0.0)
        if bad.size:
            i = int(bad[0])
            if step[i] == 0.0:
                raise chk.fail(f"{path}[{i + 1}]", "repeats the previous angle (duplicate point)",
                               chk.shown(a[i + 1], "angle"), "strictly increasing angles")
            raise chk.fail(f"{path}[{i + 1}]", "is not increasing: "
                           f"{chk.shown(a[i + 1], 'angle')} deg follows "
                           f"{chk.shown(a[i], 'angle')} deg", None, "strictly increasing angles")

    @staticmethod
    def _mirror(a: np.ndarray, y: np.ndarray, path: str) -> tuple[np.ndarray, np.ndarray]:
        if np.all(a >= 0.0):
            keep = a > 0.0
            return np.concatenate((-a[keep][::-1], a)), np.concatenate((y[keep][::-1], y))
        if np.all(a <= 0.0):
            keep = a < 0.0
            return np.concatenate((a, -a[keep][::-1])), np.concatenate((y, y[keep][::-1]))
        raise chk.fail(path, "cover both flanks but the table is marked symmetric", None,
                       "angles all >= 0 or all <= 0 for a symmetric table",
                       "set symmetric = false to use both flanks as given")

    def _fit(self, y_full: np.ndarray):
        """Periodic smoothing spline through the closed table.

        FITPACK warns when it cannot meet the residual target exactly (data with steps in
        acceleration and almost no noise); the spline it returns is then the closest it found,
        and the warning text is kept in ``fit_note`` instead of escaping as a warning.
        """
        from scipy.interpolate import make_splrep  # only table decks pay for the splines

        s = self.smoothing * self.angles.size * self.sigma ** 2
        x = np.append(self._x, self._x[0] + TWO_PI)      # periodic: last point closes the loop
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            spl = make_splrep(x, np.append(y_full, y_full[0]), k=self.degree, s=s,
                              bc_type="periodic")
        self._last_fit_note = " ".join(" ".join(str(w.message).split()) for w in caught)
        return spl

    @classmethod
    def from_table(cls, table: LiftTable, **kwargs) -> TableLift:
        kwargs.setdefault("lift_quantum", table.lift_quantum)
        law = cls(table.angles, table.lift, **kwargs)
        law.source = table.source
        return law

    @classmethod
    def dataset(cls, name: str, **kwargs) -> TableLift:
        """A shipped table: "pinto_inlet_cam" (Ball App E), "zeta_intake", "zeta_exhaust"."""
        return cls.from_table(load_dataset(name), **kwargs)

    @classmethod
    def from_csv(cls, file, **kwargs) -> TableLift:
        return cls.from_table(load_csv(file, f"{kwargs.get('path', 'lift')}.table.file"),
                              **kwargs)

    @classmethod
    def from_degrees(cls, angles_deg: Sequence[float], lift_mm: Sequence[float],
                     **kwargs) -> TableLift:
        """Angles in deg and lift in mm, as a deck or a source prints them."""
        lift_mm = np.asarray(lift_mm, dtype=float)
        kwargs.setdefault("lift_quantum", decimal_quantum(lift_mm) * MM)
        return cls(np.asarray(angles_deg, dtype=float) * DEG, lift_mm * MM, **kwargs)

    # ------------------------------------------------------------------ the law
    # The smoothing spline does not end on the base circle with zero slope and curvature: it
    # leaves residual-sized steps (~1e-5 mm, ~1e-4 mm/deg) where it would be cut to exact zeros.
    # A velocity step is a corner of the cam, which a fine enough angle grid resolves into a
    # spurious cusp. So the spline is faded to zero over five data steps outside the event,
    # where the data are base-circle zeros, with a quintic smoothstep: lift, velocity and
    # acceleration are continuous at the joints and the data inside the event are untouched.
    # (The fade adds s w'' ~ residual / length^2 to the acceleration: five steps keep that below
    # the spline's own noise on acceleration and jerk; one step would not.)
    @property
    def _fade(self) -> float:
        return 5.0 * self._h if self.method == "spline" else 0.0

    @property
    def opening_angle(self) -> float:
        return self._open - self._fade

    @property
    def closing_angle(self) -> float:
        return self._close + self._fade

    def joints(self) -> list[tuple[float, str]]:
        return [(self.opening_angle, "base circle / table"),
                (self.closing_angle, "table / base circle")]

    def _kinematics(self, theta):
        out = [np.zeros_like(theta) for _ in range(4)]
        m = theta <= self.closing_angle
        t = theta[m]
        if self.method != "spline":
            for k in range(4):
                values = self._y if k == 0 else self._cd[k - 1]
                out[k][m] = np.interp(t, self._x, values, period=TWO_PI)
            return tuple(out)
        x0 = self._x[0]                    # the spline's own period starts at the first data point
        tt = x0 + np.mod(t - x0, TWO_PI)
        s = [self._spline(tt, k) for k in range(4)]
        w = _fade_weights(t, self._open, self._close, self._fade)
        # Leibniz rule for the derivatives of the product s * w
        binomial = ((1,), (1, 1), (1, 2, 1), (1, 3, 3, 1))
        for k in range(4):
            out[k][m] = sum(c * s[k - j] * w[j] for j, c in enumerate(binomial[k]))
        return tuple(out)

    def noise_estimate(self, samples: int = 16, seed: int = 0) -> TableNoise:
        """Derivative noise caused by the data error (see ``TableNoise``).

        Central differences: sigma / (sqrt(2) h), sqrt(6) sigma / h^2, sqrt(10) sigma / (2 h^3)
        for a uniform step h (exact for independent errors). Spline: the data are perturbed
        ``samples`` times by a further uniform error of standard deviation sigma (what rounding
        leaves) and refitted; the spread of the refitted derivatives is the estimate. The
        perturbed data carry twice the noise variance the fit was tuned for, so the estimate is
        on the safe side: for a known polydyne printed to 4 decimals it is about twice the actual
        RMS error of d2 and d3 (tests/lift/test_table.py).
        """
        inside = (self.angles >= self._open) & (self.angles <= self._close)
        if self.method == "central":
            h, s = self._h, self.sigma
            return TableNoise("central", self.lift_quantum, s, 0.0, s / (np.sqrt(2.0) * h),
                              np.sqrt(6.0) * s / h**2, np.sqrt(10.0) * s / (2.0 * h**3))
        t = self.angles[inside]
        resid = float(np.sqrt(np.mean((self._spline(self.angles) - self.lift) ** 2)))
        if self.sigma == 0.0:
            return TableNoise("spline", self.lift_quantum, 0.0, resid, 0.0, 0.0, 0.0)
        rng = np.random.default_rng(seed)
        half_width = np.sqrt(3.0) * self.sigma
        runs = np.empty((samples, 3, t.size))
        n = self.angles.size
        for j in range(samples):
            y = self._y.copy()
            y[:n] += rng.uniform(-half_width, half_width, n)
            spl = self._fit(y)
            runs[j] = [spl(t, k) for k in (1, 2, 3)]
        spread = np.sqrt(np.mean(np.var(runs, axis=0, ddof=1), axis=-1))
        return TableNoise("spline", self.lift_quantum, self.sigma, resid, *map(float, spread))


def _smoothstep(u: np.ndarray) -> tuple[np.ndarray, ...]:
    """w = 10u^3 - 15u^4 + 6u^5 and its first three derivatives: 0 -> 1 with zero slope and
    curvature at both ends."""
    return (u**3 * (10.0 - 15.0 * u + 6.0 * u**2), 30.0 * u**2 * (1.0 - u) ** 2,
            60.0 * u * (1.0 - u) * (1.0 - 2.0 * u), 60.0 * (1.0 - 6.0 * u + 6.0 * u**2))


def _fade_weights(t: np.ndarray, start: float, end: float, h: float) -> list[np.ndarray]:
    """Weight w(theta) and its derivatives: 1 on [start, end], fading to 0 over h outside."""
    w = [np.ones_like(t), np.zeros_like(t), np.zeros_like(t), np.zeros_like(t)]
    for mask, u, sign in ((t < start, (t - (start - h)) / h, 1.0),
                          (t > end, ((end + h) - t) / h, -1.0)):
        if np.any(mask):
            ws = _smoothstep(np.clip(u[mask], 0.0, 1.0))
            for k in range(4):
                w[k][mask] = ws[k] * (sign / h) ** k
    return w

