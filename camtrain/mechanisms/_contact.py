"""Load and torque arms from the contact geometry (derived vector forms, common to all followers).

Everything is in the cam frame of a clockwise-turning cam, where the follower train advances
counterclockwise around the cam. The unit tangent ``t`` (counterclockwise along the cam) is the
direction of positive V_c; the unit normal ``n`` points from the cam into the follower.

Relative to the follower, cam material at the contact moves with velocity -V_s * t (V_s = V_c -
V_f), so friction on the follower acts along -sign(V_s) * t and on the cam along +sign(V_s) * t.
"""
from __future__ import annotations

import numpy as np

from camtrain.mechanisms.base import cross


def contact_arms(px, py, nx, ny, dispx, dispy, mx, my, sliding):
    """Virtual-work arms, camshaft torque arms and pressure angle at the contact.

    Parameters
    ----------
    px, py : contact point (cam frame) [m]
    nx, ny : unit normal, cam -> follower
    dispx, dispy : displacement of the follower material point at the contact per unit increase of
        the follower coordinate q (virtual displacement) [m per unit q]
    mx, my : unit direction of motion of the follower pad centre for increasing lift
    sliding : V_s = V_c - V_f (only its sign is used)

    Returns a dict with ``arm_normal`` = n . dP/dq, ``arm_friction`` = -sign(V_s) t . dP/dq,
    ``torque_arm_normal`` = -(P x n)_z and ``friction_arm`` = sign(V_s) (P x t)_z (both positive
    when resisting the clockwise cam), and ``pressure_angle`` (positive when n leans the way the
    cam surface moves, i.e. clockwise from m).
    """
    tx, ty = -ny, nx
    s = np.sign(sliding)
    if mx is nx and my is ny:   # the face moves along its own normal (flat face): no angle
        pressure_angle = np.zeros(np.shape(nx))
    else:
        pressure_angle = np.arctan2(-cross(mx, my, nx, ny), mx * nx + my * ny)
    return {
        "arm_normal": nx * dispx + ny * dispy,
        "arm_friction": -s * (tx * dispx + ty * dispy),
        "torque_arm_normal": -cross(px, py, nx, ny),
        "friction_arm": s * cross(px, py, tx, ty),
        "pressure_angle": pressure_angle,
    }
