"""Guides effect: follower/guide and valve/guide shear losses (Yang 1992 §3.3.2, eq. 3.29).

Physics: :func:`camtrain.contact.guides.guide_losses`. Values are per valve train (one follower,
one valve) and are not included in ``power_loss_mean``.
"""
from __future__ import annotations

from camtrain.metric_rows import CaseMetric, one_case


def missing(deck) -> list[str]:
    out = [] if deck.guides is not None else ["[guides] section"]
    if deck.lubricant is None:
        out.append("lubricant (viscosity)")
    return out


def reason(deck, planned) -> str:
    which = "valve guide" + (" and follower guide" if deck.guides.follower_diameter is not None
                             and deck.mechanism.type in ("flat", "domed") else "")
    return f"[guides] and lubricant given: Couette shear of the {which} (Yang 1992 eq. 3.29)"


def guide_metrics(losses) -> list:
    """Cycle-mean power of each guide and their sum (Yang 1992 §3.3.2), for a run or every case
    of a sweep batch (:class:`camtrain.metric_rows.CaseMetric`)."""
    from camtrain.formulas import cycle_mean

    total = 0.0
    out = []
    for name, power in (("follower_guide", losses.follower_guide),
                        ("valve_guide", losses.valve_guide)):
        if power is None:
            continue
        what = name.replace("_", "/")
        mean = cycle_mean(power)
        total = total + mean
        out.append(CaseMetric(f"{name}_power_mean", mean, "W", f"cycle-mean {what} friction "
                              "power, one valve train (Yang 1992 §3.3.2)"))
    out.append(CaseMetric("guide_power_mean", total, "W", "cycle-mean guide friction power, one "
                          "valve train (not included in power_loss_mean)"))
    return out


def run(deck, inputs, res):
    from camtrain.contact.guides import guide_losses
    from camtrain.mechanisms import TrainKinematics

    losses = guide_losses(deck, inputs[TrainKinematics].main)
    for name, power in (("follower_guide", losses.follower_guide),
                        ("valve_guide", losses.valve_guide)):
        if power is not None:
            res.add_column(f"{name}_power", power, "W", f"{name.replace('_', '/')} Couette "
                           "shear power (Yang 1992 eq. 3.29)")
    res.add_metrics(one_case(guide_metrics(losses)))
    if deck.guides.follower_diameter is not None and losses.follower_guide is None:
        res.warn("guides.follower_*: a pivoted follower has no guide; follower/guide friction "
                 "skipped")
    return losses


def run_cases(deck, inputs, cases):
    """:func:`run` over a leading case axis (:class:`camtrain.assemble.cases.Cases`): the
    guides' losses of every case with its lubricant, and the metrics."""
    from types import SimpleNamespace

    from camtrain.contact.guides import guide_losses
    from camtrain.mechanisms import TrainKinematics

    case_deck = SimpleNamespace(guides=deck.guides, lubricant=cases.contact.lubricant,
                                mechanism=deck.mechanism)
    losses = guide_losses(case_deck, inputs[TrainKinematics].main)
    cases.add_metrics(guide_metrics(losses))
    return losses
