"""EHL film thickness of point (elliptical) contacts, e.g. a tapered cam on a domed follower.

Common symbols (SI): W load [N]; R_x reduced radius along the entraining direction [m]; R_y
across it [m]; u mean entrainment speed [m/s] (|u| enters; see :mod:`.film_line` for the
mean/sum convention); eta0 [Pa s]; alpha [1/Pa]; E_r = E' [Pa]. Dimensionless:
U = eta0 |u| / (E' R_x), G = alpha E', W = W / (E' R_x^2), k ellipticity.

Edge cases as for line contacts: u = 0 gives 0, W = 0 gives +inf, both silently.
"""
from __future__ import annotations

import numpy as np

from ._util import arr, check, non_negative, out, positive, radius, safe_exp
from .film_line import speed_material_groups

__all__ = ["point_groups", "hamrock_dowson_ellipticity", "hamrock_dowson_1977_min",
           "hamrock_dowson_1977_cen", "chittenden_1985_min", "chittenden_1985_cen"]


def point_groups(W, Rx, u, eta0, alpha, E_r):
    """Validated (U, G, W) of a point contact referred to the entraining-direction radius."""
    Rx, E_r = radius("Rx", Rx), positive("E_r", E_r)
    U, G = speed_material_groups(Rx, u, eta0, alpha, E_r)
    Wd = None if W is None else non_negative("W", W) / (E_r * Rx**2)
    return U, G, Wd


def _film(C, a_u, a_g, a_w, factor, Rx, U, G, Wd):
    loaded = Wd > 0
    h = Rx * C * U**a_u * G**a_g * np.where(loaded, Wd, 1.0) ** a_w * factor
    return out(np.where(loaded, h, np.inf))


def hamrock_dowson_ellipticity(Rx, Ry, fit: str = "1981"):
    r"""Hamrock-Dowson curve fit of the ellipticity k = a_y/a_x from alpha_r = R_y/R_x.

    ``fit="1981"``: k = 1.0339 alpha_r^0.636 (Hamrock & Dowson 1981, *Ball Bearing
    Lubrication*). ``fit="1977"``: k = 1.03 alpha_r^0.64 (Hamrock & Dowson 1977, Part III).
    For the exact value use :func:`camtrain.formulas.hertz.ellipticity_exact`.
    """
    ratio = radius("Ry", Ry) / radius("Rx", Rx)
    if fit == "1981":
        return out(1.0339 * ratio**0.636)
    if fit == "1977":
        return out(1.03 * ratio**0.64)
    raise ValueError("fit must be '1981' or '1977'")


def _k(k, Rx, Ry):
    if k is None:
        return arr(hamrock_dowson_ellipticity(Rx, Ry))
    return check("k", k, lambda v: np.isfinite(v) & (v > 0), "an ellipticity > 0")


def _speed_exponent(a_u):
    """Mark a point-contact formula whose film goes as U^a_u at fixed geometry and load (the
    roller's film at another entrainment speed is then a scaling of one evaluation)."""
    def mark(fn):
        fn.speed_exponent = a_u
        return fn
    return mark


@_speed_exponent(0.68)
def hamrock_dowson_1977_min(W, Rx, Ry, u, eta0, alpha, E_r, k=None):
    r"""Hamrock & Dowson minimum film thickness, elliptical contact (entrainment along x).

    .. math:: \frac{h_{min}}{R_x} = 3.63\,U^{0.68} G^{0.49} W^{-0.073}\left(1 - e^{-0.68k}\right)

    Args:
        k: ellipticity; default the 1981 fit 1.0339 (R_y/R_x)^0.636 (the 1977 paper's own
            fit 1.03 (R_y/R_x)^0.64 is ``hamrock_dowson_ellipticity(Rx, Ry, "1977")``).

    Validity (34 numerical cases): k 1-8 (paper); U ~1e-12..1e-10, W ~1e-7..1e-5,
    G ~2000-6000 (approximate spans, registry).

    Reference: Hamrock & Dowson (1977) ASME J. Lubr. Technol. 99(2):264, Part III.
    Benchmark (formulas_and_anchors §4.1 case D, k = 1.0339): 55.6 nm.
    """
    U, G, Wd = point_groups(W, Rx, u, eta0, alpha, E_r)
    k = _k(k, Rx, Ry)
    return _film(3.63, 0.68, 0.49, -0.073, 1.0 - safe_exp(-0.68 * k), radius("Rx", Rx), U, G, Wd)


