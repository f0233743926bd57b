"""Bearing effects: camshaft bearing loads and orbits, and the stand-alone journal-bearing deck.

Camshaft (``bearings`` effect): the lobe forces of the camshaft effect and the drive hub load
(:func:`camtrain.camshaft.pulley_load`, from the summed torque) are shared between the bearings
as statically determinate beams (Ball 1988 §6.3; Yang 1992 §3.3.1, Fig. 3.6). Each bearing's
load diagram over one camshaft revolution then gives the journal orbit by Booker's mobility
method with the short-bearing pi film (Yang eqs 1.12-1.16; Ball eqs 6.1-6.6), marched until
periodic; or the steady-load locus (Yang eq. 1.13); or Petroff's concentric power (eq. 1.19).
Power uses the pi or 2 pi shear film (Yang eqs 1.21, 1.22).
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.bearings import JournalBearing, bearing_orbit, bearing_petroff_power, steady_orbit
from camtrain.camshaft import pulley_load, split_beam_loads
from camtrain.errors import ConvergenceError

TWO_PI = 2.0 * math.pi


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


def bearing_loads(deck, state):
    """Loads on every camshaft bearing's film, (n_bearings, n_angles) each for x and y [N]."""
    cs, shaft = deck.camshaft, state.objects["camshaft"]
    positions = [lobe.position for lobe in shaft["lobes"]]
    fx = [f[0] for f in shaft["lobe_forces"]]
    fy = [f[1] for f in shaft["lobe_forces"]]
    if cs.drive is not None:
        hx, hy = pulley_load(shaft["torque"], cs.drive.radius, cs.drive.hub_load_angle,
                             cs.drive.preload)
        positions.append(cs.drive.position)
        fx.append(hx)
        fy.append(hy)
    else:
        state.result.warn("no [camshaft.drive]: the drive hub load is left out, so the bearing "
                          "next to the drive is under-loaded")
    n = state.result["cam_angle"].size
    if not positions:
        zero = np.zeros((len(cs.bearings), n))
        return zero, zero.copy()
    return split_beam_loads([b.position for b in cs.bearings], positions, np.array(fx),
                            np.array(fy), cs.overhang)


def run(deck, state) -> None:
    cs, res = deck.camshaft, state.result
    theta = res["cam_angle"]
    omega = state.objects["camshaft"]["omega"]  # signed by the shaft rotation
    viscosity = cs.viscosity if cs.viscosity is not None else deck.lubricant.viscosity
    bx, by = bearing_loads(deck, state)
    orbits, total = [], 0.0
    for i, b in enumerate(cs.bearings):
        k = i + 1
        what = f"bearing {k}"
        brg = JournalBearing(b.diameter, b.length, b.clearance, viscosity, b.groove_width,
                             name=f"camshaft.bearings[{i}]")
        res.add_column(f"bearing_{k}_load_x", bx[i], "N", f"{what}: load on the film, x")
        res.add_column(f"bearing_{k}_load_y", by[i], "N", f"{what}: load on the film, y")
        mag = np.hypot(bx[i], by[i])
        j = int(np.argmax(mag))
        res.add_metric(f"bearing_{k}_max_load", mag[j], "N", f"{what}: largest load", theta[j])
        petroff = float(bearing_petroff_power(brg, omega))
        res.add_metric(f"bearing_{k}_petroff_power", petroff, "W",
                       f"{what}: Petroff power (concentric journal)")
        try:
            orbit = solve_bearing(brg, bx[i], by[i], theta, omega, 0.0, angle_rate=abs(omega),
                                  period=TWO_PI, method=cs.method, film=cs.film,
                                  mobility=cs.mobility, tol=min(1e-7, 1e-2 * cs.bearing_tolerance),
                                  period_tol=cs.bearing_tolerance, max_cycles=cs.max_cycles)
        except ConvergenceError as exc:
            res.warn(f"{what}: {exc}; no orbit reported")
            orbits.append(None)
            continue
        orbits.append(orbit)
        if orbit is None:
            res.add_metric(f"bearing_{k}_power_mean", petroff, "W",
                           f"{what}: Petroff power (method = petroff)")
            total += petroff
            continue
        add_orbit(res, orbit, f"bearing_{k}_", what)
        total += orbit.mean_power
    res.add_metric("bearings_power_total", total, "W",
                   "cycle-mean friction power of all camshaft bearings")
    state.objects["bearing_orbits"] = orbits


def run_bearing_deck(deck, result) -> None:
    """Stand-alone ``kind = "journal_bearing"`` deck: columns on the load-diagram grid."""
    g, s, ld, sol = deck.bearing, deck.speed, deck.load, deck.solver
    brg = JournalBearing(g.diameter, g.length, g.clearance, g.viscosity, g.groove_width)
    angles = np.asarray(ld.angles)
    lx, ly = np.asarray(ld.load_x), np.asarray(ld.load_y)
    result.add_column("angle", angles, "rad", "load-diagram angle of the journal")
    result.add_column("load_x", lx, "N", "load on the film, x")
    result.add_column("load_y", ly, "N", "load on the film, y")
    petroff = float(bearing_petroff_power(brg, s.journal, s.bearing))
    result.add_metric("petroff_power", petroff, "W", "Petroff power (concentric journal)")
    orbit = solve_bearing(brg, lx, ly, angles, s.journal, s.bearing, angle_rate=abs(s.journal),
                          period=ld.period, method=sol.method, film=sol.film,
                          mobility=sol.mobility, terms=sol.terms, tol=sol.step_tolerance,
                          period_tol=sol.period_tolerance, max_cycles=sol.max_cycles,
                          start=sol.start)
    if orbit is None:
        result.add_metric("power_mean", petroff, "W", "Petroff power (method = petroff)")
        return
    add_orbit(result, orbit, "", "bearing")
    result.add_metric("attitude_mean", float(np.mean(orbit.attitude)), "rad",
                      "mean attitude angle over the load diagram")
    result.add_metric("periodicity_error", orbit.periodicity_error, "-",
                      "largest cycle-to-cycle change of eps at the end")
    result.add_metric("petroff_ratio", orbit.mean_power / petroff if petroff else math.nan, "-",
                      "mean power / Petroff power")
