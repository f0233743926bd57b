"""Hertz effect: contact half-width and maximum pressure of every loaded pair.

Physics: the pair's :class:`camtrain.contact.model.CamContact` (Ball 1988 eqs. 3.7-3.10, Hamrock &
Dowson 1981). Writes ``hertz_pmax``, ``hertz_half_width`` (and ``hertz_half_length`` for a point
contact) per pair; the closing pair of a desmodromic train is the result's ``closing`` component.
"""
from __future__ import annotations

from camtrain.metric_rows import CaseMetric, at, one_case


def missing(deck) -> list[str]:
    return [] if deck.cam.width is not None else ["cam.width"]


def reason(deck, planned) -> str:
    return "contact load and cam width available"


def run(deck, inputs, res):
    import numpy as np

    from camtrain.components import pair_label, result_component
    from camtrain.contact.model import CamContact
    from camtrain.contact.products import ContactHertz
    from camtrain.loads.product import ContactLoad
    from camtrain.mechanisms.base import TrainKinematics

    train, loads = inputs[TrainKinematics], inputs[ContactLoad]
    fields = []
    for component, load in loads.pairs():
        kin = train[component]
        name = result_component(component)
        hz = CamContact.from_deck(deck, component).hertz(kin, np.maximum(load, 0.0))
        fields.append((component, hz))
        tag = pair_label(component)
        columns = [("hertz_pmax", hz.pmax, "Pa", "maximum Hertz contact pressure" + tag),
                   ("hertz_half_width", hz.half_width, "m",
                    "Hertz half-width along the rolling direction" + tag)]
        if not hz.line:
            columns.append(("hertz_half_length", hz.half_length, "m",
                            "Hertz semi-axis across the rolling direction" + tag))
        res.add_columns(columns, name)
        if np.count_nonzero(hz.bad):
            res.warn(f"Hertz contact undefined{tag} (equivalent radius <= 0 or infinite) at "
                     f"{int(hz.bad.sum())} loaded angles; NaN there")
        infinite = hz.pmax == np.inf
        if np.count_nonzero(infinite):
            res.warn(f"hertz_pmax is infinite{tag} at {int(infinite.sum())} loaded "
                     "angles (a vanishing contact radius or width): the contact cannot carry "
                     "the load there")
        res.add_metrics(one_case(hertz_metrics(kin.theta, hz.pmax, kin.nose, tag)), name)
    return ContactHertz(tuple(fields))


def hertz_metrics(theta, pmax, nose: int, tag: str = "") -> list:
    """Largest Hertz pressure (NaN angles skipped) and the one at maximum lift, for a run or
    every case of a sweep batch (:class:`camtrain.metric_rows.CaseMetric`)."""
    import numpy as np


    undefined = np.isnan(pmax)
    p = np.where(undefined, -np.inf, pmax) if np.count_nonzero(undefined) else pmax
    i = p.argmax(axis=-1)
    return [CaseMetric("hertz_max", at(pmax, i), "Pa",
                       "largest Hertz pressure over the cycle" + tag, at(theta, i)),
            CaseMetric("hertz_at_max_lift", at(pmax, nose), "Pa",
                       "Hertz pressure at the maximum-lift position (Ball Tables 5.1-5.3)" + tag,
                       at(theta, nose))]


def run_cases(deck, inputs, cases):
    """:func:`run` over a leading case axis (:class:`camtrain.assemble.cases.Cases`): the main
    pair's Hertz field of every case by its contact model, and the metrics."""
    from camtrain.components import MAIN
    from camtrain.contact.products import ContactHertz
    from camtrain.loads.product import ContactLoad
    from camtrain.mechanisms.base import TrainKinematics

    kin = inputs[TrainKinematics].main
    hz = cases.contact.hertz(kin, inputs[ContactLoad].carried)
    cases.add_metrics(hertz_metrics(kin.theta, hz.pmax, kin.nose))
    return ContactHertz(((MAIN, hz),))
