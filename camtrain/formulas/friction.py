"""Cam/follower contact friction: Barus shear over the Hertz zone, boundary cap, lambda switch.

Ball (1988) and Yang (1992) model the traction as isothermal Newtonian shear of a Barus fluid
at a uniform film h (the central film) across the Hertz zone, sliding only, capped by boundary
friction mu W. The pressure-integrated Barus factor grows like exp(alpha p_max), so every
function here evaluates it in log space and applies the cap before leaving log space: capped
results are always finite. Uncapped forces are returned as +inf (silently) where they exceed
the float range.
"""
from __future__ import annotations

import numpy as np

from ._util import arr, capped_exp_product, check, non_negative, out, positive, safe_divide, safe_exp
from .viscosity import ROELANDS_ETA_INF, ROELANDS_P_R, roelands_z

__all__ = ["barus_line_integral", "barus_line_integral_closed_form", "log_barus_line_integral",
           "barus_ellipse_integral",
           "log_barus_ellipse_integral", "ball_1988_shear_force", "yang_1992_shear_force",
           "ball_1988_friction", "yang_1992_friction", "friction_coefficient", "film_parameter",
           "log_roelands_line_integral", "log_roelands_ellipse_integral", "VISCOSITY_LAWS",
           "FRICTION_MODELS"]

#: Above this a = alpha p_max the I1 + L1 form is replaced by its exact-to-double asymptote.
_A_SWITCH = 40.0

# Below _A_SWITCH, J(a) is evaluated by 48-point Gauss-Legendre quadrature of its smooth form
# J = int_{-pi/2}^{pi/2} exp(a cos t) cos t dt (s = sin t): it agrees with the closed form
# pi [I_1 + L_1] + 2 to 3e-13 relative for 0 <= a <= 40 (tested) and is about 12 times faster,
# because the modified Struve function dominates the cost of a whole cam cycle.
_GL_X, _GL_W = np.polynomial.legendre.leggauss(48)
_GL_COS = np.cos(0.5 * np.pi * _GL_X)
_GL_WEIGHTS = 0.5 * np.pi * _GL_W * _GL_COS
# The nodes are symmetric, so cos(pi x / 2) takes 24 distinct values: exp is evaluated on those
# and mirrored (the weighted sum is then the same 48-term sum, bit for bit, at half the exps).
_GL_HALF = _GL_COS[:24].copy()
assert np.array_equal(np.concatenate((_GL_HALF, _GL_HALF[::-1])), _GL_COS)


def _barus_gl_sum(a):
    """sum_j w_j exp(a cos t_j) of the 48-point rule, for an array of a < _A_SWITCH."""
    half = np.multiply.outer(a, _GL_HALF)
    np.exp(half, out=half)
    nodes = np.empty(half.shape[:-1] + (48,))
    nodes[..., :24] = half
    nodes[..., 24:] = half[..., ::-1]
    return nodes @ _GL_WEIGHTS


def barus_line_integral_closed_form(a):
    r"""J(a) = pi [I_1(a) + L_1(a)] + 2 (Ball 1988 eq. 4.7 corrected, closed form); the reference
    the fast quadrature of :func:`log_barus_line_integral` is tested against (overflows above
    a ~ 700)."""
    from scipy.special import iv, modstruve

    a = non_negative("a", a)
    return out(np.pi * (iv(1, a) + modstruve(1, a)) + 2.0)


def log_barus_line_integral(a):
    r"""ln J(a), J(a) = \int_{-1}^{1} \exp(a\sqrt{1-s^2})\,ds, finite for any a >= 0.

    For a < 40, J is the closed form pi [I_1(a) + L_1(a)] + 2 evaluated by Gauss-Legendre
    quadrature (see above); above, J = 2 pi I_1(a) (the remainder pi (L_1 - I_1) + 2 =
    O(1/a^2) is below double precision relative to e^a), with I_1 taken scaled (``ive``) so
    ln J = ln(2 pi ive(1, a)) + a never overflows.
    """
    a = non_negative("a", a)
    small = a < _A_SWITCH
    if np.count_nonzero(small) == small.size:   # the usual case: no contact loaded past the switch
        return out(np.log(_barus_gl_sum(a)))
    result = np.empty_like(a, dtype=float)
    a_lo = a[small]
    result[small] = np.log(_barus_gl_sum(a_lo))
    a_hi = a[~small]
    if a_hi.size:  # scipy.special only when a contact is this heavily loaded
        from scipy.special import ive

        result[~small] = np.log(2.0 * np.pi * ive(1, a_hi)) + a_hi
    return out(result)