@_speed_exponent(0.67)
def hamrock_dowson_1977_cen(W, Rx, Ry, u, eta0, alpha, E_r, k=None):
    r"""Hamrock & Dowson central film thickness, elliptical contact (entrainment along x).

    .. math:: \frac{h_{cen}}{R_x} = 2.69\,U^{0.67} G^{0.53} W^{-0.067}
              \left(1 - 0.61\,e^{-0.73k}\right)

    Args:
        k: ellipticity; default 1.0339 (R_y/R_x)^0.636.

    Validity: as :func:`hamrock_dowson_1977_min`.

    Reference: Hamrock & Dowson (1977) Part III (coefficients tag [K] in
    formulas_and_anchors §4.1). Benchmark case D: 98.0 nm.
    """
    U, G, Wd = point_groups(W, Rx, u, eta0, alpha, E_r)
    k = _k(k, Rx, Ry)
    factor = 1.0 - 0.61 * safe_exp(-0.73 * k)
    return _film(2.69, 0.67, 0.53, -0.067, factor, radius("Rx", Rx), U, G, Wd)


def _chittenden(C, c_exp, W, R_e, R_s, u, eta0, alpha, E_r):
    U, G, Wd = point_groups(W, R_e, u, eta0, alpha, E_r)
    R_e = radius("R_e", R_e)
    R_s = check("R_s", R_s, lambda v: v > 0, "a radius > 0 (inf allowed)")
    factor = 1.0 - safe_exp(-c_exp * (R_s / R_e) ** (2.0 / 3.0))
    return _film(C, 0.68, 0.49, -0.073, factor, R_e, U, G, Wd)


@_speed_exponent(0.68)
def chittenden_1985_min(W, R_e, R_s, u, eta0, alpha, E_r):
    r"""Chittenden et al. minimum film for entrainment at any angle to the ellipse axes.

    .. math:: \frac{h_{min}}{R_e} = 3.68\,U_e^{0.68} G^{0.49} W_e^{-0.073}
              \left[1 - e^{-0.67 (R_s/R_e)^{2/3}}\right]

    with R_e, R_s the reduced radii along and across the entraining direction
    (:func:`camtrain.formulas.elastic.entrainment_radii`), U_e = eta0 |u|/(E' R_e),
    W_e = W/(E' R_e^2). R_s = inf is allowed (the bracket tends to 1). Validity (registry,
    nominal): U 1e-12..1e-10, W 1e-7..1e-5, G 2000..6000, any entrainment angle.

    Reference: Chittenden, Dowson, Dunn & Taylor (1985) Proc. R. Soc. A 397:245; Yang (1992)
    eq. 3.21 (used for the Ford Zeta cam/domed follower).
    """
    return _chittenden(3.68, 0.67, W, R_e, R_s, u, eta0, alpha, E_r)


@_speed_exponent(0.68)
def chittenden_1985_cen(W, R_e, R_s, u, eta0, alpha, E_r):
    r"""Chittenden et al. central film for entrainment at any angle to the ellipse axes.

    .. math:: \frac{h_{cen}}{R_e} = 4.31\,U_e^{0.68} G^{0.49} W_e^{-0.073}
              \left[1 - e^{-1.23 (R_s/R_e)^{2/3}}\right]

    Reference: Chittenden et al. (1985); Yang (1992) eq. 3.22 (the film Yang uses in the
    friction integral, eq. 3.24).
    """
    return _chittenden(4.31, 1.23, W, R_e, R_s, u, eta0, alpha, E_r)
