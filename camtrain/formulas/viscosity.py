"""Lubricant viscosity: pressure (Barus, Roelands) and temperature (Reynolds, Walther, Vogel).

SI throughout: pressure [Pa], dynamic viscosity [Pa s], kinematic viscosity [m^2/s],
temperature [K].

Overflow policy. exp(alpha p) leaves the double range when alpha p > ~709.78 (for alpha = 2e-8
/Pa that is p > 35 GPa, far beyond any cam contact, but a careless sweep can get there). The
pressure-viscosity functions never raise or warn: they return ``+inf`` where the true value
exceeds the float range, or ``eta_max`` when a finite cap is given. Code that must stay finite
should work with :func:`barus_log` (ln eta, always finite) or use the closed-form friction
integrals in :mod:`.friction`, which combine the exponent with the boundary cap in log space.
"""
from __future__ import annotations

import numpy as np

from camtrain.errors import field_error

from ._util import arr, check, non_negative, out, positive, safe_exp

__all__ = ["barus", "barus_log", "roelands", "roelands_z", "reynolds_viscosity",
           "reynolds_two_point", "walther_two_point", "vogel", "vogel_fit"]

#: Roelands reference constants (Roelands 1966): eta_inf = 6.31e-5 Pa s, p_r = 1.96e8 Pa.
ROELANDS_ETA_INF = 6.31e-5
ROELANDS_P_R = 1.96e8


def barus_log(p, eta0, alpha):
    r"""Natural log of the Barus viscosity, ln(eta0) + alpha p (always finite) [ln(Pa s)]."""
    return out(np.log(positive("eta0", eta0)) + non_negative("alpha", alpha) * arr(p))


def barus(p, eta0, alpha, eta_max=np.inf):
    r"""Barus (1893) pressure-viscosity law, :math:`\eta = \eta_0 e^{\alpha p}`.

    Args:
        p: pressure [Pa] (gauge).
        eta0: viscosity at ambient pressure [Pa s].
        alpha: pressure-viscosity coefficient [1/Pa].
        eta_max: optional cap [Pa s]; the result is min(eta, eta_max). Default no cap.

    Returns:
        eta [Pa s]; ``+inf`` (no warning) where it overflows and no finite cap is given.

    Validity: fits well up to roughly 0.5 GPa; over-predicts at higher pressure (use Roelands).
    Reference: Barus (1893); Ball (1988) §4.2.3.1; Yang (1992) §3.2.4.
    """
    return out(np.minimum(safe_exp(barus_log(p, eta0, alpha)), eta_max))


def roelands_z(eta0, alpha, eta_inf=ROELANDS_ETA_INF, p_r=ROELANDS_P_R):
    r"""Roelands pressure index z that matches the Barus slope alpha at p = 0.

    .. math:: z = \frac{\alpha\, p_r}{\ln(\eta_0/\eta_\infty)}

    (Houpert 1985's usual identification). Requires eta0 > eta_inf.
    """
    eta0 = check("eta0", eta0, lambda v: np.isfinite(v) & (v > eta_inf),
                 f"a viscosity above eta_inf = {eta_inf} Pa s")
    return out(non_negative("alpha", alpha) * p_r / np.log(eta0 / eta_inf))


def roelands(p, eta0, alpha=None, z=None, eta_inf=ROELANDS_ETA_INF, p_r=ROELANDS_P_R,
             eta_max=np.inf):
    r"""Roelands (1966) pressure-viscosity law.

    .. math:: \eta = \eta_0 \exp\left\{\ln(\eta_0/\eta_\infty)
              \left[(1 + p/p_r)^z - 1\right]\right\}

    with eta_inf = 6.31e-5 Pa s and p_r = 1.96e8 Pa (so ln(eta0/eta_inf) = ln eta0 + 9.67).
    Give either ``z`` or ``alpha`` (then z = :func:`roelands_z`).

    Args:
        p: pressure [Pa] (> -p_r); eta0: ambient viscosity [Pa s]; alpha: [1/Pa]; z: [-].

    Returns:
        eta [Pa s]; overflow policy as :func:`barus`.

    Reference: Roelands (1966) thesis, Delft; numerical EHL check in formulas_and_anchors §4.1
    (z = 0.68, p_0 = 1.96e8).
    """
    if (alpha is None) == (z is None):
        raise ValueError("give exactly one of alpha or z")
    if z is None:
        z = roelands_z(eta0, alpha, eta_inf, p_r)
    eta0 = positive("eta0", eta0)
    p = check("p", p, lambda v: v > -p_r, f"a pressure above -p_r = {-p_r} Pa")
    expo = np.log(eta0 / eta_inf) * ((1.0 + p / p_r) ** arr(z) - 1.0)
    return out(np.minimum(eta0 * safe_exp(expo), eta_max))


