"""Roller followers: the follower face is a roller whose centre follows the cam's offset curve.

A roller of radius r_r touching the cam is, for the kinematics of the cam contact, a curved
follower face of radius r_r centred on the roller axis: the roller centre is the face's centre
of curvature Q, which keeps the distance r_r from the cam profile along its normal (the roller
centre moves on the offset, or pitch, curve of the profile; Norton, Cam Design and
Manufacturing Handbook, 2nd ed. 2009, ch. 7; Dyson 1980 for the pivoted form). So every
follower family camtrain has with a curved face carries a roller exactly:

* roller tappet or push-rod roller lifter: the translating cylindrical follower
  (:func:`camtrain.mechanisms.translating.domed` with a cylindrical face);
* roller finger follower (end pivot on a lash adjuster, roller between the pivot and the valve
  pad) and centre-pivot roller rocker: Dyson's pivoted follower with the face centre Q at the
  roller centre (:func:`camtrain.mechanisms.pivoted.pivoted`), A = pivot to roller centre.

What the roller changes is its rotation, which is not part of the kinematics: the Kinematics of
a roller is that of the non-rotating roller (``v_follower`` is the surface speed of the roller
material point held against rotation, i.e. of the follower body at the contact), and an effect
that knows the roller's angular speed adds the roller's own surface speed to it. The contact is
a line contact (``radius_y`` inf), or elliptical for a crowned roller (``radius_y`` = crown
radius: the cam is straight across its width, the crown gives the transverse curvature).
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from camtrain.errors import field_error
from camtrain.mechanisms.base import Kinematics

ROLLER = "roller"


def roller(k: Kinematics, *, crown_radius: float | None = None) -> Kinematics:
    """The Kinematics of curved follower ``k`` declared a roller: the mechanism named as one,
    and a crowned roller's transverse radius R_y = ``crown_radius`` [m] (None: straight roller,
    line contact). ``k`` must already be a cylindrical face (``radius_y`` inf)."""
    if not np.all(np.isinf(k.radius_y)):
        raise ValueError("a roller is built on a cylindrical face (line contact)")
    changes: dict[str, object] = {"mechanism": f"{ROLLER} {k.mechanism}"}
    if crown_radius is not None:
        if not (np.isfinite(crown_radius) and crown_radius > 0.0):
            raise field_error("mechanism.roller.crown_radius", "must be a positive length",
                              crown_radius, "> 0 m")
        changes["radius_y"] = np.full(np.shape(k.theta), float(crown_radius))
    return replace(k, **changes)

