"""Lubricant film of one cam/follower pair: minimum and central EHL film thickness.

With contact loads: Dowson & Higginson (1977) minimum and Dowson & Toyoda (1979) central film for
line contacts (Ball 1988 eqs. 4.1, 4.2); Hamrock & Dowson (1977) or Chittenden et al. (1985) for
point contacts. Without loads: the load-free rigid-piezoviscous (Blok) film of Dowson, Dunn &
Taylor (1983), Ball eq. 4.3, as the minimum film. The entrainment speed is the mean (V_c+V_f)/2
or, as Ball's "entraining velocity", the sum (``tribology.entrainment``); only |u| enters.
Zero entrainment gives h = 0. Angles out of contact (no load) and non-Hertzian geometry give NaN.
"""
from __future__ import annotations

import numpy as np

from camtrain.contact._points import at
from camtrain.contact.hertz import is_line
from camtrain.contact.products import FilmField
from camtrain.formulas import film_thickness, film_thicknesses

_CENTRAL = {"dowson_higginson_1977": "dowson_toyoda_1979",
            "dowson_higginson_1966": "dowson_toyoda_1979",
            "hamrock_dowson_1977_min": "hamrock_dowson_1977_cen",
            "chittenden_1985_min": "chittenden_1985_cen"}


def entrainment(tribology, kin) -> np.ndarray:
    """|u| [m/s] by the deck's convention (``tribology.entrainment``: mean or sum of the surface
    speeds, or half the mean: Göçmen's literal |U/2| of his eq. 2.1 with U the mean of eq. 2.24,
    the reading that reproduces his base-circle film)."""
    u = kin.entrainment_sum if tribology.entrainment == "sum" else kin.entrainment
    if tribology.entrainment == "half_mean":
        u = 0.5 * u
    return np.abs(u)


def methods(tribology, kin, with_load: bool) -> tuple[str, str | None]:
    """(minimum-film method, central-film method or None) of the closed-form formulas."""
    chosen = tribology.film_formula
    if not with_load or chosen == "dowson_dunn_taylor_1983":
        return "dowson_dunn_taylor_1983", None
    if chosen == "auto":
        chosen = "dowson_higginson_1977" if is_line(kin) else "hamrock_dowson_1977_min"
    return chosen, _CENTRAL[chosen]


def steady_film(contact, kin, load=None) -> FilmField:
    """Per-angle steady film of one pair from the closed-form formulas (the ``steady`` film law
    of :mod:`camtrain.contact.model`); ``load`` None gives the load-free Blok film."""
    lub = contact.lubricant
    u = entrainment(contact.tribology, kin)
    R, Ry = kin.radius_x, kin.radius_y
    line = is_line(kin)
    ok = (R > 0.0) & np.isfinite(R)
    if not line:
        ok &= (Ry > 0.0) & np.isfinite(Ry)
    if load is not None:
        ok &= np.asarray(load) > 0.0
    m_min, m_cen = methods(contact.tribology, kin, load is not None)
    common = dict(u=u[ok], eta0=at(lub.viscosity, ok), alpha=at(lub.pressure_viscosity, ok),
                  E_r=at(contact.reduced_modulus, ok))
    if load is None:
        inputs = dict(common, R=R[ok])
    elif line:
        inputs = dict(common, w=np.asarray(load)[ok] / at(contact.width, ok), R=R[ok])
    else:
        inputs = dict(common, W=np.asarray(load)[ok], Rx=R[ok], Ry=Ry[ok], R_e=R[ok],
                      R_s=Ry[ok])
    h_min = np.empty(u.shape)   # NaN where no film is computed (np.full without its wrapper)
    h_min.fill(np.nan)
    h_cen = None
    if m_cen is not None:
        h_cen = np.empty(u.shape)
        h_cen.fill(np.nan)
    if np.count_nonzero(ok):
        if m_cen is None:
            h_min[ok] = film_thickness(method=m_min, **inputs)
        else:
            h_min[ok], h_cen[ok] = film_thicknesses((m_min, m_cen), **inputs)
    return FilmField(min=h_min, central=h_cen, method=m_min, central_method=m_cen)
