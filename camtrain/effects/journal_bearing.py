"""Journal-bearing effect: the one effect of a stand-alone ``kind = "journal_bearing"`` deck.

One plain bearing under its periodic load diagram: orbit by the deck's method (Booker mobility,
steady-load locus or Petroff), columns on the load-diagram grid (:mod:`camtrain.bearings`).
"""
from __future__ import annotations


def missing(deck) -> list[str]:
    return []


def reason(deck, planned) -> str:
    return (f"stand-alone bearing deck: {deck.solver.method} method, {deck.solver.film} film")


def run(deck, inputs, result):
    import math

    import numpy as np

    from camtrain.bearings import JournalBearing, bearing_petroff_power
    from camtrain.bearings.product import BearingOrbits
    from camtrain.effects.bearing_output import add_orbit, solve_bearing

    g, s, ld, sol = deck.bearing, deck.speed, deck.load, deck.solver
    brg = JournalBearing(g.diameter, g.length, g.clearance, g.viscosity, g.groove_width)
    angles = np.asarray(ld.angles)
    lx, ly = np.asarray(ld.load_x), np.asarray(ld.load_y)
    result.add_axis("angle", angles, "rad", "load-diagram angle of the journal")
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
        return BearingOrbits((None,))
    add_orbit(result, orbit, None, "bearing")
    result.add_metric("attitude_mean", float(np.mean(orbit.attitude)), "rad",
                      "mean attitude angle over the load diagram")
    result.add_metric("periodicity_error", orbit.periodicity_error, "-",
                      "largest cycle-to-cycle change of eps at the end")
    result.add_metric("petroff_ratio", orbit.mean_power / petroff if petroff else math.nan, "-",
                      "mean power / Petroff power")
    return BearingOrbits((orbit,))
