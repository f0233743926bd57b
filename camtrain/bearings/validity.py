"""Validity of the short-bearing (Ocvirk) model against the finite-length Reynolds solution.

At the same Sommerfeld number ``S = (R/c)^2 eta N L D / W`` (fixed bush, steady load) both
models give an eccentricity; the ratio of their minimum films ``(1 - eps_short) / (1 -
eps_finite)`` says how optimistic the short bearing is (> 1: the short bearing promises a
thicker film than the bearing has). Ocvirk: ``S = (d/b)^2 / (pi shape(eps))`` with Ocvirk's
load shape function (``camtrain.formulas.bearings.ocvirk_load``).
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.formulas.bearings import ocvirk_load

from .finite import finite_performance

__all__ = ["short_film_ratio", "ocvirk_sommerfeld"]

_EPS = (0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.93, 0.95, 0.965, 0.975,
        0.985)


def ocvirk_sommerfeld(b_over_d: float, eps):
    """Sommerfeld number of Ocvirk's short bearing at eccentricity ``eps``."""
    shape = 4.0 * np.asarray(ocvirk_load(1.0, 1.0, 1.0, 1.0, 1.0, eps))
    return 1.0 / (b_over_d ** 2 * math.pi * shape)


def short_film_ratio(b_over_d: float, sommerfeld, *, cavitation: str = "reynolds",
                     n_theta: int = 120, n_z: int = 12) -> np.ndarray:
    """h_min(short) / h_min(finite) at the Sommerfeld numbers given (no feed groove).

    The finite S(eps) curve is solved at 17 eccentricities (0.02..0.985) and interpolated in
    (log S, log(1 - eps)), where it is nearly straight; the Ocvirk curve is closed form.
    """
    s_query = np.atleast_1d(np.asarray(sommerfeld, dtype=float))
    eps = np.array(_EPS)
    s_fin, start = [], None
    for e in eps:
        r = finite_performance(b_over_d, e, cavitation=cavitation, feed="none",
                               n_theta=n_theta, n_z=n_z, start=start)
        s_fin.append(r.sommerfeld)
    s_fin = np.array(s_fin)
    eo = 1.0 - np.geomspace(0.98, 1e-4, 400)
    s_ocv = ocvirk_sommerfeld(b_over_d, eo)
    q = np.log(s_query)
    gap_fin = np.exp(np.interp(q, np.log(s_fin[::-1]), np.log(1.0 - eps[::-1])))
    gap_ocv = np.exp(np.interp(q, np.log(s_ocv[::-1]), np.log(1.0 - eo[::-1])))
    out = gap_ocv / gap_fin
    out[(q > np.log(s_fin[0])) | (q < np.log(s_fin[-1]))] = np.nan  # outside the solved range
    return out
