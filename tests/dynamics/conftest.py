"""Shared helpers of the dynamics tests: the shipped Zeta dynamics deck with fields changed, and
its kinematics."""
from __future__ import annotations

import copy
import tomllib

import pytest

from tests.conftest import DECKS

ZETA_DYNAMICS = DECKS / "zeta_intake_dynamics.toml"


def zeta_raw(changes: dict | None = None) -> dict:
    """The Zeta dynamics deck as a TOML dictionary, ``changes`` = {section: {field: value}}
    (a value None removes the field)."""
    raw = tomllib.loads(ZETA_DYNAMICS.read_text())
    raw = copy.deepcopy(raw)
    for section, fields in (changes or {}).items():
        target = raw.setdefault(section, {})
        for key, value in fields.items():
            if value is None:
                target.pop(key, None)
            else:
                target[key] = value
    return raw


def deck_of(raw: dict):
    from camtrain.deck.load import validate

    return validate(raw, "zeta_intake_dynamics")


def kinematics_of(deck):
    from camtrain.build.lift_law import build_lift_law
    from camtrain.build.mechanism import kinematics
    from camtrain.lift import angle_grid

    curve = build_lift_law(deck.lift).evaluate(angle_grid(deck.solver.angle_points))
    return kinematics(deck, curve)[0]


#: the stiff-limit train: single-rate spring without damping (the rigid train has neither
#: surge nor spring damping), every other element as the deck
SINGLE_RATE = {"spring_elements": 0, "spring_mass": None, "spring_damping_ratio": 0.0}


@pytest.fixture(scope="session")
def zeta_single_rate():
    deck = deck_of(zeta_raw({"dynamics": SINGLE_RATE}))
    return deck, kinematics_of(deck)
