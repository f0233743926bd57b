"""Shared fixtures: the Harrison deck (Ball 1988 §5.2) and its flat-follower kinematics."""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from camtrain import mechanisms as M
from camtrain.assemble.lift_law import build_lift_law
from camtrain.deck.load import load_deck
from camtrain.lift import angle_grid

DECKS = Path(__file__).resolve().parents[2] / "decks"


@pytest.fixture(scope="session")
def harrison_deck():
    return load_deck(str(DECKS / "harrison_flat.toml")).model


def harrison_kinematics(deck, points=720, omega=None):
    curve = build_lift_law(deck.lift).evaluate(angle_grid(points))
    return M.flat_faced(curve, base_radius=deck.cam.base_radius,
                        omega=deck.speed.omega if omega is None else omega)


@pytest.fixture(scope="session")
def harrison_kin(harrison_deck):
    return harrison_kinematics(harrison_deck)


def with_speed(deck, omega):
    return replace(deck, speed=replace(deck.speed, camshaft=omega))
