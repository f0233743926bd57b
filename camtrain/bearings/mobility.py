"""Short (Ocvirk) journal bearing with a half-Sommerfeld pi film: film force and its inverse, the
mobility (Booker 1965).

Frame and symbols (SI). A bush-fixed Cartesian frame; the eccentricity-ratio vector
``eps = (e_x, e_y)/c`` points from the bush centre to the journal centre; the film is thinnest in
that direction. ``wbar = (omega_journal + omega_bearing)/2`` [rad/s], counter-clockwise positive.
``W`` is the load the journal applies to the film (N), i.e. the vector sum of every other force
on the journal; the film pushes back with ``-W``.

Derivation used here (short-bearing Reynolds equation, Yang 1992 eqs 1.6-1.8, Ball 1988 eq 6.1,
written in vectors). With the wall normal ``n(theta)`` and ``H = 1 - eps . n``:

    p = 6 eta (w . n)(b^2/4 - y^2) / (c^2 H^3),   w = d(eps)/dt - wbar z x eps

``w`` is the journal-centre velocity (in clearance units) seen from a frame turning at ``wbar``.
Only ``w . n > 0`` carries pressure (the pi film). Integrating over the land and the film:

    W = k K(eps, w_hat) w,   k = eta b^3 r / c^2,   K = int_{w.n>0} n n^T / H^3 dtheta

``K`` is symmetric positive definite, so the squeeze work ``W . w`` is never negative. Booker's
mobility is the inverse map ``w = K^-1 W / k``; the pi-film window depends on the direction of
``w`` itself, found here by a one-dimensional root (the recipe of Ball 1988 §6.2, "iterating
between eqs 6.2 and 6.3"). The integrals are closed form after the Sommerfeld substitution.
At eps = 0 this gives |w| = 2 W c^2 / (pi eta r b^3), equal to Booker's M = 1/(pi (b/d)^2) in
Yang (1992) eq. 1.12 with the corrected (c/r)^2 group.
"""
from __future__ import annotations

import math

__all__ = ["film_window_integrals", "squeeze_force", "mobility_exact", "mobility_booker",
           "film_factor", "film_factors"]

_TWO_PI = 2.0 * math.pi


def _sommerfeld(beta: float, eps: float) -> float:
    """Monotone Sommerfeld angle gamma(beta) with 1 + eps cos(beta) = (1 - eps^2)/(1 - eps cos gamma).

    gamma(beta + 2 pi) = gamma(beta) + 2 pi; continuous for every beta.
    """
    m = round(beta / _TWO_PI)
    b0 = beta - _TWO_PI * m
    k = math.sqrt((1.0 - eps) / (1.0 + eps))
    return 2.0 * math.atan2(k * math.sin(0.5 * b0), math.cos(0.5 * b0)) + _TWO_PI * m


def film_window_integrals(eps: float, a: float, span: float = math.pi):
    r"""Integrals of cos^2, cos sin, sin^2 over (1 + eps cos beta)^3 for beta in [a, a + span].

    With the Sommerfeld substitution the integrands become trigonometric polynomials in gamma:

    .. math:: \int\frac{\cos^2\beta}{h^3}d\beta = \frac{[\gamma/2+\sin2\gamma/4-2\epsilon\sin\gamma
              +\epsilon^2\gamma]}{(1-\epsilon^2)^{5/2}},\quad
              \int\frac{\cos\beta\sin\beta}{h^3}d\beta=\frac{[\sin^2\gamma/2+\epsilon\cos\gamma]}
              {(1-\epsilon^2)^2},\quad
              \int\frac{\sin^2\beta}{h^3}d\beta=\frac{[\gamma/2-\sin2\gamma/4]}{(1-\epsilon^2)^{3/2}}

    Returns (I_cc, I_cs, I_ss, J) where J = int dbeta / (1 + eps cos beta) (Yang 1992 eq. 1.21).
    """
    g0 = _sommerfeld(a, eps)
    g1 = _sommerfeld(a + span, eps)
    s0, c0, s1, c1 = math.sin(g0), math.cos(g0), math.sin(g1), math.cos(g1)
    q = 1.0 - eps * eps
    dg = g1 - g0
    d2 = 0.5 * (s1 * c1 - s0 * c0)  # [sin 2g / 4]
    icc = (0.5 * dg + d2 - 2.0 * eps * (s1 - s0) + eps * eps * dg) / q ** 2.5
    ics = (0.5 * (s1 * s1 - s0 * s0) + eps * (c1 - c0)) / q ** 2
    iss = (0.5 * dg - d2) / q ** 1.5
    return icc, ics, iss, dg / math.sqrt(q)


