"""Shared by the bearing effects (not an effect itself): one bearing's orbit by the deck's
method, and the columns and metrics of an orbit."""
from __future__ import annotations

from contextlib import contextmanager
from dataclasses import replace

import numpy as np

from camtrain.bearings import JournalBearing, bearing_orbit, steady_orbit


def model_reason(brg: JournalBearing, options, sommerfeld=None) -> tuple[str, str]:
    """(film model used, the plan's sentence) for ``options`` (a FilmModelOptions);
    ``sommerfeld`` of a land at the largest load when the deck gives the loads."""
    from camtrain.bearings.models import choose_model

    used, why = choose_model(brg, options.model, sommerfeld=sommerfeld)
    if used == "finite":
        why += f" ({options.cavitation} cavitation, mesh {options.n_theta} x {options.n_z})"
    return used, why


def solve_bearing(brg: JournalBearing, lx, ly, angles, omega_journal, omega_bearing, *,
                  angle_rate, period, method, film, mobility="exact", terms="shear",
                  tol=1e-7, period_tol=1e-5, max_cycles=20, start="steady", options=None,
                  march_points=None):
    """JournalOrbit for ``method`` mobility or steady; None for petroff (no orbit).

    ``options`` (a FilmModelOptions; None = the short model) picks the film through
    :func:`camtrain.bearings.models.choose_model`: the short pi film or the finite-length
    Reynolds film (its mobility map, or its steady curve). ``march_points``: the orbit's own
    load grid (:func:`camtrain.bearings.bearing_orbit`), None: the diagram's."""
    from camtrain.bearings.models import finite_steady_orbit, orbit_mobility

    used = "short" if options is None else model_reason(brg, options)[0]
    if method == "mobility":
        if used == "finite":
            mobility = orbit_mobility(brg, used, mobility, options.cavitation,
                                      options.n_theta, options.n_z)
        return bearing_orbit(brg, lx, ly, angles, omega_journal, omega_bearing,
                             angle_rate=angle_rate, period=period, film=film, terms=terms,
                             mobility=mobility, tol=tol, period_tol=period_tol,
                             max_cycles=max_cycles, start=start, march_points=march_points)
    if method == "steady":
        if used == "finite":
            return finite_steady_orbit(brg, lx, ly, angles, omega_journal, omega_bearing,
                                       angle_rate=angle_rate, period=period, film=film,
                                       terms=terms, cavitation=options.cavitation,
                                       n_theta=options.n_theta, n_z=options.n_z)
        return steady_orbit(brg, lx, ly, angles, omega_journal, omega_bearing,
                            angle_rate=angle_rate, period=period, film=film, terms=terms)
    return None


def add_orbit(res, orbit, component: str | None, what: str, model: str = "short") -> None:
    """Columns and metrics of one orbit (``eccentricity`` etc.) of a result component; the
    film ``model`` used is named in the metric descriptions."""
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
        f"{what}: smallest film ({model} film model); angle = where on the cycle",
        orbit.min_film_angle)
    met("min_film_position", orbit.min_film_position, "rad",
                   f"{what}: direction of the smallest film in the bearing frame")
    met("power_mean", orbit.mean_power, "W",
                   f"{what}: cycle-mean friction power ({model} film model, {orbit.method}, "
        f"{orbit.film} film)")
    met("cycles", orbit.cycles, "-", f"{what}: load cycles marched")


#: the symbols of the bearing physics, as a stand-alone bearing deck names them: problem paths
#: (``omega``, ``load``) and the symbols in messages and hints
BEARING_DECK_TERMS = {
    "omega": "speed.journal, speed.bearing", "load": "load.load_x, load.load_y",
    "angle_rate": "speed.journal",
    "(omega_j + omega_b)/2": "the mean of speed.journal and speed.bearing",
    "period_tol": "solver.period_tolerance", "max_cycles": "solver.max_cycles",
    "loosen tol": "loosen solver.step_tolerance",
    "the film model": "solver.model",
}
#: ... and as the [camshaft] section of a valve-train deck names them
CAMSHAFT_DECK_TERMS = {
    "omega": "speed", "angle_rate": "speed", "(omega_j + omega_b)/2": "the camshaft speed",
    "period_tol": "camshaft.bearing_tolerance", "max_cycles": "camshaft.max_cycles",
    "loosen tol": "loosen camshaft.bearing_tolerance",
    "the film model": "camshaft.bearing_model",
}
#: symbols replaced inside messages (the others are only ever a problem's path)
_IN_TEXT = ("(omega_j + omega_b)/2", "period_tol", "max_cycles", "loosen tol", "the film model")


def _in_deck_terms(text: str, terms: dict[str, str]) -> str:
    for symbol in _IN_TEXT:
        if symbol in terms:
            text = text.replace(symbol, terms[symbol])
    return text


@contextmanager
def deck_terms(terms: dict[str, str], load_path: str | None = None):
    """Errors of the bearing physics re-raised in the deck's words: a problem named ``omega``
    or ``load`` names the deck fields it came from, and a hint names the deck's solver knob."""
    from camtrain.errors import ConvergenceError, InputError

    fields = dict(terms, **({"load": load_path} if load_path else {}))
    try:
        yield
    except InputError as exc:
        problems = [replace(p, path=fields.get(p.path, p.path),
                            message=_in_deck_terms(p.message, fields),
                            hint=_in_deck_terms(p.hint, fields)) for p in exc.problems]
        raise InputError(problems, source=exc.source) from None
    except ConvergenceError as exc:
        raise ConvergenceError(_in_deck_terms(str(exc), fields)) from None