def reynolds_viscosity(T, eta_ref, T_ref, beta):
    r"""Reynolds (1886) exponential temperature law, :math:`\eta = \eta_{ref} e^{-\beta(T-T_{ref})}`.

    Args:
        T, T_ref: temperatures [K]; eta_ref: viscosity at T_ref [Pa s];
        beta: temperature-viscosity coefficient [1/K].

    Validity: a narrow temperature band (+-20 K) around T_ref.
    """
    return out(positive("eta_ref", eta_ref) * safe_exp(-arr(beta) * (arr(T) - arr(T_ref))))


def reynolds_two_point(T, T1, eta1, T2, eta2):
    r"""Two-point fit of :func:`reynolds_viscosity` through (T1, eta1) and (T2, eta2).

    .. math:: \beta = \frac{\ln(\eta_1/\eta_2)}{T_2 - T_1}

    Interpolates exactly; extrapolation is poor for multigrade oils (prefer Walther).
    """
    eta1, eta2 = positive("eta1", eta1), positive("eta2", eta2)
    T1, T2 = positive("T1", T1), positive("T2", T2)
    if np.any(T1 == T2):
        raise field_error("T2", "the two fit temperatures must differ", float(np.max(T2)))
    beta = np.log(eta1 / eta2) / (T2 - T1)
    return reynolds_viscosity(T, eta1, T1, beta)


def walther_two_point(T, T1, nu1, T2, nu2):
    r"""Walther / ASTM D341 two-point kinematic viscosity-temperature line.

    .. math:: \log_{10}\log_{10}(\nu_{cSt} + 0.7) = A - B \log_{10} T

    fitted through (T1, nu1) and (T2, nu2), typically 40 and 100 degC data-sheet values. The
    0.7 offset is valid for nu >= 2 cSt (ASTM D341 adds small corrections below).

    Args:
        T, T1, T2: temperatures [K]; nu1, nu2: kinematic viscosities [m^2/s].

    Returns:
        kinematic viscosity [m^2/s] (multiply by density for Pa s).

    Reference: Walther (1931); ASTM D341.
    """
    nu1, nu2 = positive("nu1", nu1) * 1e6, positive("nu2", nu2) * 1e6  # to cSt
    T1, T2, T = positive("T1", T1), positive("T2", T2), positive("T", T)
    z1, z2 = np.log10(np.log10(nu1 + 0.7)), np.log10(np.log10(nu2 + 0.7))
    B = (z1 - z2) / (np.log10(T2) - np.log10(T1))
    zz = z1 - B * (np.log10(T) - np.log10(T1))
    return out((10.0 ** (10.0**zz) - 0.7) * 1e-6)


def vogel(T, A, B, T_inf):
    r"""Vogel (1921) equation, :math:`\eta = A \exp[B / (T - T_\infty)]`.

    Args:
        T: temperature [K] (> T_inf); A: [Pa s]; B: [K]; T_inf: [K].

    Returns:
        eta [Pa s]. Reference: Vogel (1921) Phys. Z. 22:645.
    """
    T = arr(T)
    if np.any(T <= arr(T_inf)):
        raise field_error("T", "temperature at or below the Vogel asymptote T_inf",
                          float(np.min(T)), f"> {float(np.max(T_inf))} K")
    return out(arr(A) * safe_exp(arr(B) / (T - arr(T_inf))))


def vogel_fit(T, eta):
    r"""Fit :func:`vogel` to three or more (T, eta) points; returns (A, B, T_inf).

    Three points: exact solution (T_inf from the ratio of log-viscosity differences). More
    points: least squares in ln(eta), T_inf found by a bounded scalar search with (ln A, B)
    solved linearly for each trial value.
    """
    T, eta = np.ravel(positive("T", T)), np.ravel(positive("eta", eta))
    if T.size != eta.size or T.size < 3:
        raise field_error("T", "Vogel fit needs at least three (T, eta) pairs", T.size)
    order = np.argsort(T)
    T, y = T[order], np.log(eta[order])
    if np.any(np.diff(T) <= 0) or np.any(np.diff(y) >= 0):
        raise field_error("eta", "Vogel fit needs distinct temperatures and viscosity falling "
                          "with temperature", eta.tolist())

    def solve_ab(c):
        X = np.column_stack([np.ones_like(T), 1.0 / (T - c)])
        coef, *_ = np.linalg.lstsq(X, y, rcond=None)
        return coef, float(np.sum((X @ coef - y) ** 2))

    if T.size == 3:
        q = (y[0] - y[1]) / (y[1] - y[2])
        d1, d2 = T[1] - T[0], T[2] - T[1]
        c = (d1 * T[2] - q * d2 * T[0]) / (d1 - q * d2)
    else:
        from scipy.optimize import minimize_scalar

        c = minimize_scalar(lambda c: solve_ab(c)[1], bounds=(0.0, T[0] - 1e-6),
                            method="bounded", options={"xatol": 1e-10}).x
    if not c < T[0]:
        raise field_error("eta", "the points do not follow a Vogel curve (T_inf >= min T)", c)
    (lnA, B), _ = solve_ab(c)
    return float(np.exp(lnA)), float(B), float(c)
