"""Camshaft torque: each lobe's torque over a camshaft revolution, phased and summed.

Williams (2013) ch 9 and App 7: a single-valve torque curve with the valve fully open at the
reference angle is shifted (circularly) to its timing, to every cylinder of the bank (one firing
interval apart in camshaft degrees) and, for a V engine, the second bank is the first one
advanced by half the V angle (V in crank degrees, so V/2 camshaft degrees):
TqBank2(theta) = TqBank1(theta + V/2). All angles here are camshaft radians on a uniform grid
over one revolution; torque curves are arrays on that grid [N m].
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.errors import field_error

__all__ = ["cam_grid", "shift_curve", "camshaft_torque", "bank_torque", "second_bank",
           "drive_power"]

TWO_PI = 2.0 * math.pi


def cam_grid(n: int) -> np.ndarray:
    """Uniform grid of ``n`` camshaft angles over one revolution, 0 <= theta < 2 pi [rad]."""
    if int(n) < 4:
        raise field_error("samples", "need at least 4 samples per revolution", n)
    return np.arange(int(n)) * (TWO_PI / int(n))


def _curve(name, y, n=None) -> np.ndarray:
    y = np.asarray(y, dtype=float)
    if y.ndim != 1 or y.size < 4 or (n is not None and y.size != n):
        raise field_error(name, "must be a 1-D array on the uniform camshaft grid",
                          getattr(y, "shape", None), f"{n or '>= 4'} samples")
    if not np.all(np.isfinite(y)):
        raise field_error(name, "must be finite")
    return y


def shift_curve(y, delay: float) -> np.ndarray:
    """Curve delayed by ``delay`` camshaft radians: out(theta) = y(theta - delay).

    A feature at theta0 moves to theta0 + delay. Whole grid steps are exact rolls (Williams' App 7
    shifts by whole steps); other delays interpolate linearly and periodically.
    """
    y = _curve("torque", y)
    n = y.size
    steps = delay * n / TWO_PI
    k = round(steps)
    if abs(steps - k) < 1e-9:
        return np.roll(y, k)
    th = cam_grid(n)
    return np.interp(th - delay, th, y, period=TWO_PI)


def camshaft_torque(lobe_torques, lobe_angles) -> np.ndarray:
    """Summed camshaft torque [N m] from lobes sharing one reference curve convention.

    Args:
        lobe_torques: sequence of torque curves, each with its lobe's maximum lift at theta = 0
            (or one curve used for every lobe).
        lobe_angles: camshaft angle of each lobe's maximum lift [rad] (Yang 1992 Appendix C.5
            "angle to maximum lift"; Ball 1988 §6.3 phases from timing and firing order).
    """
    angles = np.atleast_1d(np.asarray(lobe_angles, dtype=float))
    curves = np.asarray(lobe_torques, dtype=float)
    if curves.ndim == 1:
        curves = np.broadcast_to(curves, (angles.size, curves.size))
    if curves.shape[0] != angles.size:
        raise field_error("lobe_angles", "one angle per lobe torque curve", angles.size,
                          f"{curves.shape[0]} angles")
    return np.sum([shift_curve(c, a) for c, a in zip(curves, angles, strict=True)], axis=0)


def bank_torque(inlet, exhaust, cylinders: int, inlet_peak_atdc: float,
                exhaust_peak_btdc: float, valves_per_cylinder: int = 2,
                firing_interval: float | None = None) -> dict:
    """Torque of one bank's inlet and exhaust camshafts (Williams 2013 App 7, steps 1-3).

    Args:
        inlet, exhaust: single-valve torque curves [N m] with the valve fully open at theta = 0
            (that is at cylinder 1 TDC); either may be None.
        cylinders: cylinders in the bank (they fire one ``firing_interval`` apart).
        inlet_peak_atdc: inlet fully open after TDC [crank rad] -> delay of half that.
        exhaust_peak_btdc: exhaust fully open before TDC [crank rad] -> advance of half that.
        valves_per_cylinder: valves of each kind per cylinder driven by the camshaft.
        firing_interval: camshaft angle between successive firings [rad]; 2 pi / cylinders by
            default (a 4-cylinder bank fires every 90 camshaft degrees).

    Returns:
        dict with "inlet", "exhaust" and "bank" torque curves [N m].
    """
    if int(cylinders) < 1:
        raise field_error("cylinders", "must be >= 1", cylinders)
    step = TWO_PI / cylinders if firing_interval is None else float(firing_interval)
    out = {}
    for key, curve, delay in (("inlet", inlet, 0.5 * inlet_peak_atdc),
                              ("exhaust", exhaust, -0.5 * exhaust_peak_btdc)):
        if curve is None:
            out[key] = None
            continue
        timed = shift_curve(curve, delay)
        out[key] = valves_per_cylinder * np.sum(
            [shift_curve(timed, p * step) for p in range(int(cylinders))], axis=0)
    parts = [v for v in out.values() if v is not None]
    if not parts:
        raise field_error("inlet", "need an inlet or an exhaust torque curve")
    out["bank"] = np.sum(parts, axis=0)
    return out


def second_bank(bank1, v_angle: float) -> np.ndarray:
    """Second bank of a V engine: TqBank2(theta) = TqBank1(theta + V/2) (Williams App 7 step 4).

    ``v_angle`` is the V angle in crank radians (so the camshafts are V/2 apart).
    """
    return shift_curve(bank1, -0.5 * v_angle)


def drive_power(torque, omega: float):
    """Instantaneous drive power T omega [W] and its cycle mean (Ball 1988 §4.2.3.5)."""
    p = _curve("torque", torque) * float(omega)
    return p, float(np.mean(p))
