"""Journal-bearing effect: the one effect of a stand-alone ``kind = "journal_bearing"`` deck.

One plain bearing under its periodic load diagram: orbit by the deck's method (Booker mobility,
steady-load locus or Petroff) with the deck's film model (``solver.model``: short, finite or
auto, :mod:`camtrain.bearings.models`), columns on the load-diagram grid
(:mod:`camtrain.bearings`).
"""
from __future__ import annotations


def missing(deck) -> list[str]:
    return []


def _journal(deck):
    from camtrain.bearings import JournalBearing

    g = deck.bearing
    return JournalBearing(g.diameter, g.length, g.clearance, g.viscosity, g.groove_width)


def reason(deck, planned) -> str:
    head = f"stand-alone bearing deck: {deck.solver.method} method, {deck.solver.film} film"
    if deck.solver.method == "petroff":
        return head + " (concentric power, no film model)"
    from camtrain.deck.schema_bearing_model import film_model_options
    from camtrain.tabulate.bearing import model_reason

    brg = _journal(deck)
    return head + "; " + model_reason(brg, film_model_options(deck.solver),
                                      _largest_load_sommerfeld(deck, brg))[1]


def _largest_load_sommerfeld(deck, brg) -> float:
    """Steady Sommerfeld number of one land at the largest load of the diagram (the load is
    shared by the lands; N from the mean of journal and bush speeds, so a fixed bush gives the
    journal speed)."""
    import math

    from camtrain.bearings.validity import steady_sommerfeld

    ld, s = deck.load, deck.speed
    load = max(math.hypot(x, y) for x, y in zip(ld.load_x, ld.load_y, strict=True))
    lands = 2 if brg.grooved else 1
    return steady_sommerfeld(brg.diameter, brg.land, brg.clearance, brg.viscosity,
                             abs(s.journal + s.bearing) / (2.0 * math.pi), load / lands)


def run(deck, inputs, result):
    import math

    import numpy as np

    from camtrain.bearings import bearing_petroff_power
    from camtrain.bearings.product import BearingOrbits
    from camtrain.deck.schema_bearing_model import film_model_options
    from camtrain.tabulate.bearing import (
        BEARING_DECK_TERMS,
        add_orbit,
        deck_terms,
        model_reason,
        solve_bearing,
    )

    s, ld, sol = deck.speed, deck.load, deck.solver
    brg = _journal(deck)
    options = film_model_options(sol)
    angles = np.asarray(ld.angles)
    lx, ly = np.asarray(ld.load_x), np.asarray(ld.load_y)
    result.add_axis("angle", angles, "rad", "load-diagram angle of the journal")
    result.add_column("load_x", lx, "N", "load on the film, x")
    result.add_column("load_y", ly, "N", "load on the film, y")
    petroff = float(bearing_petroff_power(brg, s.journal, s.bearing))
    result.add_metric("petroff_power", petroff, "W", "Petroff power (concentric journal)")
    with deck_terms(BEARING_DECK_TERMS):
        orbit = solve_bearing(brg, lx, ly, angles, s.journal, s.bearing,
                              angle_rate=abs(s.journal), period=ld.period, method=sol.method,
                              film=sol.film, mobility=sol.mobility, terms=sol.terms,
                              tol=sol.step_tolerance, period_tol=sol.period_tolerance,
                              max_cycles=sol.max_cycles, start=sol.start, options=options)
    if orbit is None:
        result.add_metric("power_mean", petroff, "W", "Petroff power (method = petroff)")
        return BearingOrbits((None,))
    add_orbit(result, orbit, None, "bearing", model_reason(brg, options)[0])
    result.add_metric("attitude_mean", float(np.mean(orbit.attitude)), "rad",
                      "mean attitude angle over the load diagram")
    result.add_metric("periodicity_error", orbit.periodicity_error, "-",
                      "largest cycle-to-cycle change of eps at the end")
    result.add_metric("petroff_ratio", orbit.mean_power / petroff if petroff else math.nan, "-",
                      "mean power / Petroff power")
    if not petroff:
        result.warn("petroff_ratio is undefined (NaN): the Petroff power is 0 because the journal "
                    "and the bush turn at the same speed (speed.journal = speed.bearing), so no "
                    "film is sheared")
    return BearingOrbits((orbit,))
