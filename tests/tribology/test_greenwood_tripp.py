"""The greenwood_tripp friction model (Teodorescu et al. 2005 eqs. 8-15 with Greenwood-Tripp)."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from camtrain.contact.friction import GT_LAMBDA_LIMIT, greenwood_tripp_law
from camtrain.contact.model import CamContact, contact_friction, contact_hertz
from camtrain.deck.load import load_deck
from camtrain.formulas import ball_1988_shear_force
from camtrain.runner import run_plan
from tests.tribology.conftest import DECKS, harrison_kinematics


def gt(deck, **kw):
    return replace(deck, tribology=replace(deck.tribology, friction_model="greenwood_tripp", **kw))


@pytest.mark.parametrize("name", ["harrison_flat", "rover_2300_rocker", "pinto_finger",
                                  "zeta_intake", "desmo_rig"])
def test_finite_on_every_tribology_deck(name):
    deck = gt(load_deck(str(DECKS / f"{name}.toml")).model)
    res = run_plan(deck)
    assert np.all(np.isfinite(res["friction_force"]))
    assert np.all(res["friction_force"] >= 0.0)
    assert np.isfinite(res.metrics["power_loss_mean"].value)


@pytest.fixture(scope="module")
def harrison():
    deck = gt(load_deck(str(DECKS / "harrison_flat.toml")).model)
    kin = harrison_kinematics(deck)
    load = np.linspace(100.0, 1400.0, kin.theta.size)
    use = np.ones(kin.theta.size, dtype=bool)
    return deck, kin, load, use, contact_hertz(deck, kin, load)


def greenwood_tripp_friction(deck, kin, load, hz, h, use):
    return greenwood_tripp_law(CamContact.from_deck(deck), kin, load, hz, np.asarray(h), use)


def newtonian(deck, kin, hz, h, load):
    lub = deck.lubricant
    return np.asarray(ball_1988_shear_force(np.abs(kin.sliding), h, lub.viscosity,
                                            lub.pressure_viscosity, hz.pmax,
                                            hz.half_width, deck.cam.width), dtype=float)


def test_thick_film_limit_is_the_viscous_result(harrison):
    """lambda -> large: no asperity load, F = min(Newtonian shear, tau0 A + gamma W)."""
    deck, kin, load, use, hz = harrison
    h = np.full(load.shape, 50.0 * deck.lubricant.roughness)      # lambda = 50
    f = greenwood_tripp_friction(deck, kin, load, hz, h, use)
    area = 2.0 * hz.half_width * deck.cam.width
    lim = 2.0e6 * area + 0.08 * load
    np.testing.assert_allclose(f, np.minimum(newtonian(deck, kin, hz, h, load), lim), rtol=1e-12)
    # with a very strong fluid the result is the Newtonian (Ball eq. 4.7) shear itself
    strong = gt(deck, eyring_stress=1e18)            # Pa: never limits
    f2 = greenwood_tripp_friction(strong, kin, load, hz, h, use)
    np.testing.assert_allclose(f2, newtonian(deck, kin, hz, h, load), rtol=1e-12)


def test_thin_film_adds_asperity_friction(harrison):
    deck, kin, load, use, hz = harrison
    thick = greenwood_tripp_friction(deck, kin, load, hz, np.full(load.shape, 5e-6), use)
    h = np.full(load.shape, 0.5 * deck.lubricant.roughness)       # lambda = 0.5
    thin = greenwood_tripp_friction(deck, kin, load, hz, h, use)
    assert np.all(np.isfinite(thin))
    moving = np.abs(kin.sliding) > 0.1
    assert np.all(thin[moving] > thick[moving])
    # zero film (zero entrainment): finite, limited by the boundary + limiting shear
    zero = greenwood_tripp_friction(deck, kin, load, hz, np.zeros(load.shape), use)
    assert np.all(np.isfinite(zero))
    assert GT_LAMBDA_LIMIT == 3.0


def test_wired_through_contact_friction(harrison):
    deck, kin, load, _, _ = harrison
    f = contact_friction(deck, kin, load).force
    cap = contact_friction(replace(deck, tribology=replace(deck.tribology,
                                                           friction_model="cap")), kin, load)
    assert np.all(np.isfinite(f)) and not np.allclose(f, cap.force)
