"""Follower/guide and valve/guide friction (Yang 1992, §3.3.2).

Two models: a boundary model of a follower tilted in its bore by the lateral force at the cam
contact (static balance, eqs. 3.26-3.28), and a full-film Couette model of a concentric
oil-filled clearance (eq. 3.29), used for both the follower bore and the valve stem.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ._util import arr, non_negative, out, positive

__all__ = ["GuideBoundary", "yang_1992_guide_boundary", "couette_guide_friction",
           "couette_guide_power"]


class GuideBoundary(NamedTuple):
    friction_1: object  #: F_f1, friction at the first guide contact point [N]
    friction_2: object  #: F_f2, friction at the second guide contact point [N]
    axial_reaction: object  #: F_z, axial reaction from the valve / lash adjuster [N]


def yang_1992_guide_boundary(F_v, F_c, e, d, H_f, mu=0.08) -> GuideBoundary:
    r"""Boundary friction of a follower tilted in its guide, Yang (1992) eqs. 3.26-3.28.

    .. math::
        F_z = \frac{F_v - \mu(1 + \mu d/H_f)F_c}{1 + 2\mu e/H_f},\quad
        F_{f1} = \tfrac12(F_v - F_z - \mu F_c),\quad
        F_{f2} = \tfrac12(F_v - F_z + \mu F_c)

    so that F_f1 + F_f2 = F_v - F_z (total guide friction) and F_f2 - F_f1 = mu F_c.

    Args:
        F_v: vertical (axial) force from the cam on the follower [N].
        F_c: horizontal force tilting the follower [N] (horizontal part of the cam/follower
            friction plus the dome force F_d).
        e: lateral offset of the cam contact from the follower axis [m] (~ dL/dtheta).
        d: follower diameter [m]; H_f: follower height [m]; mu: guide friction coefficient
            (0.08 in Yang).

    Returns:
        :class:`GuideBoundary`. The symbol meanings are Yang's figure 3.7 as read in the
        extraction (they are not defined in the text).
    """
    F_v, F_c, e = arr(F_v), arr(F_c), arr(e)
    d, H_f, mu = positive("d", d), positive("H_f", H_f), non_negative("mu", mu)
    Fz = (F_v - mu * (1.0 + mu * d / H_f) * F_c) / (1.0 + 2.0 * mu * e / H_f)
    return GuideBoundary(out(0.5 * (F_v - Fz - mu * F_c)), out(0.5 * (F_v - Fz + mu * F_c)),
                         out(Fz))


def couette_guide_friction(V, eta, d, L, c):
    r"""Full-film Couette friction of a concentric rod in a guide, Yang (1992) eq. 3.29.

    .. math:: F = \frac{\eta V}{c}\,\pi d L

    Args:
        V: axial sliding velocity [m/s] (signed; the force has the same sign, i.e. it is the
            force the film exerts against the motion, in magnitude).
        eta: viscosity [Pa s]; d: rod (follower or valve stem) diameter [m];
        L: guide (engaged) length [m]; c: radial clearance [m].

    Returns:
        F [N]. Reference: Yang (1992) eq. 3.29 (Petroff-type shear, no tilt, no pressure flow).
    """
    k = positive("eta", eta) * np.pi * positive("d", d) * positive("L", L) / positive("c", c)
    return out(k * arr(V))


def couette_guide_power(V, eta, d, L, c):
    """Instantaneous dissipation F V = (eta pi d L / c) V^2 [W] of :func:`couette_guide_friction`.

    Average over the cam cycle with :func:`camtrain.formulas.cycle.cycle_mean`. Check (Yang 1992
    Zeta intake, 1500 rpm cam, eta = 0.009865 Pa s): 0.606 W per follower, 0.253 W per valve
    (Yang extraction §4.6, derived; seed totals 4.9 W and 2.0 W for 8).
    """
    return out(arr(couette_guide_friction(V, eta, d, L, c)) * arr(V))
