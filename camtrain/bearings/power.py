"""Friction power of a plain journal bearing: Petroff, steady (Martin 1985) and over an orbit.

Yang (1992) §1.4, eqs 1.18-1.25; Ball (1988) eq. 6.7. The Couette (shear) term is
``(eta r^3 b / c) J (omega_j - omega_b)^2`` with one of two shear integrals ``J``:

* ``film="2pi"``: complete film, ``J = 2 pi / sqrt(1 - eps^2)`` (Martin 1985; Yang eqs 1.18,
  1.22). This is **Ball's bearing power, eq. 6.7** (he calls it an overestimate).
* ``film="pi"``: shear over the loaded (pressure) pi film only, Booker's (1965)
  ``J = int 1/(1 + eps cos)`` over that half (Yang eq. 1.21); about half the 2 pi value.

(Martin's steady pi film with shear in both regions, Yang eq. 1.17, is a third formula; it is
``camtrain.formulas.martin_1985_shear_power(..., film="pi")`` and is not used for orbits.)
The "all terms" option adds the translatory term ``W . V`` in the frame turning at wbar
(eq. 1.23, where the pressure term vanishes). Grooving enters through the shear length
(sum of lands) held by :class:`~camtrain.bearings.geometry.JournalBearing`.
"""
from __future__ import annotations

import numpy as np

from camtrain.errors import field_error
from camtrain.formulas.bearings import petroff_power

from .geometry import JournalBearing
from .mobility import film_factors

__all__ = ["FILMS", "TERMS", "bearing_petroff_power", "shear_power", "check_film", "check_terms"]

FILMS = ("pi", "2pi")
TERMS = ("shear", "all")


def check_film(film: str) -> str:
    if film not in FILMS:
        raise field_error("film", "unknown film model", film, " or ".join(FILMS),
                          "'2pi' (complete film; Yang eq. 1.22 = Ball eq. 6.7) reproduces Yang (1992) "
                          "Tables 2.1-2.4 and 4.1; 'pi' is Booker's loaded pi film (Yang eq. 1.21)")
    return film


def check_terms(terms: str) -> str:
    if terms not in TERMS:
        raise field_error("terms", "unknown power terms", terms, " or ".join(TERMS))
    return terms


def bearing_petroff_power(bearing: JournalBearing, omega_journal, omega_bearing=0.0):
    """Petroff power [W] of a concentric bearing, 2 pi eta r^3 b_shear (omega_j - omega_b)^2 / c.

    Yang (1992) eq. 1.19 with b = sum of lands when grooved (his Tables 2.1-2.4, 4.1 Petroff
    columns; the relative speed is the engine or camshaft speed). Reuses
    :func:`camtrain.formulas.bearings.petroff_power`.
    """
    rel = np.asarray(omega_journal, dtype=float) - np.asarray(omega_bearing, dtype=float)
    return petroff_power(bearing.viscosity, rel, bearing.radius, bearing.shear_length,
                         bearing.clearance)


def shear_power(bearing: JournalBearing, eps, delta, omega_rel, film: str = "2pi") -> np.ndarray:
    """Couette shear power [W] for eccentricity ratios ``eps`` (Yang eq. 1.20 shear term with
    J from eq. 1.22 for ``film="2pi"`` (= Ball eq. 6.7) or eq. 1.21 for ``film="pi"``).

    Args:
        eps: eccentricity ratio(s), 0 <= eps < 1.
        delta: squeeze-velocity direction from the line of centres [rad]; fixes the pi-film
            window (ignored for "2pi"). -pi/2 for pure rotation with wbar > 0.
        omega_rel: omega_journal - omega_bearing [rad/s].
    """
    eps = np.atleast_1d(np.asarray(eps, dtype=float))
    delta = np.broadcast_to(np.asarray(delta, dtype=float), eps.shape)
    j = film_factors(eps, delta, film)
    return bearing.shear_coefficient * j * np.asarray(omega_rel, dtype=float) ** 2