#: Pressure-viscosity laws the shear integrals accept.
VISCOSITY_LAWS = ("barus", "roelands")

# Gauss-Legendre nodes on [0, 1] for the elliptical-zone integral of a radial profile
_GL01_C = 0.5 * (_GL_X + 1.0)
_GL01_W = 0.5 * _GL_W


def _roelands_exponent(p, eta0, alpha):
    """ln(eta/eta0) of Roelands' law with z matched to the Barus slope alpha at p = 0."""
    z = roelands_z(eta0, alpha)
    return np.log(eta0 / ROELANDS_ETA_INF) * ((1.0 + p / ROELANDS_P_R) ** z - 1.0)


def _log_weighted_sum(exponents, weights):
    """ln sum_j w_j exp(E_ij) over the last axis, without overflow (log-sum-exp)."""
    top = np.max(exponents, axis=-1, keepdims=True)
    return np.log(np.exp(exponents - top) @ weights) + top[..., 0]


def log_roelands_line_integral(p_max, eta0, alpha):
    r"""ln J_R, J_R = \int_{-1}^{1} \eta(p_{max}\sqrt{1-s^2})/\eta_0\,ds for Roelands' law
    (z from :func:`roelands_z`), by the 48-point Gauss-Legendre rule of the Barus case; the
    Roelands counterpart of :func:`log_barus_line_integral` (Ball 1988 eq. 4.7 with the
    viscosity law exchanged). Equals ln J(alpha p_max) to first order as p_max -> 0."""
    p = non_negative("p_max", p_max)
    e = _roelands_exponent(np.multiply.outer(p, _GL_COS), eta0, alpha)
    return out(_log_weighted_sum(e, _GL_WEIGHTS))


def log_roelands_ellipse_integral(p_max, eta0, alpha):
    r"""ln K_R, K_R = \iint_{unit\ disc} \eta(p_{max}\sqrt{1-r^2})/\eta_0\,dS
    = 2\pi\int_0^1 \eta(p_{max} c)/\eta_0\, c\,dc (Yang 1992 eq. 3.24 with Roelands' law),
    by 48-point Gauss-Legendre quadrature on [0, 1]."""
    p = non_negative("p_max", p_max)
    e = _roelands_exponent(np.multiply.outer(p, _GL01_C), eta0, alpha)
    return out(np.log(2.0 * np.pi) + _log_weighted_sum(e, _GL01_W * _GL01_C))


def _log_zone_integral(law, p_max, eta0, alpha, shape):
    """ln of the pressure-viscosity factor integrated over the Hertz zone (line or ellipse)."""
    if law == "barus":
        a = non_negative("alpha", alpha) * non_negative("p_max", p_max)
        return log_barus_line_integral(a) if shape == "line" else log_barus_ellipse_integral(a)
    if law == "roelands":
        fn = log_roelands_line_integral if shape == "line" else log_roelands_ellipse_integral
        return fn(p_max, eta0, alpha)
    raise ValueError(f"viscosity law must be one of {VISCOSITY_LAWS}, got {law!r}")


def barus_line_integral(a):
    r"""Dimensionless Barus-Hertz integral for a line contact.

    .. math:: J(a) = \int_{-1}^{1} e^{a\sqrt{1-s^2}}\,ds = \pi\left[I_1(a) + \mathbf{L}_1(a)\right] + 2

    with I_1 the modified Bessel and L_1 the modified Struve function (s = x/b, a = alpha p_max).
    J(0) = 2. Returns +inf (silently) above a ~ 714.

    Reference: Ball (1988) eq. 4.7 corrected (alpha p_max inside the exponent); closed form
    derived in the Ball extraction §2.6 and checked here against quadrature to 1e-10.
    """
    return out(safe_exp(log_barus_line_integral(a)))