def _kd(eps: float, delta: float):
    """K d and det K in the line-of-centres frame for a squeeze direction at angle delta from eps.

    beta is measured from the thickest film (opposite eps); the loaded half is
    beta in [delta + pi/2, delta + 3 pi/2]. n n^T is even in n, so the sign flip is harmless.
    """
    icc, ics, iss, _ = film_window_integrals(eps, delta + 0.5 * math.pi)
    cd, sd = math.cos(delta), math.sin(delta)
    return icc * cd + ics * sd, ics * cd + iss * sd, icc * iss - ics * ics


def squeeze_force(eps: float, delta: float, speed: float) -> tuple[float, float]:
    """Dimensionless film reaction K w for |w| = speed at angle delta from the line of centres.

    Multiply by k = eta b^3 r / c^2 (and c for a dimensional speed) to get newtons.
    Components are along the line of centres and 90 deg ahead of it (counter-clockwise).
    """
    fx, fy, _ = _kd(eps, delta)
    return speed * fx, speed * fy


def mobility_exact(eps: float, tau: float, delta0: float | None = None,
                   tol: float = 1e-13) -> tuple[float, float]:
    """Exact pi-film short-bearing mobility: squeeze direction and size for a unit load.

    Args:
        eps: eccentricity ratio, 0 <= eps < 1.
        tau: load direction measured from the line of centres [rad].
        delta0: warm-start guess of the squeeze direction (e.g. from the previous time step).

    Returns:
        (delta, m): ``w`` points at angle ``delta`` from the line of centres and
        |w| = m W / k. Solved by safeguarded Newton on the angle of K d, whose derivative is
        det K / |K d|^2 > 0 (so the root is unique); the bracket [tau - pi/2, tau + pi/2] always
        holds it because d . K d > 0.
    """
    lo, hi = tau - 0.5 * math.pi, tau + 0.5 * math.pi
    x = tau if delta0 is None or not (lo < delta0 < hi) else delta0
    for _ in range(100):
        fx, fy, det = _kd(eps, x)
        ct, st = math.cos(tau), math.sin(tau)
        g = math.atan2(ct * fy - st * fx, ct * fx + st * fy)  # angle of K d past the load
        if g > 0.0:
            hi = x
        else:
            lo = x
        if abs(g) < tol:
            break
        step = g * (fx * fx + fy * fy) / det
        xn = x - step
        x = xn if lo < xn < hi else 0.5 * (lo + hi)
        if hi - lo < tol:
            break
    fx, fy, _ = _kd(eps, x)
    return x, 1.0 / math.hypot(fx, fy)


def mobility_booker(xi: float, mu: float) -> tuple[float, float]:
    r"""Booker's (1965) closed-form short-bearing mobility for b/d = 1, in the load frame.

    .. math:: M^\xi \approx \frac{(1-\xi)^{5/2}}{\pi},\qquad
              M^\mu \approx -\frac{4\mu(1-\xi)^{3/2}}{\pi^2}

    Yang (1992) eqs 1.15, 1.16 (divide by (b/d)^2). ``xi`` is the eccentricity component along
    the load, ``mu`` the component normal to it, positive in the sense of ``wbar``.
    The velocity is ``w = W (c/r)^2/(eta b d) * (M^xi, M^mu)`` in that frame.
    """
    s = 1.0 - xi
    return s ** 2.5 / math.pi, -4.0 * mu * s ** 1.5 / math.pi ** 2


def film_factor(eps: float, delta: float, film: str) -> float:
    """Shear integral J_1^00: ``"2pi"`` 2 pi/sqrt(1 - eps^2) for a complete film (Martin 1985,
    Yang eq. 1.22; Ball eq. 6.7), or ``"pi"`` Booker's (1965) integral of 1/(1 + eps cos beta)
    over the loaded pi film only (Yang eq. 1.21)."""
    if film == "2pi":
        return _TWO_PI / math.sqrt(1.0 - eps * eps)
    return film_window_integrals(eps, delta + 0.5 * math.pi)[3]


def film_factors(eps, delta, film: str):
    """:func:`film_factor` over arrays of ``eps`` and ``delta`` (same formulas, vectorised: an
    orbit has one value per load-diagram angle)."""
    import numpy as np

    eps = np.asarray(eps, dtype=float)
    if film == "2pi":
        return _TWO_PI / np.sqrt(1.0 - eps * eps)
    k = np.sqrt((1.0 - eps) / (1.0 + eps))

    def gamma(beta):   # _sommerfeld, elementwise
        m = np.round(beta / _TWO_PI)
        b0 = beta - _TWO_PI * m
        return 2.0 * np.arctan2(k * np.sin(0.5 * b0), np.cos(0.5 * b0)) + _TWO_PI * m

    a = np.asarray(delta, dtype=float) + 0.5 * math.pi
    return (gamma(a + math.pi) - gamma(a)) / np.sqrt(1.0 - eps * eps)
