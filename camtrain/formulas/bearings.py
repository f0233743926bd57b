"""Plain journal bearings (camshaft bearings): Petroff / Couette loss and Ocvirk short bearing.

Symbols (SI): eta viscosity [Pa s]; omega relative angular speed journal - bush [rad/s];
R journal radius [m]; L bearing (land) length [m]; c radial clearance [m]; eps = e/c
eccentricity ratio [-], 0 <= eps < 1.
"""
from __future__ import annotations

import numpy as np

from ._util import arr, check, non_negative, out, positive

__all__ = ["petroff_torque", "petroff_power", "martin_1985_shear_power", "ocvirk_load",
           "ocvirk_eccentricity", "ocvirk_attitude_angle", "ocvirk_min_film"]


def _eps(eps):
    return check("eps", eps, lambda v: (v >= 0) & (v < 1), "0 <= eps < 1")


def petroff_torque(eta, omega, R, L, c):
    r"""Petroff friction torque of a concentric journal bearing.

    .. math:: T = \frac{2\pi\eta\,\omega R^3 L}{c}

    Returns:
        T [N m] (sign of omega). Validity: light load (eps ~ 0), full 2 pi film, laminar.
    Reference: Petroff (1883); Yang (1992) eq. 1.19 as torque. Check (formulas_and_anchors
    §4.3): D 25 mm, L 18 mm, c 25 um, eta 0.01, 1500 rev/min gives 13.879 N mm.
    """
    k = positive("eta", eta) * positive("R", R) ** 3 * positive("L", L) / positive("c", c)
    return out(2.0 * np.pi * k * arr(omega))


def petroff_power(eta, omega, R, L, c):
    """Petroff power loss P = T omega = 2 pi eta omega^2 R^3 L / c [W] (Yang 1992 eq. 1.19)."""
    return out(arr(petroff_torque(eta, omega, R, L, c)) * arr(omega))


def martin_1985_shear_power(eta, omega, R, L, c, eps, film: str = "2pi"):
    r"""Couette shear power of an eccentric journal bearing (Martin 1985).

    .. math::
        H_{2\pi} = \frac{\eta R^3 L}{c}\,\frac{2\pi}{\sqrt{1-\epsilon^2}}\,\omega^2,\qquad
        H_{\pi} = \frac{\eta R^3 L}{c}\,\frac{\pi}{\sqrt{1-\epsilon^2}}\,
        \frac{2+\epsilon}{1+\epsilon}\,\omega^2

    Args:
        film: ``"2pi"`` (complete film, shear only; Martin 1985 via Yang eq. 1.18, identical
            to Ball eq. 6.7) or ``"pi"`` (Martin's steady pi film with shear in both the
            converging and diverging regions; Yang eq. 1.17). Not to be confused with the
            orbit power's ``film="pi"`` (Booker's loaded pi film, Yang eq. 1.21, in
            :mod:`camtrain.bearings.power`).

    Returns:
        H [W]; eps = 0 with ``"2pi"`` equals :func:`petroff_power`.
    """
    eps = _eps(eps)
    base = positive("eta", eta) * positive("R", R) ** 3 * positive("L", L) / positive("c", c)
    base = base * arr(omega) ** 2 / np.sqrt(1.0 - eps**2)
    if film == "2pi":
        return out(2.0 * np.pi * base)
    if film == "pi":
        return out(np.pi * base * (2.0 + eps) / (1.0 + eps))
    raise ValueError("film must be '2pi' or 'pi'")


def _ocvirk_shape(eps):
    return eps / (1.0 - eps**2) ** 2 * np.sqrt(np.pi**2 * (1.0 - eps**2) + 16.0 * eps**2)


def ocvirk_load(eta, omega, R, L, c, eps):
    r"""Load capacity of a short (Ocvirk) journal bearing, half-Sommerfeld pi film.

    .. math:: W = \frac{\eta U L^3}{4c^2}\,\frac{\epsilon}{(1-\epsilon^2)^2}
              \sqrt{\pi^2(1-\epsilon^2) + 16\epsilon^2},\qquad U = \omega R

    Validity: L/D < ~0.7 (short-bearing approximation), steady load, stationary bush.
    Reference: Ocvirk (1952) NACA TN 2808; Yang (1992) §1.3.2. Check (formulas_and_anchors
    §4.3): the Petroff example bearing carries 500 N at eps = 0.7165.
    """
    U = positive("omega", omega) * positive("R", R)
    k = positive("eta", eta) * U * positive("L", L) ** 3 / (4.0 * positive("c", c) ** 2)
    return out(k * _ocvirk_shape(_eps(eps)))


def ocvirk_eccentricity(W, eta, omega, R, L, c):
    """Eccentricity ratio of a short bearing carrying ``W`` [N]: inverse of :func:`ocvirk_load`.

    The load shape factor rises monotonically from 0 (eps = 0) to infinity (eps -> 1), so a
    vectorised bisection on eps in [0, 1) is used (64 halvings; |error| < 1e-15).
    """
    W = non_negative("W", W)
    U = positive("omega", omega) * positive("R", R)
    k = positive("eta", eta) * U * positive("L", L) ** 3 / (4.0 * positive("c", c) ** 2)
    target = W / k
    lo, hi = np.zeros_like(target), np.ones_like(target)
    top = np.nextafter(1.0, 0.0)  # keep 1 - eps^2 > 0 even for absurd loads
    for _ in range(64):
        mid = np.minimum(0.5 * (lo + hi), top)
        high = _ocvirk_shape(mid) > target
        hi, lo = np.where(high, mid, hi), np.where(high, lo, mid)
    return out(np.where(target > 0, 0.5 * (lo + hi), 0.0))


def ocvirk_attitude_angle(eps):
    r"""Attitude angle of a short bearing, phi = atan[pi sqrt(1 - eps^2) / (4 eps)] [rad].

    pi/2 at eps = 0. Reference: Ocvirk (1952). Check: eps = 0.7165 gives 37.40 deg.
    """
    eps = _eps(eps)
    return out(np.arctan2(np.pi * np.sqrt(1.0 - eps**2), 4.0 * eps))


def ocvirk_min_film(c, eps):
    """Minimum film thickness h_min = c (1 - eps) [m]."""
    return out(positive("c", c) * (1.0 - _eps(eps)))
