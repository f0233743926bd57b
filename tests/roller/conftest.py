"""The chain's products up to the Hertz field for a deck, to test the roller physics on arrays."""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from camtrain.catalogue import VALVE_TRAIN
from camtrain.deck.load import load_deck
from camtrain.result import Result
from camtrain.runner import Inputs
from camtrain.scene import effect_module

DECKS = Path(__file__).resolve().parents[2] / "decks"


def chain(deck, upto=("kinematics", "loads", "hertz")):
    """{product name: product} of the chain's first effects on ``deck``."""
    products: dict[str, object] = {}
    specs = {s.name: s for s in VALVE_TRAIN}
    res = Result()
    for name in upto:
        spec = specs[name]
        out = effect_module(spec).run(deck, Inputs(spec, products), res)
        products[spec.produces[0]] = out
    return products


def roller_deck(points=360, **changes):
    """The non-rotating roller deck (Harrison's cam, 12 mm roller) at ``points`` angles."""
    deck = load_deck(str(DECKS / "harrison_roller.toml")).model
    deck = replace(deck, solver=replace(deck.solver, angle_points=points))
    for section, values in changes.items():
        deck = replace(deck, **{section: replace(getattr(deck, section), **values)})
    return deck


def traction_of(deck, law="limiting_shear", rolling="goksem_hargreaves"):
    from camtrain.contact.model import CamContact
    from camtrain.roller.traction import Traction

    p = chain(deck)
    kin, load, hz = p["TrainKinematics"].main, p["ContactLoad"].load, p["ContactHertz"].main
    return Traction(CamContact.from_deck(deck), kin, np.maximum(load, 0.0), hz, law, rolling)


@pytest.fixture(scope="module")
def harrison_traction():
    return traction_of(roller_deck())
