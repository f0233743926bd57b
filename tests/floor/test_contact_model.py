"""The contact model: one object for Hertz, film and friction of a pair, laws from registries,
one Teodorescu/Greenwood-Tripp friction (the formula)."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from camtrain.contact import model as cm
from camtrain.contact.friction import GT_LAMBDA_LIMIT, greenwood_tripp_law
from camtrain.contact.products import FilmField
from camtrain.formulas import teodorescu_2005_friction
from tests.tribology.conftest import harrison_kinematics

from .test_registry import toy_deck


@pytest.fixture(scope="module")
def pair():
    deck = toy_deck(None)
    kin = harrison_kinematics(deck)
    load = np.where(kin.valve_lift > 0, 600.0, 0.0)
    return deck, kin, load


def test_solve_is_hertz_then_film_then_friction(pair):
    deck, kin, load = pair
    contact = cm.CamContact.from_deck(deck)
    out = contact.solve(kin, load)
    hz, film = contact.hertz(kin, load), contact.film(kin, load)
    np.testing.assert_array_equal(out.hertz.pmax, hz.pmax)
    np.testing.assert_array_equal(out.film.min, film.min)
    np.testing.assert_array_equal(out.force, contact.friction(kin, load, hz, film).force)
    assert np.all(out.force[load == 0] == 0.0) and np.all(out.force[load > 0] > 0.0)


def test_a_registered_film_law_is_used_by_every_user_of_the_contact(pair, monkeypatch):
    """A film law registered by name (as a transient film would be) reaches the friction."""
    deck, kin, load = pair
    seen = []

    def thick(contact, kin, load):
        seen.append(load is not None)
        h = np.full(kin.theta.shape, 5e-6)
        return FilmField(min=h, central=h, method="thick", central_method="thick")

    monkeypatch.setitem(cm.FILM_LAWS, "thick", thick)
    contact = replace(cm.CamContact.from_deck(deck), film_law="thick")
    out = contact.solve(kin, load)
    assert seen == [True] and out.film.method == "thick"
    steady = cm.CamContact.from_deck(deck).solve(kin, load)
    assert np.all(out.film.min == 5e-6)
    assert not np.array_equal(out.force, steady.force)  # the friction saw the registered film


def test_friction_laws_are_the_deck_options():
    from camtrain.deck.schema_tribology import Tribology

    options = Tribology.__dataclass_fields__["friction_model"].type
    for name in ("cap", "lambda", "lambda_cap", "greenwood_tripp"):
        assert name in options and name in cm.FRICTION_LAWS


def test_greenwood_tripp_law_is_the_teodorescu_formula_when_the_fluid_limits(pair):
    """With a Newtonian shear far above the limiting shear (slow film, large viscosity) the law
    is exactly Teodorescu et al. (2005) eqs. 8-15, computed by the one formula."""
    deck, kin, load = pair
    deck = replace(deck, tribology=replace(deck.tribology, friction_model="greenwood_tripp"),
                   lubricant=replace(deck.lubricant, viscosity=50.0))
    contact = cm.CamContact.from_deck(deck)
    hz = contact.hertz(kin, load)
    use = load > 0
    sigma = deck.lubricant.roughness
    h = np.full(load.shape, 1.2 * sigma)
    f = greenwood_tripp_law(contact, kin, load, hz, h, use)
    trib = deck.tribology
    beta = sigma / trib.roughness_slope
    zeta = trib.asperity_density_product / (beta * sigma)
    area = 2.0 * hz.half_width[use] * deck.cam.width
    ref = teodorescu_2005_friction(load[use], area, h[use] / sigma, trib.eyring_stress,
                                   trib.shear_pressure_coefficient,
                                   trib.boundary_shear_coefficient, contact.reduced_modulus,
                                   sigma, beta, zeta, lambda_limit=GT_LAMBDA_LIMIT)
    moving = np.abs(kin.sliding[use]) > 0.5
    np.testing.assert_allclose(f[moving], np.asarray(ref.total)[moving], rtol=1e-12)
    assert np.all(np.asarray(ref.asperity_load)[moving] > 0)  # lambda = 1.2: mixed
