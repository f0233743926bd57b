"""Even power-series lift laws: general polynomial and polydyne (Teodorescu et al. 2005).

The lift over the main event ``|theta| <= half_period`` is a sum of powers of
``x = |theta| / half_period``; constant-velocity ramps (``ramps.py``) may sit outside it. Ball's
four-power polynomial (``four_power.py``) is the same machinery with his parametrisation.
"""
from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from camtrain.lift import _checks as chk
from camtrain.lift.base import TWO_PI, LiftLaw
from camtrain.lift.ramps import Ramps, ramp_kinematics


def polydyne_coefficients(exponents: Sequence[float]) -> np.ndarray:
    """Polydyne coefficients C_i = prod_{j!=i} r_j / prod_{j!=i} (r_j - r_i).

    Teodorescu, Kushwaha, Rahnejat & Taraza (2005) eq. 18 (after Chen). With these, the law
    ``rise * (1 - sum C_i x^r_i)`` reaches zero at x = 1 with its first k-1 derivatives zero
    (k = number of exponents): the Vandermonde conditions sum C_i = 1, sum C_i r_i^n = 0.
    Exponents must be distinct (checked by the caller).
    """
    r = np.asarray(exponents, dtype=float)
    out = np.empty_like(r)
    for i in range(r.size):
        others = np.delete(r, i)
        out[i] = np.prod(others) / np.prod(others - r[i])
    return out


