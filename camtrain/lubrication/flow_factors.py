r"""Flow and contact factors of the averaged Reynolds equation (rough surfaces).

All are functions of the local film ratio H = h/sigma (h the nominal separation of the mean
planes, sigma the composite rms roughness), for isotropic roughness (Peklenik gamma = 1, Göçmen
Table 3.1). The thesis takes them "from Akalın (1999)" and prints no coefficients; the forms
below are the standard published ones (external to the sources, flagged in the docs):

* pressure flow factor, Patir & Cheng (1978): phi_x = 1 - 0.90 exp(-0.56 H), fitted for H > 0.5;
* shear flow factor, Patir & Cheng (1979): Phi_s = 1.899 H^0.98 exp(-0.92 H + 0.05 H^2) for
  H <= 5, 1.126 exp(-0.25 H) above (continuous at 5 to 1e-3);
* contact factor, Wu & Zheng (1989): phi_c = exp(-0.6912 + 0.782 H - 0.304 H^2 + 0.0401 H^3)
  for 0 <= H < 3, 1 above (the slope of the mean gap, d h_T/dh).

Outside a fit's range the argument is clamped to the range end (phi_x at 0.5, phi_c at 0);
:func:`clamped_count` reports how many nodes were clamped.
"""
from __future__ import annotations

import numpy as np
from scipy.interpolate import CubicSpline

__all__ = ["PRESSURE_FIT_MIN", "CONTACT_FIT_MAX", "pressure_flow_factor", "shear_flow_factor",
           "contact_factor", "mean_gap", "clamped_count"]

#: Lower end of the Patir-Cheng pressure-flow fit [h/sigma].
PRESSURE_FIT_MIN = 0.5
#: Upper end of the Wu-Zheng contact-factor fit [h/sigma] (phi_c = 1 above).
CONTACT_FIT_MAX = 3.0


def pressure_flow_factor(H):
    """Patir & Cheng (1978) pressure flow factor phi_x, gamma = 1 (H clamped to >= 0.5)."""
    H = np.maximum(np.asarray(H, dtype=float), PRESSURE_FIT_MIN)
    return 1.0 - 0.90 * np.exp(-0.56 * H)


def shear_flow_factor(H):
    """Patir & Cheng (1979) shear flow factor Phi_s for one rough surface, gamma = 1.

    For two rough surfaces the shear term carries (Vr1 - Vr2) Phi_s with Vr_i = sigma_i^2/sigma^2
    (the caller's ``shear_weight``).
    """
    H = np.maximum(np.asarray(H, dtype=float), 0.0)
    Hl = np.minimum(H, 5.0)
    low = 1.899 * Hl**0.98 * np.exp(-0.92 * Hl + 0.05 * Hl**2)
    return np.where(H <= 5.0, low, 1.126 * np.exp(-0.25 * H))


def _contact_poly(H):
    return np.exp(-0.6912 + 0.782 * H - 0.304 * H**2 + 0.0401 * H**3)


def contact_factor(H):
    """Wu & Zheng (1989) contact factor phi_c (H clamped to >= 0; 1 for H >= 3)."""
    H = np.maximum(np.asarray(H, dtype=float), 0.0)
    return np.where(H < CONTACT_FIT_MAX, _contact_poly(np.minimum(H, CONTACT_FIT_MAX)), 1.0)


_GRID = np.linspace(0.0, CONTACT_FIT_MAX, 6001)
#: mean gap on the fit range: H + int_H^3 (1 - phi_c) dH' (spline antiderivative, tabulated
#: for linear interpolation: error < 1e-8 sigma)
_ANTI = CubicSpline(_GRID, _contact_poly(_GRID) - 1.0).antiderivative()
_MEAN_GAP = _GRID - float(_ANTI(CONTACT_FIT_MAX)) + _ANTI(_GRID)
_PHI_C0 = float(_contact_poly(0.0))


def mean_gap(H):
    r"""Mean gap h_T/sigma = integral of phi_c dH, normalised so h_T -> h for H >= 3.

    h_T = H + \int_H^3 (1 - phi_c) dH' (H < 3), H above; slope phi_c(0) below H = 0.
    """
    H = np.asarray(H, dtype=float)
    inner = np.interp(H, _GRID, _MEAN_GAP) + _PHI_C0 * np.minimum(H, 0.0)
    return np.where(H < CONTACT_FIT_MAX, inner, H)


def clamped_count(H) -> int:
    """Nodes whose film ratio lies below the Patir-Cheng pressure-flow fit (H < 0.5)."""
    return int(np.count_nonzero(np.asarray(H) < PRESSURE_FIT_MIN))
