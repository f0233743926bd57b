"""Friction effect: cam/follower friction force and coefficient around the cycle, every pair.

Physics: the pair's :class:`camtrain.contact.model.CamContact` on the planned Hertz field and
film (the same contact model the friction/load iteration uses): Newtonian Barus shear over the Hertz zone
capped by boundary friction (Ball 1988 eqs. 4.4-4.7, §4.2.3.4; Yang 1992 eq. 3.24), or the
Greenwood-Tripp mixed model (Teodorescu et al. 2005), by ``tribology.friction_model``.
"""
from __future__ import annotations

from camtrain.metric_rows import CaseMetric, count, one_case


def missing(deck) -> list[str]:
    return []


def reason(deck, planned) -> str:
    return "Hertz zone and film available"


def friction_metrics(load, force, boundary_friction, tag: str = "") -> list:
    """Share of the loaded angles at the boundary friction limit, for a run or every case of
    a sweep batch (:class:`camtrain.metric_rows.CaseMetric`); ``load`` >= 0."""
    import numpy as np


    pos = load > 0.0
    capped = pos & (force >= boundary_friction * load * (1.0 - 1e-12))
    loaded = count(pos)
    share = count(capped) / (max(loaded, 1) if load.ndim == 1 else np.maximum(loaded, 1))
    return [CaseMetric("boundary_fraction", share, "-",
                       "share of loaded angles at the boundary friction limit" + tag)]


def run(deck, inputs, res):
    import numpy as np

    from camtrain.components import pair_label, result_component
    from camtrain.contact.model import CamContact
    from camtrain.contact.products import ContactFilm, ContactFriction, ContactHertz
    from camtrain.loads.product import ContactLoad
    from camtrain.mechanisms.base import TrainKinematics

    train, loads = inputs[TrainKinematics], inputs[ContactLoad]
    hertz, films = inputs[ContactHertz], inputs[ContactFilm]
    fields = []
    for component, load in loads.pairs():
        contact = CamContact.from_deck(deck, component)
        tag = pair_label(component)
        name = result_component(component)
        load = np.maximum(load, 0.0)
        field = contact.friction(train[component], load, hertz[component], films[component])
        fields.append((component, field))
        force = field.force
        pos = load > 0.0
        mu = np.divide(force, load, out=np.zeros(load.shape), where=pos)
        res.add_columns((
            ("friction_force", force, "N",
             f"cam/follower friction force ({contact.friction_law} model){tag}"),
            ("friction_coefficient", mu, "-", "friction coefficient F/W (0 unloaded)" + tag)),
            name)
        res.add_metrics(one_case(friction_metrics(load, force,
                                                  contact.tribology.boundary_friction, tag)),
                        name)
        skipped = pos & ~(field.used | np.isnan(hertz[component].pmax))
        if np.count_nonzero(skipped):
            res.warn(f"friction_force not computed{tag} at {int(skipped.sum())} loaded angles "
                     "where the Hertz stress or the film is not finite: friction, torque and "
                     "power_loss_mean count 0 there and understate the loss")
        if np.count_nonzero(np.isfinite(force)) != force.size:
            res.warn(f"friction force not finite at some angles{tag} (uncapped lambda model)")
    return ContactFriction(tuple(fields), model=CamContact.from_deck(deck).friction_law)


#: deck fields the contact model holds (the Greenwood-Tripp law reads them unselected)
_CONTACT_FIELDS = ("cam.width", "lubricant.", "tribology.", "materials.")


def cases_refused(deck, swept: tuple[str, ...]) -> str:
    """Why :func:`run_cases` cannot take this deck's cases ("" when it can)."""
    if deck.tribology.friction_model == "greenwood_tripp" and any(
            p.startswith(_CONTACT_FIELDS) for p in swept):
        return "the greenwood_tripp friction law with a swept contact parameter"
    return ""


def run_cases(deck, inputs, cases):
    """:func:`run` over a leading case axis (:class:`camtrain.assemble.cases.Cases`): the main
    pair's friction of every case by its contact model, and the metrics."""
    from camtrain.components import MAIN
    from camtrain.contact.products import ContactFilm, ContactFriction, ContactHertz
    from camtrain.loads.product import ContactLoad
    from camtrain.mechanisms.base import TrainKinematics

    load = inputs[ContactLoad].carried
    contact = cases.contact
    field = contact.friction(inputs[TrainKinematics].main, load, inputs[ContactHertz].main,
                             inputs[ContactFilm].main)
    cases.add_metrics(friction_metrics(load, field.force, cases.scalars["boundary_friction"]))
    return ContactFriction(((MAIN, field),), model=contact.friction_law)
