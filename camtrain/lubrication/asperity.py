r"""Greenwood-Tripp asperity pressure and contact-area fraction along a gap (tabulated F_n).

p_a(h) = (8 sqrt2/15) pi (zeta beta sigma)^2 sqrt(sigma/beta) E' F_{5/2}(h/sigma) and the local
real-area fraction a_a(h) = pi^2 (zeta beta sigma)^2 F_2(h/sigma): Greenwood & Tripp (1970-71),
the per-area form of Teodorescu et al. (2005) eqs. 9-10 (Göçmen 2013 uses GT for W_A but prints
no formula; integrating p_a over the zone is a camtrain choice, flagged). F_n is the exact
Gaussian integral of :func:`camtrain.formulas.greenwood_tripp_function`, tabulated once as a
cubic spline of ln F_n (relative error < 1e-8 on -4 <= lambda <= 30; 0 beyond 30) because the
parabolic-cylinder evaluation costs ~10 us per node and the load balance calls it thousands of
times per cycle.
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np
from scipy.interpolate import CubicSpline

from camtrain.formulas import greenwood_tripp_function

__all__ = ["gt_function", "asperity_pressure_coefficient", "asperity_pressure",
           "asperity_area_fraction"]

_LAMBDA_MIN, _LAMBDA_MAX = -4.0, 30.0


_CELLS = 6800
_STEP = (_LAMBDA_MAX - _LAMBDA_MIN) / _CELLS


@lru_cache(maxsize=4)
def _log_table(n: float) -> np.ndarray:
    """Piecewise-cubic coefficients (4, cells) of the spline of ln F_n on the uniform grid."""
    lam = np.linspace(_LAMBDA_MIN, _LAMBDA_MAX, _CELLS + 1)
    return CubicSpline(lam, np.log(greenwood_tripp_function(lam, n))).c


def _cells(lam: np.ndarray):
    """(cell index, offset in the cell) of each lambda in the table."""
    s = (lam - _LAMBDA_MIN) / _STEP
    i = np.minimum(s.astype(np.intp), _CELLS - 1)
    return i, (s - i) * _STEP


def _log_f(lam: np.ndarray, n: float, cells=None) -> np.ndarray:
    c = _log_table(float(n))
    i, d = _cells(lam) if cells is None else cells
    return ((c[0, i] * d + c[1, i]) * d + c[2, i]) * d + c[3, i]


def gt_function(lam, n: float) -> np.ndarray:
    """F_n(lambda) from the table (exact function outside -4 <= lambda; 0 above 30)."""
    lam = np.asarray(lam, dtype=float)
    inside = (lam >= _LAMBDA_MIN) & (lam <= _LAMBDA_MAX)
    if np.all(inside):
        return np.exp(_log_f(lam, n))
    val = np.zeros(lam.shape)
    val[inside] = np.exp(_log_f(lam[inside], n))
    low = lam < _LAMBDA_MIN
    if np.any(low):
        val[low] = greenwood_tripp_function(lam[low], n)
    return val


def gt_functions(lam, orders) -> tuple:
    """F_n(lambda) for each n of ``orders`` (as :func:`gt_function`; the table cells are
    located once for all orders: a Newton iterate needs F_5/2 and its slope -5/2 F_3/2)."""
    lam = np.asarray(lam, dtype=float)
    inside = (lam >= _LAMBDA_MIN) & (lam <= _LAMBDA_MAX)
    low = lam < _LAMBDA_MIN
    some_low = bool(np.any(low))
    cells = _cells(lam[inside])
    values = []
    for n in orders:
        val = np.zeros(lam.shape)
        val[inside] = np.exp(_log_f(None, n, cells))
        if some_low:
            val[low] = greenwood_tripp_function(lam[low], n)
        values.append(val)
    return tuple(values)


def asperity_pressure_coefficient(E_r, zeta_beta_sigma, sigma_over_beta) -> float:
    """(8 sqrt2/15) pi (zeta beta sigma)^2 sqrt(sigma/beta) E' [Pa]."""
    return (8.0 * np.sqrt(2.0) / 15.0 * np.pi * zeta_beta_sigma**2
            * np.sqrt(sigma_over_beta) * E_r)


def asperity_pressure(h, sigma, coefficient) -> np.ndarray:
    """Nominal asperity contact pressure p_a(h) [Pa] at separations h [m]."""
    return coefficient * gt_function(np.asarray(h) / sigma, 2.5)


def asperity_area_fraction(h, sigma, zeta_beta_sigma) -> np.ndarray:
    """Real-to-nominal contact-area ratio pi^2 (zeta beta sigma)^2 F_2(h/sigma), at most 1."""
    return np.minimum(np.pi**2 * zeta_beta_sigma**2 * gt_function(np.asarray(h) / sigma, 2.0),
                      1.0)
