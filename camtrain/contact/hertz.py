"""Hertz contact of one cam/follower pair: half-width and maximum pressure from the load.

Line contact (flat and pivoted followers, cylindrical pads; radius_y = inf): Ball (1988) eqs.
3.8-3.10 over the cam width. Point contact (spherical domed follower): exact Hertz ellipse
(Hamrock & Dowson 1981 ch. 3) or Ball's eq. 3.7 (``tribology.hertz = "ball_1988"``).
Angles without load give zero size and pressure; angles where the contact is not Hertzian
(equivalent radius <= 0 or infinite) give NaN.
"""
from __future__ import annotations

import numpy as np

from camtrain.contact._points import at
from camtrain.contact.products import HertzField
from camtrain.formulas import hertz_line, hertz_point, hertz_point_max_pressure
from camtrain.formulas.hertz import ellipticity_exact
from camtrain.identity_cache import by_identity


def is_line(kin) -> bool:
    """A line contact: no finite transverse radius anywhere (known once per Kinematics)."""
    line = getattr(kin, "line_contact", None)
    return bool(np.isinf(kin.radius_y).all()) if line is None else line


@by_identity
def major_ellipticity(kin) -> np.ndarray:
    """Exact Hertz ellipticity k = a_major/a_minor >= 1 at every angle with a Hertzian point
    geometry (NaN elsewhere). It depends on the radii only, not on the load, so it is solved once
    per Kinematics (the load iteration and the Hertz effect share it)."""
    R, Ry = kin.radius_x, kin.radius_y
    good = (R > 0.0) & np.isfinite(R) & (Ry > 0.0) & np.isfinite(Ry)
    k = np.full(R.shape, np.nan)
    if np.any(good):
        # the bisection is per element: solve each distinct radius pair once (a base circle or
        # a constant-radius flank repeats one pair over many angles)
        pairs, where = np.unique(np.stack((np.minimum(R[good], Ry[good]),
                                           np.maximum(R[good], Ry[good]))), axis=1,
                                 return_inverse=True)
        k[good] = np.asarray(ellipticity_exact(pairs[0], pairs[1]))[where.reshape(-1)]
    k.flags.writeable = False
    return k


def hertz_field(contact, kin, load) -> HertzField:
    """Per-angle Hertz field of one pair (a :class:`camtrain.contact.model.CamContact`) under a
    per-angle load [N]."""
    load = np.asarray(load, dtype=float)
    E_r = contact.reduced_modulus
    width = contact.width
    R, Ry = kin.radius_x, kin.radius_y
    line = is_line(kin)
    good_r = (R > 0.0) & np.isfinite(R)
    if not line:
        good_r &= (Ry > 0.0) & np.isfinite(Ry)
    loaded = load > 0.0
    use = good_r & loaded
    pmax, bx, by = np.zeros(load.shape), np.zeros(load.shape), np.zeros(load.shape)
    if np.count_nonzero(use):
        if line:
            h = hertz_line(load[use], R[use], at(E_r, use), L=at(width, use))
            pmax[use], bx[use] = h.max_pressure, h.half_width
            by[use] = 0.5 * at(width, use)
        else:
            h = hertz_point(load[use], R[use], Ry[use], at(E_r, use),
                            ellipticity=major_ellipticity(kin)[use])
            bx[use], by[use], pmax[use] = h.a_x, h.a_y, h.max_pressure
            if contact.tribology.hertz == "ball_1988":
                pmax[use] = hertz_point_max_pressure(load[use], R[use], Ry[use], at(E_r, use),
                                                     method="ball_1988")
    bad = ~good_r & loaded
    if np.count_nonzero(bad):
        pmax[bad] = bx[bad] = by[bad] = np.nan
    return HertzField(pmax=pmax, half_width=bx, half_length=by, bad=bad, line=line)
