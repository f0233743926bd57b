"""The plain bushing with mixed friction (roller.pin_friction = "mixed"): Greenwood-Tripp
asperity friction where the bushing's minimum film falls below 3 roughnesses."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain import api
from camtrain.bearings import JournalBearing
from camtrain.contact.model import CamContact
from camtrain.roller.pin import Asperities, Pin
from camtrain.roller.solve import RollerSettings, solve_roller
from tests.roller.conftest import DECKS, roller_deck, traction_of
from tests.roller.test_roller_trends import HEAVY, INERTIA, LIGHT, RADIUS

BEARING = JournalBearing(0.006, 0.010, 10e-6, 0.05)


def asperities(deck):
    trib, sigma = deck.tribology, deck.lubricant.roughness
    beta = sigma / trib.roughness_slope
    return Asperities(sigma, beta, trib.asperity_density_product / (beta * sigma),
                      float(CamContact.from_deck(deck).reduced_modulus), trib.eyring_stress,
                      trib.boundary_shear_coefficient)


@pytest.mark.derived
def test_asperity_torque_limits():
    """Thick film (h_min >= 3 sigma): the hydrodynamic torque alone; at rest (eps -> 1) the
    asperities carry the whole load: breakaway >= m W d/2; more load, more asperity torque."""
    a = asperities(roller_deck())
    mixed, hydro = Pin("bushing", bearing=BEARING, asperities=a), Pin("bushing", bearing=BEARING)
    w, light = np.array([2000.0]), np.array([10.0])
    assert mixed.torque(w, light) == pytest.approx(hydro.torque(w, light), rel=1e-15)
    load = np.array([1.0e3, 1.0e4])
    rest = mixed.breakaway(load)
    assert np.all(rest >= a.m * load * 0.5 * BEARING.diameter)
    assert np.all(hydro.breakaway(load) == 0.0)
    slow = np.array([0.5, 0.5])
    assert np.all(mixed.torque(slow, load) > hydro.torque(slow, load))
    assert mixed.torque(slow, load)[1] > mixed.torque(slow, load)[0]
    assert mixed.torque(-slow, load) == pytest.approx(-mixed.torque(slow, load))


def _losses(scale, rpm, asp, terms="all"):
    deck = roller_deck(spring=dict(rate=38254.0 * scale),
                       speed=dict(camshaft=rpm * 2.0 * math.pi / 60.0))
    tr = traction_of(deck)
    pin = Pin("bushing", bearing=BEARING, asperities=asperities(deck) if asp else None,
              terms=terms)
    f = solve_roller(tr, pin, RADIUS, INERTIA, RollerSettings())
    return f.pin_power.mean(), f.sliding_power.mean() + f.rolling_power.mean()


@pytest.mark.parametrize("terms", ["all", "shear"])
def test_mixed_bushing_at_high_load(terms):
    """At 18 kN and 500 rpm the bushing's film falls into the mixed regime: the asperities add
    about 0.02 W to its loss whichever film torque it has (Couette alone: 0.111 -> 0.133 W;
    with the pressure term: 0.785 -> 0.807 W), and the cam-roller loss (0.324 W, nearly all
    rolling) does not change. At light load and 2500 rpm the turning bushing's film stays thick
    and the roller never stops, so nothing changes."""
    pin_h, cam_h = _losses(HEAVY, 500.0, False, terms)
    pin_m, cam_m = _losses(HEAVY, 500.0, True, terms)
    assert pin_m - pin_h > 0.01
    assert cam_m == pytest.approx(cam_h, rel=1e-6)
    assert _losses(LIGHT, 2500.0, True, terms) == pytest.approx(
        _losses(LIGHT, 2500.0, False, terms), rel=1e-12)


def test_mixed_bushing_from_the_deck():
    sets = ("roller.pin=bushing", "roller.pin_diameter=6", "roller.pin_length=10",
            "roller.pin_clearance=10", "roller.solver=quasi_static", "spring.rate=1147.62")
    hydro = api.run(api.load(DECKS / "harrison_roller_needle.toml", sets + ("speed.camshaft=500",)))
    mixed = api.run(api.load(DECKS / "harrison_roller_needle.toml",
                             sets + ("speed.camshaft=500", "roller.pin_friction=mixed",
                                     "roller.pin_roughness=0.2")))
    assert mixed.metrics["roller_power_pin"].value > hydro.metrics["roller_power_pin"].value
