"""Plain journal bearings under dynamic load: short-bearing (Ocvirk) pi film, Booker's mobility
orbit, the steady-load approximation and friction power (Petroff, Martin 1985, Yang 1992); and
the finite-length Reynolds film over the whole bearing (:mod:`.reynolds`, :mod:`.finite`; imported
on use, they need scipy.sparse).

Stand-alone use: a load diagram in, an orbit out (:func:`journal_orbit`); engine and camshaft
bearings build a :class:`JournalBearing` and call :func:`bearing_orbit` or :func:`steady_orbit`.
"""
from .geometry import JournalBearing
from .mobility import mobility_booker, mobility_exact
from .orbit import EPS_LIMIT, bearing_orbit, journal_orbit
from .power import bearing_petroff_power, shear_power
from .result import JournalOrbit
from .steady import steady_eccentricity, steady_eccentricity_vector, steady_orbit

__all__ = ["JournalBearing", "JournalOrbit", "bearing_orbit", "journal_orbit", "steady_orbit",
           "steady_eccentricity", "steady_eccentricity_vector", "bearing_petroff_power",
           "shear_power", "mobility_exact", "mobility_booker", "EPS_LIMIT"]