def log_barus_ellipse_integral(A):
    r"""ln K(A), K(A) = \iint_{unit\ disc} \exp(A\sqrt{1-r^2})\,dS, finite for any A >= 0.

    K = 2 pi [e^A (A - 1) + 1] / A^2. Small A uses the series sum_{n>=2} (n-1) A^(n-2) / n!
    (K(0) = pi); large A works with ln[e^A (A-1) + 1] = A + ln(A - 1 + e^-A).
    """
    A = non_negative("A", A)
    small = A < 1e-2
    As = np.where(small, A, 0.0)
    coef = (1 / 2, 1 / 3, 1 / 8, 1 / 30, 1 / 144, 1 / 840, 1 / 5760)  # (n-1)/n!, n = 2..8
    series = sum(c * As**i for i, c in enumerate(coef))
    Al = np.where(small, 1.0, A)
    logf = Al + np.log(Al + np.expm1(-np.minimum(Al, 700.0))) - 2.0 * np.log(Al)
    return out(np.log(2.0 * np.pi) + np.where(small, np.log(series), logf))


def barus_ellipse_integral(A):
    r"""Dimensionless Barus-Hertz integral over an elliptical contact (per unit a b).

    .. math:: K(A) = \frac{1}{ab}\iint_{ellipse} e^{A\sqrt{1 - x^2/a^2 - y^2/b^2}}\,dx\,dy
              = \frac{2\pi\left[e^{A}(A-1) + 1\right]}{A^2}

    K(0) = pi. Reference: Yang (1992) eq. 3.24 (integration limit b sqrt(1 - x^2/a^2), garbled
    in the scan); closed form in the Yang extraction §2.2.5.
    """
    return out(safe_exp(log_barus_ellipse_integral(A)))


def _prefactor(u_s, h, eta0):
    """eta0 |u_s| / h [Pa]; +inf where h = 0 and the surfaces slide, 0 where nothing slides.

    h = +inf (the films' value for an unloaded contact) is accepted and gives 0.
    """
    h = check("h", h, lambda v: v >= 0, "a film thickness >= 0 (inf allowed)")
    return safe_divide(positive("eta0", eta0) * np.abs(arr(u_s)), h, zero_den=np.inf)


def ball_1988_shear_force(u_s, h, eta0, alpha, p_max, b, L, cap=np.inf, viscosity_law="barus"):
    r"""Viscous (Barus) sliding friction over a Hertz line contact, Ball (1988) eq. 4.7 corrected.

    .. math:: F = L\,\frac{\eta_0 |V_s|}{h}\int_{-b}^{b}
              \exp\left[\alpha p_{max}\sqrt{1 - x^2/b^2}\right]dx
              = L\,\frac{\eta_0 |V_s|}{h}\, b\,\left\{\pi\left[I_1(a) + \mathbf{L}_1(a)\right]
              + 2\right\},\quad a = \alpha p_{max}

    Args:
        u_s: sliding speed [m/s] (sign ignored); h: film thickness used for the shear rate [m]
            (Ball uses h_cen); eta0 [Pa s]; alpha [1/Pa]; p_max [Pa]; b Hertz half-width [m];
        L: contact length [m]; cap: optional upper bound [N] applied in log space;
        viscosity_law: "barus" (Ball) or "roelands" (z matched to alpha at p = 0).

    Returns:
        F [N] = min(F_visc, cap). h = 0 with sliding gives +inf before the cap.

    Reference: Ball (1988) eqs. 4.4-4.7 (printed 4.7 pulls e^{alpha p_max} out of the
    integral: wrong; corrected here).
    """
    pre = _prefactor(u_s, h, eta0) * non_negative("b", b) * non_negative("L", L)
    log_j = _log_zone_integral(viscosity_law, p_max, eta0, alpha, "line")
    return out(capped_exp_product(pre, log_j, cap))


