"""Crank-bearings effect: orbits, films and power of every big-end and main bearing.

Each load diagram of the ``CrankLoads`` product goes through the journal-bearing machinery
(:mod:`camtrain.engine.crank_bearings`): Booker's mobility orbit marched from the bush centre
to a periodic cycle over the engine cycle (Yang 1992 §1.3, eqs 1.12-1.16), the steady-load locus
(eq. 1.13) and Petroff's concentric power (eq. 1.19) beside it, power by the 2 pi or pi shear
film (eqs 1.21-1.22), per bearing and in total. Grooving: ungrooved, central groove (two lands)
or FLAME's partial groove (the mean of the two). Yang's program's half mobility is the
compatibility option ``solver.mobility_factor = "yang1992_program"``.
"""
from __future__ import annotations


def missing(deck) -> list[str]:
    return [] if deck.bearings is not None else ["[bearings.big_end] and [bearings.main]"]


def reason(deck, planned) -> str:
    s = deck.solver
    factor = ("Yang's program's half mobility" if s.mobility_factor == "yang1992_program"
              else "mobility as printed")
    head = (f"{'/'.join(s.methods)}; {s.mobility} mobility, {factor}; {s.film} film; big-end "
            f"{deck.bearings.big_end.grooving}, mains {deck.bearings.main.grooving} grooving")
    if s.methods == ("petroff",):
        return head + " (concentric power, no film model)"
    from camtrain.bearings import JournalBearing
    from camtrain.deck.schema_bearing_model import film_model_options
    from camtrain.tabulate.bearing import model_reason

    options = film_model_options(s, "bearing_")
    parts = []
    for name in ("big_end", "main"):
        b = getattr(deck.bearings, name)
        brg = JournalBearing(b.diameter, b.length, b.clearance, b.viscosity[0],
                             b.groove_width if b.grooving != "none" else 0.0)
        parts.append(f"{name.replace('_', '-')}: {model_reason(brg, options)[1]}")
    return head + "; " + "; ".join(parts)


def run(deck, inputs, result):
    from camtrain.assemble import engine as build
    from camtrain.engine import CrankLoads, solve_crank_bearings
    from camtrain.errors import ConvergenceError
    from camtrain.tabulate.crank_bearing import add_bearing

    loads = inputs[CrankLoads]
    try:
        res = solve_crank_bearings(loads, build.bearing(deck, "big_end"),
                                   build.bearing(deck, "main"), build.solver_options(deck))
    except ConvergenceError as exc:
        text = str(exc).replace("the film model", "solver.bearing_model")
        knobs = "" if "bearing_model" in text else (" (raise solver.max_cycles or "
                                                    "solver.period_tolerance)")
        raise ConvergenceError(f"crank bearings: {text}{knobs}") from None
    for b in res.bearings:
        add_bearing(result, b)
    for method, what in (("dynamic", "mobility orbits"), ("steady", "steady-load locus"),
                         ("petroff", "Petroff, concentric")):
        total = res.total(method)
        if total is not None:
            result.add_metric(f"total_power_{method}", total, "W",
                              f"engine total, every big-end and main ({what})")
    return res
