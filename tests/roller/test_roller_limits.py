"""Limits of the roller's rotation to models camtrain already has (derived tier)."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.roller.pin import Pin, needle_torque
from camtrain.roller.solve import RollerSettings, solve_roller
from tests.roller.conftest import roller_deck, traction_of

pytestmark = pytest.mark.derived
RADIUS = 0.012
NEEDLE = dict(pitch_diameter=0.008, kinematic_viscosity=0.05 / 850.0)


def test_frictionless_pin_without_inertia_rolls_and_loses_only_rolling(harrison_traction):
    """Zero pin friction, J = 0: slip 0 wherever loaded, no sliding loss; the cam-roller loss is
    the hydrodynamic rolling loss alone."""
    tr = harrison_traction
    f = solve_roller(tr, Pin("frictionless"), RADIUS, 0.0)
    loaded = tr.load > 0.0
    assert np.all(f.slip[loaded] == 0.0) and np.all(f.sliding[loaded] == 0.0)
    assert np.all(f.sliding_power == 0.0) and np.all(f.pin_power == 0.0)
    np.testing.assert_array_equal(f.rolling_power + f.sliding_power, f.rolling_power)
    assert f.rolling_power[loaded].min() > 0.0
    np.testing.assert_allclose(f.omega_roller * RADIUS, tr.v_s0, rtol=1e-12)


def test_locked_roller_is_the_non_rotating_curved_follower():
    """Infinite pin friction: w_r = 0 at every angle, and with the deck's own friction law the
    roller's film and friction equal the chain's non-rotating follower's to 1e-9."""
    from camtrain.contact.model import CamContact

    deck = roller_deck()
    tr = traction_of(deck, law="contact", rolling="none")
    f = solve_roller(tr, Pin("locked"), RADIUS, 1e-6, RollerSettings(solver="inertial"))
    assert np.all(f.omega_roller == 0.0)
    contact = CamContact.from_deck(deck)
    chain = contact.solve(tr.kin, tr.load)
    np.testing.assert_allclose(np.abs(f.traction), chain.force, rtol=1e-9, atol=0.0)
    film = tr.film(f.sliding)
    np.testing.assert_allclose(film.min, chain.film.min, rtol=1e-9, equal_nan=True)
    loaded = tr.load > 0.0
    np.testing.assert_allclose(f.slip[loaded], 1.0, rtol=1e-12)
    assert np.all(f.rolling_power == 0.0)


def test_needle_with_zero_coefficients_is_a_frictionless_pin(harrison_traction):
    tr = harrison_traction
    free = solve_roller(tr, Pin("frictionless"), RADIUS, 0.0)
    needle = solve_roller(tr, Pin("needle", f0=0.0, f1=0.0, **NEEDLE), RADIUS, 0.0)
    np.testing.assert_allclose(needle.omega_roller, free.omega_roller, rtol=1e-9)
    np.testing.assert_allclose(needle.pin_power, 0.0, atol=0.0)
    np.testing.assert_allclose(needle.sliding_power, free.sliding_power, atol=1e-9)


def test_needle_torque_is_the_catalogue_form():
    """M0 = 1e-7 f0 (nu n)^(2/3) d_m^3 above nu n = 2000, 160e-7 f0 d_m^3 below, M1 = f1 F d_m
    [N mm]: hand values at d_m = 10 mm, nu = 20 cSt."""
    w = np.array([2.0 * np.pi * 50.0 / 60.0, 2.0 * np.pi * 1000.0 / 60.0])   # 50 and 1000 rpm
    T = needle_torque(w, np.array([100.0, 100.0]), 0.010, 20e-6, 3.0, 5e-4)
    low = 160e-7 * 3.0 * 1000.0 + 5e-4 * 100.0 * 10.0                        # nu n = 1000
    high = 1e-7 * 3.0 * (20.0 * 1000.0) ** (2.0 / 3.0) * 1000.0 + 0.5        # nu n = 20000
    np.testing.assert_allclose(T, np.array([low, high]) * 1e-3, rtol=1e-12)


def test_pin_torque_opposes_the_rotation():
    from camtrain.bearings import JournalBearing

    w = np.array([-300.0, -1.0, 0.0, 1.0, 300.0])
    F = np.full(w.shape, 800.0)
    for pin in (Pin("needle", **NEEDLE), Pin("bushing", bearing=JournalBearing(
            0.006, 0.010, 10e-6, 0.05))):
        T = pin.torque(w, F)
        assert np.all(T * w >= 0.0) and T[2] == 0.0 and np.all(np.diff(T[[0, 1, 3, 4]]) > 0)
