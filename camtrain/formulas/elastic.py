"""Elastic constants and contact geometry: reduced modulus, reduced radius, entrainment radii.

Convention (used by every formula in this package): the *reduced modulus*

    E' = 2 / [(1 - nu1^2)/E1 + (1 - nu2^2)/E2]                                   [Pa]

as in Dowson & Higginson (1977), Hamrock & Dowson (1981), Ball (1988) nomenclature and Yang (1992)
eq. 3.20. Johnson's contact modulus E* = E'/2 is available as :func:`contact_modulus`.

Radii are signed: a concave surface has a negative radius and a flat surface ``np.inf``.
"""
from __future__ import annotations

import numpy as np

from ._util import arr, check, out, positive

__all__ = ["reduced_modulus", "contact_modulus", "reduced_radius", "curvature_sum",
           "entrainment_radii", "entrainment_speed", "sliding_speed"]


def reduced_modulus(E1, nu1, E2, nu2):
    r"""Reduced (equivalent) elastic modulus E' of two bodies in contact.

    .. math:: E' = \frac{2}{(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2}

    Args:
        E1, E2: Young's moduli [Pa].
        nu1, nu2: Poisson's ratios [-], in [0, 0.5].

    Returns:
        E' [Pa].

    Reference: Ball (1988) nomenclature ("equivalent elastic modulus"); Yang (1992) eq. 3.20;
    Hamrock & Dowson (1981). Examples: 207 GPa steel pair with nu = 0.29 gives 226.0 GPa;
    Ford Zeta cam/follower (170 GPa, 0.28 / 204 GPa, 0.29) gives 201.80 GPa.
    """
    E1, E2 = positive("E1", E1), positive("E2", E2)
    nu1 = check("nu1", nu1, lambda v: (v >= 0) & (v <= 0.5), "0 <= nu <= 0.5")
    nu2 = check("nu2", nu2, lambda v: (v >= 0) & (v <= 0.5), "0 <= nu <= 0.5")
    return out(2.0 / ((1.0 - nu1**2) / E1 + (1.0 - nu2**2) / E2))


def contact_modulus(E1, nu1, E2, nu2):
    r"""Johnson's contact modulus E* = 1/[(1-nu1^2)/E1 + (1-nu2^2)/E2] = E'/2 [Pa].

    Reference: Johnson (1985) *Contact Mechanics*, eq. 4.23 (definition).
    """
    return out(arr(reduced_modulus(E1, nu1, E2, nu2)) / 2.0)


def curvature_sum(*radii):
    r"""Sum of curvatures 1/r1 + 1/r2 + ... [1/m]; ``np.inf`` radii (flat) contribute 0.

    Radii of concave surfaces are negative. A zero radius is rejected (infinite curvature).
    """
    total = 0.0
    for i, r in enumerate(radii):
        r = check(f"r{i + 1}", r, lambda v: v != 0, "a non-zero radius (inf for a flat face)")
        total = total + 1.0 / r
    return out(total)


def reduced_radius(*radii):
    r"""Reduced radius R = 1 / (1/r1 + 1/r2 + ...) [m] of a contact in one principal plane.

    .. math:: \frac{1}{R} = \frac{1}{r_1} + \frac{1}{r_2}

    Signed radii: concave surfaces negative, flat surfaces ``np.inf``. The result is ``np.inf``
    where the curvature sum is exactly 0 (a conformal contact) and negative where the concave body
    dominates (the bodies interfere). Neither is a Hertzian contact; the Hertz and film functions
    reject such radii with a field error, so this helper only reports the geometry.

    Reference: Ball (1988) eq. 3.9 (1/R = 1/r_c + 1/r_f); Yang (1992) eq. 3.16.
    """
    k = arr(curvature_sum(*radii))
    nz = k != 0
    return out(np.where(nz, 1.0 / np.where(nz, k, 1.0), np.inf))


def entrainment_radii(Rx, Ry, angle=0.0):
    r"""Reduced radii along (R_e) and across (R_s) an entrainment direction at ``angle`` to x.

    For a contact with principal reduced radii R_x, R_y and the entraining velocity at angle
    theta to the x axis (Euler's theorem for the normal curvature):

    .. math:: \frac{1}{R_e} = \frac{\cos^2\theta}{R_x} + \frac{\sin^2\theta}{R_y},\qquad
              \frac{1}{R_s} = \frac{\sin^2\theta}{R_x} + \frac{\cos^2\theta}{R_y}

    Args:
        Rx, Ry: principal reduced radii [m] (positive; ``np.inf`` allowed for one of them).
        angle: angle between entrainment and the x axis [rad].

    Returns:
        (R_e, R_s) [m], the radii used by Chittenden et al. (1985).
    """
    Rx = check("Rx", Rx, lambda v: v > 0, "a radius > 0 (inf allowed)")
    Ry = check("Ry", Ry, lambda v: v > 0, "a radius > 0 (inf allowed)")
    c2, s2 = np.cos(arr(angle)) ** 2, np.sin(arr(angle)) ** 2
    ke = c2 / Rx + s2 / Ry
    ks = s2 / Rx + c2 / Ry
    with np.errstate(divide="ignore"):  # a zero curvature means an infinite radius, on purpose
        return out(1.0 / ke), out(1.0 / ks)


def entrainment_speed(v1, v2, convention: str = "mean"):
    r"""Entrainment (rolling) speed of two surfaces moving at v1, v2 through the contact [m/s].

    ``convention="mean"`` (default, the standard EHL definition used by every film formula
    here): u = (v1 + v2)/2. ``convention="sum"``: u = v1 + v2, the quantity Ball (1988, Ch. 3
    and 5) and Yang (1992, §3.2.1 text) call "the entraining velocity"; passing it to a film
    formula reproduces Ball's printed power losses more closely (see docs/formulas.md).

    Signed; film formulas take its magnitude.
    """
    v1, v2 = arr(v1), arr(v2)
    if convention == "mean":
        return out(0.5 * (v1 + v2))
    if convention == "sum":
        return out(v1 + v2)
    raise ValueError(f"convention must be 'mean' or 'sum', got {convention!r}")


def sliding_speed(v1, v2):
    """Sliding speed v1 - v2 [m/s] (Ball 1988 V_s = V_c - V_f; Yang 1992 eq. 3.5). Signed."""
    return out(arr(v1) - arr(v2))