def power_series(x: np.ndarray, exps: np.ndarray, coefs: np.ndarray
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """sum c |x|^r and its first three derivatives with respect to the signed x.

    Exponents are 2 or >= 3 (validated), so every power below is of a non-negative exponent and
    finite at x = 0; the jerk term of r = 2 is identically zero and skipped.
    """
    ax, sg = np.abs(x), np.sign(x)
    s0, s1, s2, s3 = (np.zeros_like(ax) for _ in range(4))
    with np.errstate(under="ignore"):        # x^80 near the nose underflows to its true value, 0
        for r, c in zip(exps, coefs, strict=True):
            # one fractional power per term, the others by multiplication (4x fewer pow calls)
            p2 = ax ** (r - 2.0)
            p1 = p2 * ax
            s0 += c * (p1 * ax)
            s1 += c * r * p1
            s2 += c * r * (r - 1.0) * p2
            if r >= 3.0:
                s3 += c * r * (r - 1.0) * (r - 2.0) * ax ** (r - 3.0)
    return s0, sg * s1, s2, sg * s3


class EvenSeriesLaw(LiftLaw):
    """lift = peak + sum K_i |theta/half_period|^r_i on |theta| <= half_period, ramps outside.

    Shared core of ``PolynomialLift`` and ``FourPowerLift``; subclasses compute ``peak`` and the
    series coefficients ``K`` [m] from their own parameters.
    """

    def _setup(self, half_period: float, peak: float, exps: np.ndarray, series: np.ndarray,
               ramps: Ramps, path: str) -> None:
        self.half_period = half_period
        self.peak = peak
        self.exponents = exps
        self.series = series
        self.ramps = ramps
        span = 2.0 * half_period + ramps.opening_length + ramps.closing_length
        if span >= TWO_PI:
            raise chk.fail(f"{path}.{self.form}.half_period",
                           "makes the event longer than one cam revolution (deg)",
                           chk.shown(half_period, "angle"),
                           "2 x half_period + ramp lengths < 360 deg")
        # a series that overshoots the nose or dips below the ramp is not a usable lift event
        x = np.linspace(-1.0, 1.0, 4001)
        lift = peak + power_series(x, exps, series)[0]
        floor = min(ramps.opening_height, ramps.closing_height)
        if lift.max() > peak + 1e-9 or lift.min() < floor - 1e-6:
            raise chk.fail(f"{path}.{self.form}.exponents",
                           "give a lift outside the range from the ramp height to the nose",
                           [float(e) for e in exps],
                           f"lift between {chk.shown(floor, 'length')} and "
                           f"{chk.shown(peak, 'length')} mm",
                           f"the series reaches {chk.shown(lift.min(), 'length')} to "
                           f"{chk.shown(lift.max(), 'length')} mm")

    @property
    def opening_angle(self) -> float:
        return -self.half_period - self.ramps.opening_length

    @property
    def closing_angle(self) -> float:
        return self.half_period + self.ramps.closing_length

    @property
    def max_lift(self) -> float:
        return self.peak

    def joints(self) -> list[tuple[float, str]]:
        out = []
        if self.ramps.opening_length > 0.0:
            out += [(self.opening_angle, "opening ramp start")]
        out += [(-self.half_period, "opening ramp / polynomial"), (0.0, "nose"),
                (self.half_period, "polynomial / closing ramp")]
        if self.ramps.closing_length > 0.0:
            out += [(self.closing_angle, "closing ramp end")]
        return out

    def _kinematics(self, theta):
        out = [np.zeros_like(theta) for _ in range(4)]
        tp = self.half_period
        core = np.abs(theta) <= tp
        s = power_series(theta[core] / tp, self.exponents, self.series)
        for k in range(4):
            out[k][core] = (self.peak if k == 0 else 0.0) + s[k] / tp ** k
        r = self.ramps
        for mask, start, length, height, rising in (
                ((theta >= self.opening_angle) & (theta < -tp), self.opening_angle,
                 r.opening_length, r.opening_height, True),
                ((theta > tp) & (theta <= self.closing_angle), tp, r.closing_length,
                 r.closing_height, False)):
            if np.any(mask):
                out[0][mask], out[1][mask] = ramp_kinematics(theta[mask], start, length,
                                                             height, rising)
        return tuple(out)


class PolynomialLift(EvenSeriesLaw):
    """General even polynomial / polydyne lift (Teodorescu et al. 2005 eqs. 18-19, corrected sign).

    lift = ramp_height + rise * (1 - sum C_i |theta/half_period|^r_i)   for |theta| <= half_period

    The paper prints ``1 + sum``, which gives a minimum at the nose and twice the lift at the
    event ends; the minus sign is the standard polydyne and is what is implemented.

    Parameters (SI)
    ---------------
    half_period : cam angle from the nose to the end of the polynomial [rad]
    rise : lift of the polynomial above the ramp height [m] (the paper's x0 when there are no ramps)
    exponents : distinct exponents r_i, each 2 or >= 3 (Teodorescu: 2, 8, 14, 20, 26)
    coefficients : C_i; default the polydyne set of ``polydyne_coefficients``. Given ones must sum
        to 1 so the lift returns to the ramp height.
    ramps : optional constant-velocity ramps (both at the same height: the series is even)
    path : deck prefix for error messages
    """

    form = "polynomial"

    def __init__(self, half_period: float, rise: float, exponents: Sequence[float],
                 coefficients: Sequence[float] | None = None, ramps: Ramps | None = None, *,
                 path: str = "lift") -> None:
        base = f"{path}.{self.form}"
        tp = chk.scalar(half_period, f"{base}.half_period", "angle", minimum=0.0, strict=True)
        x0 = chk.scalar(rise, f"{base}.max_lift", "length", minimum=0.0, strict=True)
        exps = chk.exponents(exponents, f"{base}.exponents")
        if coefficients is None:
            coefs = polydyne_coefficients(exps)
        else:
            coefs = chk.vector(coefficients, f"{base}.coefficients", min_len=exps.size,
                               max_len=exps.size)
            if abs(coefs.sum() - 1.0) > 1e-9:
                raise chk.fail(f"{base}.coefficients",
                               "do not bring the lift back to the ramp height",
                               float(coefs.sum()), "coefficients summing to 1",
                               f"the lift at the end of the polynomial is "
                               f"{chk.shown(x0 * (1.0 - coefs.sum()), 'length')} mm above the ramp")
        ramps = (ramps or Ramps()).resolved(path)
        if abs(ramps.opening_height - ramps.closing_height) > 1e-9:
            raise chk.fail(f"{path}.ramps.closing_height",
                           "differs from the opening ramp height (mm)",
                           chk.shown(ramps.closing_height, "length"),
                           f"{chk.shown(ramps.opening_height, 'length')} mm",
                           "an even polynomial meets both ramps at the same lift")
        self.rise = x0
        self.coefficients = coefs
        self._setup(tp, ramps.opening_height + x0, exps, -x0 * coefs, ramps, path)
