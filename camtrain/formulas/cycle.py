"""Torque about the camshaft axis, friction power, and cycle means over a periodic angle grid.

Cycle means. For a smooth periodic integrand sampled at N equally spaced angles over one
period, the trapezoidal rule (here simply the arithmetic mean of the samples, since the end
points coincide) is *spectrally* accurate: its error falls faster than any power of 1/N
(geometrically for analytic integrands), because it integrates every Fourier harmonic below
order N exactly. Simpson's rule, which Ball (1988) used, is only fourth order on such data and
gains nothing; it is offered to reproduce his numbers. Integrands with kinks (the friction cap
switching on and off, contact starting at the ramps) limit either rule to low order; there the
only remedy is a finer grid.
"""
from __future__ import annotations

import numpy as np

from ._util import arr, out

__all__ = ["friction_torque", "cam_torque", "friction_power", "cycle_mean"]


def friction_torque(F, r):
    r"""Torque of the contact friction force about the cam axis, T_f = F r [N m].

    Args:
        F: friction force [N]; r: perpendicular distance from the cam axis to the line of the
            friction force [m] (flat or domed direct-acting follower: r = r_B + l).

    Reference: Ball (1988) eq. 4.8 (H = F r omega); Yang (1992) eq. 3.25 (r_f = R_b + L_c).
    """
    return out(arr(F) * arr(r))


def cam_torque(W, e, F, r):
    r"""Total cam driving torque: normal-load torque plus friction torque [N m].

    .. math:: T = W e + F r

    Args:
        W: normal contact load [N] (or the axial component F_v when the load is resolved, as
            Yang does); e: offset of its line of action from the cam axis [m] (flat follower:
            e = dl/dtheta, the contact eccentricity); F: friction force [N]; r: its arm [m].

    Sign: positive means the camshaft must supply work (opening side). Reference: Ball (1988)
    §4.2.3.5 "Total Torque"; Yang (1992) §4.2.1 (form not printed, T = F_v dL/dtheta + F r_f).
    """
    return out(arr(W) * arr(e) + arr(F) * arr(r))


def friction_power(F, r, omega):
    r"""Instantaneous friction power referred to the cam axis, H = F r omega [W].

    Equals the true dissipation F |V_s| only for the flat-faced follower (Ball extraction §2.7).
    Reference: Ball (1988) eq. 4.8; Yang (1992) eq. 3.25 integrand.
    """
    return out(arr(F) * arr(r) * np.abs(arr(omega)))


def cycle_mean(values, axis: int = -1, method: str = "trapezoid", closed: bool = False):
    r"""Mean of a quantity over one period, e.g. H-bar = (1/2pi) \int_0^{2pi} F r omega dphi.

    Args:
        values: samples on a uniform grid over one full period along ``axis``.
        closed: False (default) if the grid excludes the end point (phi_k = 2 pi k / N);
            True if the last sample repeats the first (phi_N = 2 pi).
        method: ``"trapezoid"`` (default; spectrally accurate for smooth periodic data) or
            ``"simpson"`` (Ball 1988 eq. 4.9; needs an even number of intervals).

    Returns:
        the mean (float or array).
    """
    v = arr(values)
    if v.ndim == 1 and method == "trapezoid" and not closed and axis in (0, -1):
        if v.size < 2:   # the plain mean of one periodic curve (the chain's case), as below
            raise ValueError("need at least two samples per period")
        return float(np.add.reduce(v) / v.size)
    v = np.moveaxis(v, axis, -1)
    if v.shape[-1] < 2:
        raise ValueError("need at least two samples per period")
    if method == "trapezoid":
        body = v[..., :-1] if closed else v
        return out(body.mean(axis=-1))
    if method == "simpson":
        ring = v if closed else np.concatenate([v, v[..., :1]], axis=-1)
        n = ring.shape[-1] - 1
        if n % 2:
            raise ValueError(f"Simpson's rule needs an even number of intervals, got {n}")
        from scipy.integrate import simpson

        return out(simpson(ring, dx=1.0 / n, axis=-1))
    raise ValueError("method must be 'trapezoid' or 'simpson'")
