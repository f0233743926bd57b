"""Ball's four-power polynomial with constant-velocity ramps (Ball 1988 §2.2.3, §5.2).

    l = Y_R + l_cmax + C_p x^p + C_q x^q + C_r x^r + C_s x^s,   x = |phi| / phi_T <= 1

with ramps from the base circle to Y_R outside +-phi_T. The lift meets the ramp height at the
event ends only if sum C = -l_cmax, which is checked. Ball's template also asks for separate
opening and closing ramps; because the polynomial is even it meets both at the same lift, so the
two heights must agree (the lengths, and so the ramp slopes, may differ).
"""
from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from camtrain.lift import _checks as chk
from camtrain.lift.base import DEG, MM
from camtrain.lift.polynomial import EvenSeriesLaw
from camtrain.lift.ramps import Ramps

# Harrison's flat-follower cam, Ball (1988) §5.2 and template Fig 4.5f (full-precision C's)
HARRISON = {
    "half_period": 60.0 * DEG,
    "rise": 8.90 * MM,
    "exponents": (2.0, 9.0, 78.0, 80.0),
    "coefficients": tuple(c * MM for c in (-11.6918407, 2.8498942, -0.5894568, 0.5314033)),
    "ramps": Ramps(0.50 * MM, 25.0 * DEG, 0.50 * MM, 25.0 * DEG),
}


class FourPowerLift(EvenSeriesLaw):
    """Four-power polynomial lift, Ball (1988) §2.2.3 (equation in the text, unnumbered).

    Parameters (SI)
    ---------------
    half_period : phi_T, cam angle from the nose to the end of the polynomial [rad]
    rise : l_cmax, Ball's "maximum lift" field, the rise above the ramp height [m];
        the peak lift is ramp height + rise
    exponents : p, q, r, s (four distinct values, each 2 or >= 3)
    coefficients : C_p, C_q, C_r, C_s [m]; must sum to -rise within ``tolerance``
    ramps : constant-velocity opening and closing ramps (equal heights)
    tolerance : allowed |sum C + rise| [m]; default 1 um, which accepts coefficients rounded to
        five significant figures as printed in Ball's template
    path : deck prefix for error messages
    """

    form = "four_power"

    def __init__(self, half_period: float, rise: float, exponents: Sequence[float],
                 coefficients: Sequence[float], ramps: Ramps | None = None, *,
                 tolerance: float = 1e-6, path: str = "lift") -> None:
        base = f"{path}.{self.form}"
        tp = chk.scalar(half_period, f"{base}.half_period", "angle", minimum=0.0, strict=True)
        lc = chk.scalar(rise, f"{base}.max_lift", "length", minimum=0.0, strict=True)
        exps = chk.exponents(exponents, f"{base}.exponents", count=4)
        coefs = chk.vector(coefficients, f"{base}.coefficients", min_len=4, max_len=4,
                           kind="length")
        ramps = (ramps or Ramps()).resolved(path)
        if abs(ramps.opening_height - ramps.closing_height) > 1e-9:
            raise chk.fail(f"{path}.ramps.closing_height",
                           "differs from the opening ramp height (mm)",
                           chk.shown(ramps.closing_height, "length"),
                           f"{chk.shown(ramps.opening_height, 'length')} mm",
                           "the four-power polynomial is even and meets both ramps at the same "
                           "lift; use the multipol or williams_low_jerk form for unequal ramps")
        miss = coefs.sum() + lc
        if abs(miss) > tolerance:
            raise chk.fail(f"{base}.coefficients",
                           "do not bring the lift down to the ramp height at the end of the "
                           "half period", [chk.shown(c, "length") for c in coefs],
                           f"coefficients summing to -rise = {chk.shown(-lc, 'length')} mm",
                           f"they sum to {chk.shown(coefs.sum(), 'length')} mm, leaving a "
                           f"{chk.shown(miss, 'length')} mm step at the ramp")
        self.rise = lc
        self.coefficients = coefs
        self._setup(tp, ramps.opening_height + lc, exps, coefs, ramps, path)

    @classmethod
    def harrison(cls, **overrides) -> FourPowerLift:
        """Harrison's datum cam (Ball 1988 §5.2): p, q, r, s = 2, 9, 78, 80; peak 9.40 mm."""
        return cls(**{**HARRISON, **overrides})

    def end_conditions(self) -> dict[str, float]:
        """Lift, velocity, acceleration at the closing end of the polynomial (x = 1), SI.

        Ball's data are built so that the lift equals the ramp height, the velocity equals the
        ramp slope and the acceleration is zero there (Ball 1988 §5.2; derived from his
        coefficients: sum C = -l_cmax, sum n C_n = -phi_T * slope, sum n(n-1) C_n ~ 0).
        """
        n, c, tp = self.exponents, self.coefficients, self.half_period
        return {"lift": float(self.peak + c.sum()),
                "d1": float(np.sum(n * c) / tp),
                "d2": float(np.sum(n * (n - 1.0) * c) / tp**2),
                "d3": float(np.sum(n * (n - 1.0) * (n - 2.0) * c) / tp**3)}
