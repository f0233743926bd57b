"""Mixed lubrication: Greenwood-Tripp asperity load/area and Teodorescu boundary + viscous friction.

Symbols (SI): lambda = h/sigma film parameter [-]; sigma composite rms roughness [m]; beta
asperity tip radius [m]; zeta areal density of asperity peaks [1/m^2]; A apparent (Hertz)
contact area [m^2]; E_r the reduced modulus passed by the caller [Pa].

Modulus convention flag: Teodorescu et al. (2005) print "E_t" in eq. 9 and define
1/E' = (1/2)[(1-nu1^2)/E1 + (1-nu2^2)/E2] in the notation list, i.e. the same E' as the film
formulas; Greenwood & Tripp's original composite modulus is sometimes defined without the 1/2.
The functions take the modulus as an argument, so the caller decides; camtrain passes E'.
"""
from __future__ import annotations

from functools import lru_cache
from typing import NamedTuple

import numpy as np

from ._util import arr, check, non_negative, out, positive

__all__ = ["greenwood_tripp_function", "greenwood_tripp_tabulated", "greenwood_tripp_f52_fit",
           "greenwood_tripp_1970_load",
           "greenwood_tripp_1970_area", "evans_johnson_shear_stress", "teodorescu_2005_friction",
           "TeodorescuFriction"]

#: Beyond this film parameter F_n(lambda) < 1e-190 and is returned as exactly 0 (avoids
#: subnormal underflow in the parabolic-cylinder evaluation).
_LAMBDA_ZERO = 30.0


def greenwood_tripp_function(lam, n):
    r"""Gaussian asperity-height integral F_n of Greenwood & Tripp.

    .. math:: F_n(\lambda) = \frac{1}{\sqrt{2\pi}}\int_\lambda^\infty (s-\lambda)^n e^{-s^2/2}\,ds
              = \frac{\Gamma(n+1)}{\sqrt{2\pi}}\, e^{-\lambda^2/4}\, D_{-n-1}(\lambda)

    evaluated exactly through the parabolic-cylinder function D (scipy ``pbdv``), for any
    real lambda and n > -1 (n = 2 and 5/2 in use). F_n(lambda) = 0 for lambda > 30.

    Reference: Greenwood & Tripp (1970-71) Proc. IMechE 185:625; Teodorescu et al. (2005)
    notation list (lower limit printed as gamma; read lambda).
    """
    lam = arr(lam)
    if not np.all(np.isfinite(lam)):
        raise ValueError("lambda must be finite")
    far = lam > _LAMBDA_ZERO
    lc = np.where(far, 0.0, lam)
    from scipy.special import gamma, pbdv

    d, _ = pbdv(-float(n) - 1.0, lc)
    val = gamma(n + 1.0) / np.sqrt(2.0 * np.pi) * np.exp(-lc**2 / 4.0) * d
    return out(np.where(far, 0.0, val))


#: the tabulated F_n (:func:`greenwood_tripp_tabulated`): nodes this far apart over
#: [0, _TABLE_TOP] (the mixed range of Teodorescu et al., lambda < 3)
_TABLE_STEP = 2e-3
_TABLE_TOP = 3.0


@lru_cache(maxsize=8)
def _ln_table(n: float):
    """ln F_n and its slope -n F_{n-1} / F_n on the table's nodes, as a cubic Hermite spline."""
    from scipy.interpolate import CubicHermiteSpline

    x = np.linspace(0.0, _TABLE_TOP, int(round(_TABLE_TOP / _TABLE_STEP)) + 1)
    f = greenwood_tripp_function(x, n)
    return CubicHermiteSpline(x, np.log(f), -n * greenwood_tripp_function(x, n - 1.0) / f)


def greenwood_tripp_tabulated(lam, n):
    r"""F_n(lambda) of :func:`greenwood_tripp_function` from a table, for many evaluations.

    ln F_n is interpolated by cubic Hermite pieces between nodes 0.002 apart on
    0 <= lambda <= 3, with the exact slope d ln F_n / d lambda = -n F_{n-1} / F_n (the
    derivative of the integral under its lower limit, n > 0); outside that range F_n is
    evaluated exactly. The interpolation error is h^4/384 times the fourth derivative of
    ln F_n, below the round-off of the exact evaluation: within 2e-13 relative of
    :func:`greenwood_tripp_function` for n = 2 and 5/2 (tests/formulas/test_formulas_properties.py). The
    exact evaluation (a parabolic-cylinder function per point) costs some microseconds; this
    costs some tens of nanoseconds, which the marched roller's traction tables need (hundreds
    of thousands of points).
    """
    if not n > 0.0:
        raise ValueError(f"n = {n}: the tabulated F_n needs n > 0 (its slope is -n F_(n-1))")
    lam = arr(lam)
    if not np.all(np.isfinite(lam)):
        raise ValueError("lambda must be finite")
    inside = (lam >= 0.0) & (lam <= _TABLE_TOP)
    val = np.empty(lam.shape)
    val[inside] = np.exp(_ln_table(float(n))(lam[inside]))
    if not np.all(inside):
        val[~inside] = greenwood_tripp_function(lam[~inside], n)
    return out(val)


