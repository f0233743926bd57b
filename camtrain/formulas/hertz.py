"""Hertz dry elastic contact: line contact and elliptical (point) contact.

Modulus convention: E' = 2/[(1-nu1^2)/E1 + (1-nu2^2)/E2] (see :mod:`.elastic`).

Edge cases (documented policy, identical in every function here):

* zero load gives zero contact size and zero pressure (finite);
* a negative load is a field error (the contact has separated; a film or Hertz value is
  meaningless there);
* the reduced radius must satisfy 0 < R < inf. Large finite R (nearly conformal) gives large but
  finite semi-axes and small pressures. ``R = inf`` (curvature sum exactly 0) or a negative R
  (concave body dominates) is a field error naming the first offending index: Hertz theory does
  not describe conformal contacts.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ._util import arr, non_negative, out, positive, radius

__all__ = ["hertz_line", "hertz_line_half_width", "hertz_line_max_pressure", "HertzLine",
           "hertz_point", "hertz_point_max_pressure", "HertzPoint", "ellipticity_exact",
           "ball_1988_point_max_pressure", "HERTZ_POINT_METHODS"]


class HertzLine(NamedTuple):
    half_width: object  #: b [m]
    max_pressure: object  #: p_max [Pa]
    load_per_length: object  #: w [N/m]


def hertz_line_half_width(w, R, E_r):
    r"""Hertz half-width of a line contact, :math:`b = \sqrt{8 w R / (\pi E')}`.

    Args:
        w: load per unit contact length [N/m] (W/L).
        R: reduced radius [m].
        E_r: reduced modulus E' [Pa].

    Returns:
        b [m].

    Reference: Ball (1988) eq. 3.9 (with w = W/L). Check: w = 2e5 N/m, R = 5 mm,
    E' = 230.77 GPa gives b = 105.0 um.
    """
    w, R, E_r = non_negative("w", w), radius("R", R), positive("E_r", E_r)
    return out(np.sqrt(8.0 * w * R / (np.pi * E_r)))


def hertz_line_max_pressure(w, R, E_r):
    r"""Hertz maximum pressure of a line contact, :math:`p_{max} = \sqrt{w E' / (2\pi R)}`.

    Equivalent to Ball (1988) eq. 3.10, p_max = 2W/(pi L b), with eq. 3.9 for b.

    Args:
        w: load per unit length [N/m]; R: reduced radius [m]; E_r: reduced modulus [Pa].

    Returns:
        p_max [Pa].
    """
    w, R, E_r = non_negative("w", w), radius("R", R), positive("E_r", E_r)
    return out(np.sqrt(w * E_r / (2.0 * np.pi * R)))


def hertz_line(W, R, E_r, L=None) -> HertzLine:
    r"""Line-contact Hertz solution: half-width, maximum pressure and load per unit length.

    .. math:: b = \left[\frac{8 W R}{\pi L E'}\right]^{1/2},\qquad
              p_{max} = \frac{2W}{\pi L b},\qquad p(x) = p_{max}\sqrt{1 - x^2/b^2}

    Args:
        W: load [N] over the contact length ``L``; when ``L`` is None, ``W`` is already the load
            per unit length [N/m].
        R: reduced radius [m], 0 < R < inf.
        E_r: reduced modulus E' [Pa].
        L: contact length [m] (cam width), optional.

    Returns:
        :class:`HertzLine` (half_width [m], max_pressure [Pa], load_per_length [N/m]).

    Validity: elastic half-spaces, b << R and b << L; frictionless. Reference: Ball (1988)
    eqs. 3.8-3.10.
    """
    w = non_negative("W", W)
    if L is not None:
        w = w / positive("L", L)
    return HertzLine(hertz_line_half_width(w, R, E_r), hertz_line_max_pressure(w, R, E_r), out(w))


class HertzPoint(NamedTuple):
    a_x: object  #: semi-axis along x (the direction of R_x) [m]
    a_y: object  #: semi-axis along y [m]
    max_pressure: object  #: p_max = 3W/(2 pi a_x a_y) [Pa]
    ellipticity: object  #: k = a_y / a_x [-]
    ellipe: object  #: complete elliptic integral of the second kind used [-]
    ellipk: object  #: complete elliptic integral of the first kind used [-]
    approach: object  #: elastic approach of distant points delta [m]


def _one_minus_gamma(p):
    """1 - Gamma for p = 1/k^2, Gamma = R (1/R_small - 1/R_big) the curvature difference.

    With m = 1 - p, Gamma = [(k^2+1)E - 2K] / [(k^2-1)E]; rearranged as
    1 - Gamma = 2 p (K - E) / (m E) = (2/3) p R_D(0, p, 1) / E(m), using K - E = (m/3) R_D(0, 1-m, 1)
    (DLMF 19.25.1), which has no cancellation at either end (p -> 0 line-like, p -> 1 circular).
    """
    from scipy.special import ellipe, elliprd

    return (2.0 / 3.0) * p * elliprd(0.0, p, 1.0) / ellipe(1.0 - p)


def ellipticity_exact(Rx, Ry):
    r"""Exact Hertz ellipticity k = a_y/a_x from the principal reduced radii.

    Solves the Hertz transcendental equation (Hamrock & Dowson 1981, ch. 3; Johnson 1985
    eq. 4.39 in another notation) with complete elliptic integrals of modulus parameter
    m = 1 - 1/k^2 (larger/smaller semi-axis convention):

    .. math:: R\left(\frac{1}{R_{small}} - \frac{1}{R_{big}}\right) =
              \frac{(k^2+1)\,\mathcal{E} - 2\mathcal{F}}{(k^2-1)\,\mathcal{E}}

    by bisection on ln(1/k^2) (60 halvings: relative error ~1e-16, robust for ratios up to
    ~1e12). The major axis lies along the direction of the larger reduced radius, so k >= 1 when
    R_y >= R_x and k <= 1 otherwise.

    Returns:
        k [-] (array or float).
    """
    Rx, Ry = radius("Rx", Rx), radius("Ry", Ry)
    Rx, Ry = np.broadcast_arrays(Rx, Ry)
    small, big = np.minimum(Rx, Ry), np.maximum(Rx, Ry)
    target = 2.0 * small / (small + big)  # 1 - Gamma, = 2/(r+1)
    # bracket: 1 - Gamma(p) ~ p ln(1/p) for small p, so p = target/(4 ln(16/target)) is below
    lo = np.log(target) - np.log(4.0 * np.log(16.0 / target)) - 1.0
    hi = np.zeros_like(target)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        too_round = _one_minus_gamma(np.exp(mid)) > target
        hi = np.where(too_round, mid, hi)
        lo = np.where(too_round, lo, mid)
    k_major = np.exp(-0.25 * (lo + hi))
    return out(np.where(Ry >= Rx, k_major, 1.0 / k_major))


def _approx_integrals(r, method):
    """Ellipticity and elliptic-integral curve fits for r = R_big/R_small >= 1."""
    q = np.pi / 2.0 - 1.0
    if method == "hamrock_brewe_1983":
        return r ** (2.0 / np.pi), 1.0 + q / r, np.pi / 2.0 + q * np.log(r)
    if method == "hamrock_dowson_1981":
        return 1.0339 * r**0.6360, 1.0003 + 0.5968 / r, 1.5277 + 0.6023 * np.log(r)
    if method == "yang_1992":
        return r ** (2.0 / 3.0), 1.0 + q / r, np.pi / 2.0 + q * np.log(r)
    raise ValueError(method)


HERTZ_POINT_METHODS = ("exact", "hamrock_brewe_1983", "hamrock_dowson_1981", "yang_1992")


def hertz_point(W, Rx, Ry, E_r, method: str = "exact", ellipticity=None) -> HertzPoint:
    r"""Elliptical (point) Hertz contact: semi-axes, maximum pressure, ellipticity, approach.

    .. math::
        a_{major} = \left(\frac{6 k^2 \mathcal{E} W R}{\pi E'}\right)^{1/3},\quad
        a_{minor} = \left(\frac{6 \mathcal{E} W R}{\pi k E'}\right)^{1/3},\quad
        p_{max} = \frac{3W}{2\pi a_x a_y},\quad
        \delta = \mathcal{F}\left[\frac{9}{2\mathcal{E}R}\left(\frac{W}{\pi k E'}\right)^2
                 \right]^{1/3}

    with 1/R = 1/R_x + 1/R_y and k = a_major/a_minor >= 1 here.

    Methods (``method``):
        * ``"exact"`` (default): k from :func:`ellipticity_exact`, exact complete elliptic
          integrals (scipy ``ellipkm1``, ``ellipe``).
        * ``"hamrock_brewe_1983"``: k = r^(2/pi), E = 1 + (pi/2-1)/r, F = pi/2 + (pi/2-1) ln r,
          r = R_big/R_small (Hamrock & Brewe 1983, ASME J. Lubr. Technol. 105:171). Within ~3 %.
        * ``"hamrock_dowson_1981"``: k = 1.0339 r^0.636, E = 1.0003 + 0.5968/r,
          F = 1.5277 + 0.6023 ln r (Hamrock & Dowson 1981, *Ball Bearing Lubrication*).
        * ``"yang_1992"``: k = r^(2/3) with the Hamrock-Brewe integrals, as Yang (1992)
          eqs. 3.14-3.19 (ESDU 78035) read with the crossed integral labels corrected:
          the second-kind integral goes into the semi-axes. Reproduces Yang's Zeta numbers.

    Ball's printed circular-equivalent formula is :func:`ball_1988_point_max_pressure`.

    Args:
        W: normal load [N] (>= 0).
        Rx, Ry: principal reduced radii [m], each 0 < R < inf (R_x along entrainment, by the
            film formulas' convention). A zero principal curvature is a line contact: use
            :func:`hertz_line`.
        E_r: reduced modulus E' [Pa].
        ellipticity: for ``"exact"``, k = a_major/a_minor >= 1 already solved for these radii
            (``ellipticity_exact(min(Rx, Ry), max(Rx, Ry))``): it depends on the geometry only,
            so a load iteration over a fixed geometry solves it once. None: solved here.

    Returns:
        :class:`HertzPoint`.

    References: Hertz (1881); Hamrock & Dowson (1981) ch. 3; Yang (1992) eqs. 3.12-3.16.
    Check: equal radii give the circular result a^3 = 3 W R_x / (2 E') (R_x the ball radius).
    """
    W = non_negative("W", W)
    Rx, Ry, E_r = radius("Rx", Rx), radius("Ry", Ry), positive("E_r", E_r)
    W, Rx, Ry, E_r = np.broadcast_arrays(W, Rx, Ry, E_r)
    small, big = np.minimum(Rx, Ry), np.maximum(Rx, Ry)
    R = Rx * Ry / (Rx + Ry)
    if method == "exact":
        # R_y argument largest, so k >= 1
        k = arr(ellipticity_exact(small, big) if ellipticity is None else ellipticity)
        p = 1.0 / k**2
        from scipy.special import ellipe, ellipkm1

        E, F = ellipe(1.0 - p), ellipkm1(p)
    elif method in HERTZ_POINT_METHODS:
        k, E, F = _approx_integrals(big / small, method)
    else:
        raise ValueError(f"method must be one of {HERTZ_POINT_METHODS}, got {method!r}")
    a_major = np.cbrt(6.0 * k**2 * E * W * R / (np.pi * E_r))
    a_minor = np.cbrt(6.0 * E * W * R / (np.pi * k * E_r))
    loaded = a_minor > 0
    area = np.where(loaded, a_major * a_minor, 1.0)
    pmax = np.where(loaded, 3.0 * W / (2.0 * np.pi * area), 0.0)
    delta = F * np.cbrt(9.0 / (2.0 * E * R) * (W / (np.pi * k * E_r)) ** 2)
    y_major = Ry >= Rx
    a_x = np.where(y_major, a_minor, a_major)
    a_y = np.where(y_major, a_major, a_minor)
    k_xy = np.where(y_major, k, 1.0 / k)
    return HertzPoint(out(a_x), out(a_y), out(pmax), out(k_xy), out(E), out(F), out(delta))


def ball_1988_point_max_pressure(W, R, E_r):
    r"""Ball's printed maximum Hertz pressure for a domed follower, eq. 3.7.

    .. math:: p_{max} = \frac{E'}{2\pi}\left[\frac{3W}{E' R^2}\right]^{1/3},\qquad
              \frac{1}{R} = \frac{1}{R_x} + \frac{1}{R_y}

    This is the *circular* Hertz result with the equivalent radius R; it is exact for
    R_x = R_y and ignores ellipticity otherwise (it over-predicts p_max for elongated contacts).
    Note: the engineering extraction of Ball's thesis states that (3.7) is 2^(2/3) below exact
    Hertz; that holds only if R is read as the ball radius. With R as printed (the curvature
    sum) the formula equals exact circular Hertz, which the test-suite checks.

    Args:
        W: load [N]; R: equivalent radius (1/R = 1/R_x + 1/R_y) [m]; E_r: reduced modulus [Pa].

    Returns:
        p_max [Pa]. Reference: Ball (1988) eq. 3.7.
    """
    W, R, E_r = non_negative("W", W), radius("R", R), positive("E_r", E_r)
    return out(E_r / (2.0 * np.pi) * np.cbrt(3.0 * W / (E_r * R**2)))


def hertz_point_max_pressure(W, Rx, Ry, E_r, method: str = "exact"):
    """Maximum Hertz pressure of a point contact by any method, including ``"ball_1988"`` [Pa].

    ``method="ball_1988"`` evaluates Ball (1988) eq. 3.7 with 1/R = 1/R_x + 1/R_y; the other
    methods are those of :func:`hertz_point`.
    """
    if method == "ball_1988":
        Rx, Ry = radius("Rx", Rx), radius("Ry", Ry)
        return ball_1988_point_max_pressure(W, Rx * Ry / (Rx + Ry), E_r)
    return hertz_point(W, Rx, Ry, E_r, method).max_pressure
