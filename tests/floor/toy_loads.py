"""A toy effect in a module of its own: an alternative ContactLoad (the rigid-train load scaled
by a deck factor), registered only by the test that uses it. It shows what a dynamic-loads
effect has to provide: missing(), reason(), run() returning a ContactLoad."""
from __future__ import annotations

from dataclasses import dataclass

from camtrain.catalogue import EffectSpec
from camtrain.deck.schema import Deck

SPEC = EffectSpec("toy_loads", __name__, "toy contact load: the rigid-train load scaled",
                  needs=("TrainKinematics",), produces=("ContactLoad",), rank=1)


@dataclass(frozen=True, kw_only=True)
class ToyDeck(Deck):
    """A valve-train deck with one more (toy) section."""

    toy_scale: float | None = None


def missing(deck) -> list[str]:
    return [] if getattr(deck, "toy_scale", None) is not None else ["toy_scale"]


def reason(deck, planned) -> str:
    return f"toy_scale = {deck.toy_scale:g} given: toy loads"


def run(deck, inputs, result):
    import numpy as np

    from camtrain.loads import ContactLoad, contact_load, contact_mask
    from camtrain.mechanisms import TrainKinematics

    kin = inputs[TrainKinematics].main
    s, m = deck.spring, deck.masses
    load = deck.toy_scale * contact_load(kin, np.full(kin.theta.shape, 0.08), rate=s.rate,
                                         preload_compression=s.preload_compression,
                                         valve_mass=m.valve_side)
    result.add_column("load", load, "N", "toy contact load")
    return ContactLoad(load=load, in_contact=contact_mask(kin.valve_lift, 0.0), model="toy")
