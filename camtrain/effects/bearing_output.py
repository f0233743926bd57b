"""Shared by the bearing effects (not an effect itself): one bearing's orbit by the deck's
method, and the columns and metrics of an orbit."""
from __future__ import annotations

import numpy as np

from camtrain.bearings import JournalBearing, bearing_orbit, steady_orbit


def solve_bearing(brg: JournalBearing, lx, ly, angles, omega_journal, omega_bearing, *,
                  angle_rate, period, method, film, mobility="exact", terms="shear",
                  tol=1e-7, period_tol=1e-5, max_cycles=20, start="steady"):
    """JournalOrbit for ``method`` mobility or steady; None for petroff (no orbit)."""
    if method == "mobility":
        return bearing_orbit(brg, lx, ly, angles, omega_journal, omega_bearing,
                             angle_rate=angle_rate, period=period, film=film, terms=terms,
                             mobility=mobility, tol=tol, period_tol=period_tol,
                             max_cycles=max_cycles, start=start)
    if method == "steady":
        return steady_orbit(brg, lx, ly, angles, omega_journal, omega_bearing,
                            angle_rate=angle_rate, period=period, film=film, terms=terms)
    return None


def add_orbit(res, orbit, component: str | None, what: str) -> None:
    """Columns and metrics of one orbit (``eccentricity`` etc.) of a result component."""
    from functools import partial

    col = partial(res.add_column, component=component)
    met = partial(res.add_metric, component=component)
    col("eccentricity", orbit.eccentricity, "-",
                   f"{what}: eccentricity ratio")
    col("attitude", orbit.attitude, "rad",
                   f"{what}: attitude angle from the load to the line of centres")
    col("min_film", orbit.h_min, "m", f"{what}: minimum film c (1 - eps)")
    col("min_film_position", orbit.position, "rad",
                   f"{what}: direction of the minimum film in the bearing frame")
    col("power", orbit.power, "W", f"{what}: friction power ({orbit.film} "
                   "film)")
    i = int(np.argmax(orbit.eccentricity))
    met("max_eccentricity", orbit.eccentricity[i], "-",
                   f"{what}: largest eccentricity ratio", orbit.angle[i])
    met("min_film", orbit.min_film, "m",
                   f"{what}: smallest film; angle = where on the cycle", orbit.min_film_angle)
    met("min_film_position", orbit.min_film_position, "rad",
                   f"{what}: direction of the smallest film in the bearing frame")
    met("power_mean", orbit.mean_power, "W",
                   f"{what}: cycle-mean friction power ({orbit.method}, {orbit.film} film)")
    met("cycles", orbit.cycles, "-", f"{what}: load cycles marched")
