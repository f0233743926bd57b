"""Film effect: minimum and central EHL film thickness and the film parameter lambda = h/sigma.

Physics: the pair's :class:`camtrain.contact.model.CamContact` and its film law. With a planned
contact load the EHL film of each loaded pair (Ball 1988 eqs. 4.1, 4.2; Hamrock & Dowson 1977
or Chittenden et al. 1985 for point contacts); without, the load-free Blok film (Dowson, Dunn &
Taylor 1983; Ball eq. 4.3). The plan says which, from the products it provides.
"""
from __future__ import annotations


def missing(deck) -> list[str]:
    return [] if deck.lubricant is not None else ["lubricant (viscosity, pressure_viscosity)"]


def reason(deck, planned) -> str:
    if "ContactLoad" in planned:
        return "lubricant given and contact loads planned: EHL film with the contact load"
    return ("lubricant given, no contact loads: Blok rigid-piezoviscous film, "
            "which needs no load (Ball eq. 4.3)")


def run(deck, inputs, res):
    from camtrain.components import MAIN, result_component
    from camtrain.contact.model import CamContact
    from camtrain.contact.products import ContactFilm
    from camtrain.loads import ContactLoad
    from camtrain.mechanisms import TrainKinematics

    train, loads = inputs[TrainKinematics], inputs.get(ContactLoad)
    pairs = loads.pairs() if loads is not None else ((MAIN, None),)
    fields = []
    for component, load in pairs:
        film = run_pair(CamContact.from_deck(deck, component), train[component], load, res,
                        result_component(component))
        fields.append((component, film))
    return ContactFilm(tuple(fields), with_load=loads is not None)


def run_pair(contact, kin, load, res, component: str | None = None):
    """Columns and metrics of one pair's film; returns its FilmField."""
    from functools import partial

    import numpy as np

    from camtrain.formulas import film_parameter

    tag = f" ({component} pair)" if component else ""
    col = partial(res.add_column, component=component)
    met = partial(res.add_metric, component=component)
    film = contact.film(kin, None if load is None else np.maximum(load, 0.0))
    what = "out of contact" if load is not None else "non-Hertzian geometry"
    col("film_min", film.min, "m",
                   f"minimum film thickness, {film.method} (NaN: {what}){tag}")
    if film.central is not None:
        col("film_central", film.central, "m",
                       f"central film thickness, {film.central_method}{tag}")
    lam = np.full(film.min.shape, np.nan)
    fin = np.isfinite(film.min)
    lam[fin] = film_parameter(film.min[fin], contact.lubricant.roughness)
    col("lambda", lam, "-",
                   "film parameter h_min / sigma (< 1: boundary regime)" + tag)
    if np.any(fin):
        h = np.where(fin, film.min, np.inf)
        i = int(np.argmin(h))
        met("film_min", h[i], "m",
                       "smallest minimum film over the cycle" + tag, kin.theta[i])
    k = int(np.argmax(kin.valve_lift))
    met("film_min_at_max_lift", film.min[k], "m",
                   "minimum film at the maximum-lift position (Ball Tables 5.1-5.3)" + tag,
                   kin.theta[k])
    if load is None:
        res.warn("film without contact loads: Blok rigid-piezoviscous film (Ball eq. 4.3)")
    return film
