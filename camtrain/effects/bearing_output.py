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


def add_orbit(res, orbit, prefix: str, what: str) -> None:
    """Columns and metrics of one orbit, named ``<prefix>eccentricity`` etc."""
    res.add_column(f"{prefix}eccentricity", orbit.eccentricity, "-",
                   f"{what}: eccentricity ratio")
    res.add_column(f"{prefix}attitude", orbit.attitude, "rad",
                   f"{what}: attitude angle from the load to the line of centres")
    res.add_column(f"{prefix}min_film", orbit.h_min, "m", f"{what}: minimum film c (1 - eps)")
    res.add_column(f"{prefix}min_film_position", orbit.position, "rad",
                   f"{what}: direction of the minimum film in the bearing frame")
    res.add_column(f"{prefix}power", orbit.power, "W", f"{what}: friction power ({orbit.film} "
                   "film)")
    i = int(np.argmax(orbit.eccentricity))
    res.add_metric(f"{prefix}max_eccentricity", orbit.eccentricity[i], "-",
                   f"{what}: largest eccentricity ratio", orbit.angle[i])
    res.add_metric(f"{prefix}min_film", orbit.min_film, "m",
                   f"{what}: smallest film; angle = where on the cycle", orbit.min_film_angle)
    res.add_metric(f"{prefix}min_film_position", orbit.min_film_position, "rad",
                   f"{what}: direction of the smallest film in the bearing frame")
    res.add_metric(f"{prefix}power_mean", orbit.mean_power, "W",
                   f"{what}: cycle-mean friction power ({orbit.method}, {orbit.film} film)")
    res.add_metric(f"{prefix}cycles", orbit.cycles, "-", f"{what}: load cycles marched")