def greenwood_tripp_f52_fit(lam):
    r"""Common curve fit F_{5/2}(lambda) ~ 4.4086e-5 (4 - lambda)^6.804 for lambda < 4, else 0.

    Provided for reproducing papers that use it; :func:`greenwood_tripp_function` is exact.
    The fit is within ~10 % of the exact value for 0.5 <= lambda <= 2 but only a quarter of it
    at lambda = 3 and orders of magnitude low near 4. Reference: widely used fit (Göçmen
    extraction appendix, external standard forms).
    """
    lam = arr(lam)
    return out(np.where(lam < 4.0, 4.4086e-5 * np.clip(4.0 - lam, 0.0, None) ** 6.804, 0.0))


def greenwood_tripp_1970_load(lam, A, E_r, sigma, beta, zeta,
                              integral=greenwood_tripp_function):
    r"""Load carried by the asperities, Greenwood-Tripp form as in Teodorescu et al. eq. 9.

    .. math:: W_a = \frac{8\sqrt2}{15}\pi(\zeta\beta\sigma)^2\sqrt{\sigma/\beta}\;E'\,A\,
              F_{5/2}(\lambda)

    Args:
        lam: film parameter h/sigma [-]; A: apparent contact area [m^2]; E_r: modulus [Pa];
        sigma [m]; beta [m]; zeta [1/m^2]; integral: F_n(lambda, n), exact by default
        (:func:`greenwood_tripp_tabulated` for many points).

    Returns:
        W_a [N]. Reference: Greenwood & Tripp (1970-71); Teodorescu et al. (2005) eq. 9.
    """
    sigma, beta = positive("sigma", sigma), positive("beta", beta)
    k = 8.0 * np.sqrt(2.0) / 15.0 * np.pi * (non_negative("zeta", zeta) * beta * sigma) ** 2
    k = k * np.sqrt(sigma / beta) * positive("E_r", E_r)
    return out(k * non_negative("A", A) * arr(integral(lam, 2.5)))


def greenwood_tripp_1970_area(lam, A, sigma, beta, zeta, integral=greenwood_tripp_function):
    r"""Real (asperity) contact area, Teodorescu et al. eq. 10.

    .. math:: A_a = \pi^2(\zeta\beta\sigma)^2\,A\,F_2(\lambda)

    Returns:
        A_a [m^2] (not clipped to A: for lambda well below 0 the model itself exceeds A);
        ``integral`` as :func:`greenwood_tripp_1970_load`.
    """
    zbs = non_negative("zeta", zeta) * positive("beta", beta) * positive("sigma", sigma)
    return out(np.pi**2 * zbs**2 * non_negative("A", A) * arr(integral(lam, 2.0)))


def evans_johnson_shear_stress(p_mean, tau0, gamma_p):
    r"""Pressure-dependent limiting/Eyring shear stress, tau = tau0 + gamma p_mean [Pa].

    Reference: Evans & Johnson (1986) Proc. IMechE C 200:313; Teodorescu et al. (2005) eq. 12.
    """
    return out(arr(tau0) + arr(gamma_p) * arr(p_mean))


class TeodorescuFriction(NamedTuple):
    total: object  #: F_f = F_b + F_v [N]
    boundary: object  #: F_b = tau0 A_a + m W_a [N]
    viscous: object  #: F_v = tau0 (A - A_a) + gamma (W - W_a) [N]
    asperity_load: object  #: W_a [N]
    asperity_area: object  #: A_a [m^2]


def teodorescu_2005_friction(W, A, lam, tau0, gamma_p, m, E_r, sigma, beta, zeta,
                             lambda_limit=3.0, integral=greenwood_tripp_function):
    r"""Boundary (asperity) plus non-Newtonian viscous friction of a mixed contact.

    .. math::
        F_b = \tau_0 A_a + m W_a,\qquad F_v = \tau_0 (A - A_a) + \gamma (W - W_a),

    .. math::
        F_f = F_b + F_v = \tau_0 A + \gamma W + (m - \gamma) W_a

    with W_a, A_a from Greenwood-Tripp where lambda < ``lambda_limit`` (3, as the paper) and
    zero otherwise. The asperity load is clipped to W and the asperity area to A so the split
    stays physical when the statistical model over-predicts at very small lambda.

    Args:
        W: contact load [N]; A: Hertz contact area [m^2] (line contact 2 b L);
        lam: h0/sigma [-]; tau0: Eyring stress [Pa]; gamma_p: pressure coefficient of the
        shear stress [-]; m: pressure coefficient of boundary shear strength [-]; E_r, sigma,
        beta, zeta, integral: as :func:`greenwood_tripp_1970_load`.

    Returns:
        :class:`TeodorescuFriction` (total, boundary, viscous, asperity_load, asperity_area).

    Reference: Teodorescu, Kushwaha, Rahnejat & Taraza (2005) Proc. IMechE K 219, eqs. 8-15.
    """
    W, A = non_negative("W", W), non_negative("A", A)
    lam = check("lam", lam, np.isfinite, "a finite film parameter")
    mixed = lam < lambda_limit
    Wa = np.where(mixed, greenwood_tripp_1970_load(lam, A, E_r, sigma, beta, zeta, integral),
                  0.0)
    Aa = np.where(mixed, greenwood_tripp_1970_area(lam, A, sigma, beta, zeta, integral), 0.0)
    Wa, Aa = np.minimum(Wa, W), np.minimum(Aa, A)
    tau0, g, m = arr(tau0), arr(gamma_p), arr(m)
    Fb = tau0 * Aa + m * Wa
    Fv = tau0 * (A - Aa) + g * (W - Wa)
    return TeodorescuFriction(out(Fb + Fv), out(Fb), out(Fv), out(Wa), out(Aa))
