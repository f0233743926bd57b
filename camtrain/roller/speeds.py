"""Surface speeds of a rotating roller in the cam contact (signs of camtrain.mechanisms.base).

Along the common tangent, positive in the direction of the cam's surface speed V_c (Ball's
convention): V_f is the speed of the contact point along the follower face relative to the
roller's carrier (the non-rotating follower's surface velocity, the chain's ``v_follower``). A
roller turning on its pin at w_r (positive in the rolling sense) moves its surface past the
contact point at

    V_roll = V_f + w_r r_r                         (carrier-relative rotation + carrier term)

so the roller rolls without sliding when w_r r_r = V_c - V_f = V_s0, the sliding speed of the
non-rotating follower. Sliding, entrainment, slip and slide-roll ratio follow (Johnson,
*Contact Mechanics*, 1985, §8.1 for the kinematics of rolling; slide-roll ratio as Li et al.,
Lubricants 11:361, 2023, SRR = 2 (u_1 - u_2)/(u_1 + u_2)):

    u_s = V_c - V_roll = V_s0 - w_r r_r,   u_e = (V_c + V_roll)/2 = V_c - u_s/2,
    slip s = u_s / V_s0 = 1 - w_r r_r / V_s0,   SRR = u_s / u_e.
"""
from __future__ import annotations

import numpy as np


def roller_surface_speed(v_follower, omega_roller, radius):
    """V_roll = V_f + w_r r_r [m/s]: the roller surface's speed past the contact point."""
    return np.asarray(v_follower, dtype=float) + np.asarray(omega_roller, dtype=float) * radius


def rolling_speed(v_cam, v_follower, radius):
    """w_r of pure rolling, (V_c - V_f) / r_r [rad/s]."""
    return (np.asarray(v_cam, dtype=float) - np.asarray(v_follower, dtype=float)) / radius


def sliding_speed(v_cam, v_follower, omega_roller, radius):
    """u_s = V_c - V_roll [m/s] (positive: the cam surface outruns the roller's)."""
    return np.asarray(v_cam, dtype=float) - roller_surface_speed(v_follower, omega_roller, radius)


def entrainment_speed(v_cam, sliding):
    """u_e = (V_c + V_roll)/2 = V_c - u_s/2 [m/s]."""
    return np.asarray(v_cam, dtype=float) - 0.5 * np.asarray(sliding, dtype=float)


def slip(sliding, v_s0):
    """s = u_s / V_s0 [-]: 0 rolling, 1 a roller that does not turn; NaN where V_s0 = 0."""
    v = np.asarray(v_s0, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(v != 0.0, np.asarray(sliding, dtype=float) / np.where(v != 0.0, v, 1.0),
                        np.nan)


def slide_roll_ratio(sliding, entrainment):
    """SRR = u_s / u_e = 2 (V_c - V_roll)/(V_c + V_roll) [-]; NaN where u_e = 0."""
    u = np.asarray(entrainment, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(u != 0.0, np.asarray(sliding, dtype=float) / np.where(u != 0.0, u, 1.0),
                        np.nan)


def periodic_next(values) -> np.ndarray:
    """The next angle's value on a periodic grid, ``np.roll(values, -1)`` by slicing."""
    v = np.asarray(values)
    out = np.empty_like(v)
    out[:-1] = v[1:]
    out[-1:] = v[:1]
    return out


def periodic_previous(values) -> np.ndarray:
    """The previous angle's value on a periodic grid, ``np.roll(values, 1)`` by slicing."""
    v = np.asarray(values)
    out = np.empty_like(v)
    out[1:] = v[:-1]
    out[:1] = v[-1:]
    return out