def yang_1992_shear_force(u_s, h, eta0, alpha, p_max, a_x, a_y, cap=np.inf,
                          viscosity_law="barus"):
    r"""Viscous (Barus) sliding friction over a Hertz ellipse, Yang (1992) eq. 3.24.

    .. math:: F = \frac{\eta_0 |V_s|}{h}\iint e^{\alpha P_{max}\sqrt{1-x^2/a^2-y^2/b^2}}dx\,dy
              = \frac{\eta_0 |V_s|}{h}\,\frac{2\pi a b\left[e^{A}(A-1)+1\right]}{A^2},
              \quad A = \alpha P_{max}

    Args:
        u_s [m/s]; h [m] (Yang uses h_cen); eta0 [Pa s]; alpha [1/Pa]; p_max [Pa];
        a_x, a_y: Hertz semi-axes [m]; cap: optional upper bound [N];
        viscosity_law: "barus" (Yang) or "roelands".

    Returns:
        F [N] = min(F_visc, cap).
    """
    pre = _prefactor(u_s, h, eta0) * non_negative("a_x", a_x) * non_negative("a_y", a_y)
    log_k = _log_zone_integral(viscosity_law, p_max, eta0, alpha, "ellipse")
    return out(capped_exp_product(pre, log_k, cap))


FRICTION_MODELS = ("cap", "lambda", "lambda_cap")


def film_parameter(h, sigma):
    """Film parameter lambda = h / sigma [-] (sigma composite rms roughness [m]; h may be inf)."""
    h = check("h", h, lambda v: v >= 0, "a film thickness >= 0 (inf allowed)")
    return out(h / positive("sigma", sigma))


def _combine(F_visc_fn, h, W, mu, model, sigma):
    W = non_negative("W", W)
    bound = non_negative("mu", mu) * W
    if model not in FRICTION_MODELS:
        raise ValueError(f"model must be one of {FRICTION_MODELS}, got {model!r}")
    F = arr(F_visc_fn(bound if model in ("cap", "lambda_cap") else np.inf))
    if model != "cap":
        boundary = arr(film_parameter(h, sigma)) < 1.0
        F = np.where(boundary, bound, F)
    return out(F)


def ball_1988_friction(u_s, h, eta0, alpha, p_max, b, L, W, mu=0.08, model="cap",
                       sigma=0.2e-6, viscosity_law="barus"):
    r"""Ball's cam/follower friction force for a line contact: viscous shear and boundary limit.

    Models (``model``):
        * ``"cap"`` (Ball's default): F = min(F_visc, mu W) with F_visc from
          :func:`ball_1988_shear_force`. Always finite.
        * ``"lambda"``: F = mu W where lambda = h/sigma < 1, else F_visc (uncapped; may be +inf
          if alpha p_max is absurdly large).
        * ``"lambda_cap"``: both.

    Args:
        u_s, h, eta0, alpha, p_max, b, L: as :func:`ball_1988_shear_force`.
        W: normal load [N]. mu: boundary friction coefficient [-], 0.08 after Zhu (1988).
        sigma: composite rms roughness [m] for the lambda switch, 0.2 um (run-in, Harrison 1985).

    Returns:
        F [N]. Reference: Ball (1988) §4.2.3.4.
    """
    return _combine(lambda cap: ball_1988_shear_force(u_s, h, eta0, alpha, p_max, b, L, cap,
                                                      viscosity_law),
                    h, W, mu, model, sigma)


def yang_1992_friction(u_s, h, eta0, alpha, p_max, a_x, a_y, W, mu=0.08, model="cap",
                       sigma=0.2e-6, viscosity_law="barus"):
    """Yang's cam/follower friction for an elliptical contact: min(F_visc, mu W) by default.

    Same models as :func:`ball_1988_friction`, with F_visc from :func:`yang_1992_shear_force`.
    Reference: Yang (1992) §3.2.5 (limiting traction 0.08).
    """
    return _combine(lambda cap: yang_1992_shear_force(u_s, h, eta0, alpha, p_max, a_x, a_y, cap,
                                                      viscosity_law),
                    h, W, mu, model, sigma)


def friction_coefficient(F, W):
    """mu = F / W [-]; 0 where F = W = 0 (no load, no friction), +inf where only W = 0."""
    return out(safe_divide(arr(F), non_negative("W", W), zero_den=np.inf))
