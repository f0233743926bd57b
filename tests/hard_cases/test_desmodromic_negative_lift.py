"""A desmodromic closing cam whose lift is given negative (Ball 1988 App F prints the closing
valve lift as -10.10 mm): the closing pair is analysed by negating it (Ball §3.2.3), and a lift
that is already positive gives the same pair with ``negate_closing=False``."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.assemble.lift_law import build_lift_law
from camtrain.assemble.mechanism import closing_geometry, pivot_geometry
from camtrain.deck.load import load_deck
from camtrain.lift import LiftCurve, angle_grid
from camtrain.mechanisms import desmodromic

from .conftest import DECKS

FIELDS = ("cam_radius", "equivalent_radius", "v_cam", "v_follower", "valve_lift", "rocker_ratio")


@pytest.fixture(scope="module")
def pair_inputs():
    deck = load_deck(str(DECKS / "desmo_rig.toml")).model
    lift = build_lift_law(deck.lift).evaluate(angle_grid(1440))
    negative = LiftCurve(lift.theta, -lift.lift, -lift.d1, -lift.d2, -lift.d3)
    opening = pivot_geometry(deck.mechanism, deck.cam.base_radius, "central")
    closing = closing_geometry(deck.mechanism.closing)
    return deck, lift, negative, opening, closing


def test_negative_closing_lift_gives_a_finite_conventional_pair(pair_inputs):
    deck, lift, negative, opening, closing = pair_inputs
    assert negative.lift.min() < -7e-3            # the App F lift, negative: peak -7.29 mm
    with np.errstate(all="raise"):
        pair = desmodromic(lift, negative, opening, closing, omega=deck.speed.omega)
    k = pair.closing
    for name in FIELDS:
        assert np.all(np.isfinite(getattr(k, name))), name
    # negated, the closing pair follows the valve lift; on the base circle r_c = r_B (25 mm)
    np.testing.assert_allclose(k.valve_lift, lift.lift, atol=1e-12)
    base = np.abs(lift.lift) < 1e-15
    np.testing.assert_allclose(k.cam_radius[base], closing.base_radius, rtol=1e-9)


def test_already_positive_closing_lift_needs_no_negation(pair_inputs):
    deck, lift, negative, opening, closing = pair_inputs
    a = desmodromic(lift, negative, opening, closing, omega=deck.speed.omega).closing
    b = desmodromic(lift, lift, opening, closing, omega=deck.speed.omega,
                    negate_closing=False).closing
    for name in FIELDS:
        np.testing.assert_allclose(getattr(a, name), getattr(b, name), rtol=1e-12, atol=1e-15)
