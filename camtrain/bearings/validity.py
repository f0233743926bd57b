"""Validity of the short-bearing (Ocvirk) model against the finite-length Reynolds solution.

At the same Sommerfeld number ``S = (R/c)^2 eta N L D / W`` (fixed bush, steady load) both
models give an eccentricity; the ratio of their minimum films ``(1 - eps_short) / (1 -
eps_finite)`` says how optimistic the short bearing is (> 1: the short bearing promises a
thicker film than the bearing has). Ocvirk: ``S = (d/b)^2 / (pi shape(eps))`` with Ocvirk's
load shape function (``camtrain.formulas.bearings.ocvirk_load``).

:func:`short_model_warning` is the one place a plan or a run says how optimistic an explicit
short model is for a bearing; it reads :data:`FILM_RATIO_TABLE` (the docs/bearings.md table,
computed by :func:`short_film_ratio`, checked against it by a derived test).
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.formulas.bearings import ocvirk_load

__all__ = ["short_film_ratio", "ocvirk_sommerfeld", "FILM_RATIO_TABLE", "short_model_error",
           "short_model_ratio_at", "steady_sommerfeld", "short_model_warning"]

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
    from .finite import finite_performance

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


#: h_min(short) / h_min(finite) (Swift-Stieber, no groove, 120 x 12 mesh) from
#: :func:`short_film_ratio`: {land b/d: ratios at FILM_RATIO_SOMMERFELD}; None where the finite
#: eccentricity is above 0.985 (outside the solved range). docs/bearings.md prints the same table.
FILM_RATIO_SOMMERFELD = (1.0, 0.3, 0.1, 0.03, 0.01)
FILM_RATIO_TABLE = {
    0.05: (1.01, 1.02, 1.03, None, None),
    0.1: (1.02, 1.04, 1.06, 1.12, None),
    0.2: (1.03, 1.07, 1.12, 1.23, 1.41),
    0.25: (1.04, 1.08, 1.15, 1.28, 1.51),
    0.3: (1.04, 1.09, 1.17, 1.34, 1.60),
    0.4: (1.04, 1.11, 1.22, 1.44, 1.80),
    0.5: (1.05, 1.12, 1.26, 1.53, 2.00),
    0.7: (1.04, 1.13, 1.32, 1.72, 2.38),
    1.0: (1.04, 1.14, 1.39, 1.96, 2.95),
}


def short_model_error(b_over_d: float) -> tuple[float, float, float, float]:
    """(ratio at S = 1, ratio at S = 0.1, ratio at the lowest S solved, that S) for a land
    ``b_over_d``,
    interpolated linearly in b/d in :data:`FILM_RATIO_TABLE` (clamped to its ends)."""
    keys = sorted(FILM_RATIO_TABLE)
    x = min(max(float(b_over_d), keys[0]), keys[-1])
    hi = next(k for k in keys if k >= x)
    lo = hi if x == hi else keys[keys.index(hi) - 1]
    t = 0.0 if hi == lo else (x - lo) / (hi - lo)

    def at(col):
        a, b = FILM_RATIO_TABLE[lo][col], FILM_RATIO_TABLE[hi][col]
        if a is None or b is None:
            return None
        return a + t * (b - a)

    col = next(i for i in (4, 3, 2) if at(i) is not None)
    return at(0), at(2), at(col), FILM_RATIO_SOMMERFELD[col]


def short_model_ratio_at(b_over_d: float, sommerfeld: float) -> float | None:
    """h_min(short) / h_min(finite) at one Sommerfeld number, interpolated in b/d and log S in
    :data:`FILM_RATIO_TABLE`; None outside the table's S range (0.01-1 where solved)."""
    keys = sorted(FILM_RATIO_TABLE)
    x = min(max(float(b_over_d), keys[0]), keys[-1])
    hi = next(k for k in keys if k >= x)
    lo = hi if x == hi else keys[keys.index(hi) - 1]
    t = 0.0 if hi == lo else (x - lo) / (hi - lo)
    row = [None if a is None or b is None else a + t * (b - a)
           for a, b in zip(FILM_RATIO_TABLE[lo], FILM_RATIO_TABLE[hi], strict=True)]
    q = math.log(sommerfeld) if sommerfeld > 0 else -math.inf
    for (s0, r0), (s1, r1) in zip(zip(FILM_RATIO_SOMMERFELD, row, strict=True),
                                  zip(FILM_RATIO_SOMMERFELD[1:], row[1:], strict=True),
                                  strict=False):
        if r0 is None or r1 is None:
            return None
        if math.log(s1) <= q <= math.log(s0):
            return r0 + (q - math.log(s0)) / (math.log(s1) - math.log(s0)) * (r1 - r0)
    return None


def steady_sommerfeld(diameter: float, land: float, clearance: float, viscosity: float,
                      speed: float, load: float) -> float:
    """S = (R/c)^2 eta N L D / W of one land for a steady ``load`` on it [N]; ``speed`` N in
    rev/s (SI inputs)."""
    r = 0.5 * diameter
    return (r / clearance) ** 2 * viscosity * speed * land * diameter / load if load > 0 \
        else math.inf


def short_model_warning(b_over_d: float, limit: float = 0.05,
                        sommerfeld: float | None = None) -> str | None:
    """The warning for a short (Ocvirk) film chosen at land ``b_over_d``, or None when the land
    is short enough (b/d <= ``limit``: within 3.5 % of the finite film for S >= 0.1). With
    ``sommerfeld`` (of the largest load, when the deck knows it) the ratio there is added."""
    if not b_over_d > limit:
        return None
    at_1, at_01, low, s_low = short_model_error(b_over_d)
    more = "at least " if b_over_d > max(FILM_RATIO_TABLE) else ""
    text = (f"warning: at land b/d {b_over_d:.3g} the short film is optimistic, {more}"
            f"x{at_1:.2f} the finite-length film at Sommerfeld 1, x{at_01:.2f} at 0.1"
            + (f", x{low:.2f} at {s_low:g}" if s_low < 0.1 else ""))
    here = None if sommerfeld is None else short_model_ratio_at(b_over_d, sommerfeld)
    if here is not None:
        text += f"; about {more}x{here:.1f} at the largest load (steady S = {sommerfeld:.2g})"
    return text + " (docs/bearings.md)"
