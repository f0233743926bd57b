"""The plain-bushing pin through camtrain's bearing models: the finite-length film tends to the
short (Ocvirk) bearing for a short bushing, and carries less than it at b/d = 1."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.bearings import JournalBearing
from camtrain.bearings.models import finite_steady_eccentricity
from camtrain.bearings.steady import steady_eccentricity
from camtrain.roller.pin import Pin

pytestmark = pytest.mark.derived


def bushing(length):
    return JournalBearing(0.010, length, 10e-6, 0.02)


def test_a_short_bushing_finite_film_approaches_ocvirk():
    b, w, F = bushing(0.002), np.array([600.0]), np.array([20.0])
    e_short = steady_eccentricity(b, F, 300.0)
    e_finite = finite_steady_eccentricity(b, F, 300.0)
    assert e_finite == pytest.approx(e_short, rel=0.02)
    short = Pin("bushing", bearing=b).torque(w, F)
    finite = Pin("bushing", bearing=b, model="finite").torque(w, F)
    np.testing.assert_allclose(finite, short, rtol=0.03)


def test_the_short_bearing_overstates_the_capacity_of_a_square_bushing():
    b, F = bushing(0.010), np.array([100.0, 500.0])
    assert np.all(finite_steady_eccentricity(b, F, 300.0) > steady_eccentricity(b, F, 300.0))


def test_loads_beyond_the_finite_curve_are_held_at_its_end():
    b = bushing(0.010)
    assert float(finite_steady_eccentricity(b, np.array([1e7]), 1.0)[0]) == pytest.approx(0.99)


def test_bushing_torque_is_the_couette_shear_plus_the_pressure_term():
    """By hand: T = 2 pi eta r^3 L w / (c sqrt(1 - eps^2)) + W c eps sin(phi) / 2 with Ocvirk's
    eps (mean speed w/2, pin at rest) and attitude tan(phi) = pi sqrt(1 - eps^2) / (4 eps)
    (Raimondi & Boyd 1958 friction coefficient; Yang 1992 eq. 1.20); terms = "shear" the first
    term alone. Under a heavy load the pressure term is the larger."""
    b = JournalBearing(0.006, 0.010, 10e-6, 0.05)
    w, load = np.array([300.0, 300.0]), np.array([200.0, 18000.0])
    eps = steady_eccentricity(b, load, 0.5 * w)
    couette = 2.0 * np.pi * 0.05 * 0.003 ** 3 * 0.010 * w / (10e-6 * np.sqrt(1.0 - eps ** 2))
    phi = np.arctan2(np.pi * np.sqrt(1.0 - eps ** 2), 4.0 * eps)
    pressure = 0.5 * load * 10e-6 * eps * np.sin(phi)
    np.testing.assert_allclose(Pin("bushing", bearing=b).torque(w, load), couette + pressure,
                               rtol=1e-12)
    np.testing.assert_allclose(Pin("bushing", bearing=b, terms="shear").torque(w, load),
                               couette, rtol=1e-12)
    np.testing.assert_allclose(Pin("bushing", bearing=b).torque(-w, load), -(couette + pressure),
                               rtol=1e-12)
    assert pressure[1] > couette[1] and pressure[0] < couette[0]


def test_finite_bushing_pressure_term_uses_the_finite_film_attitude():
    """The finite film's torque has the same two terms, with its own eccentricity and the
    attitude of its steady curve: all - shear = W c eps sin(phi) / 2 of the finite film."""
    from camtrain.bearings.models import finite_steady_attitude

    b = bushing(0.0025)
    w, load = np.array([300.0, 300.0]), np.array([500.0, 8000.0])
    eps = finite_steady_eccentricity(b, load, 0.5 * w)
    pressure = 0.5 * load * 10e-6 * eps * np.sin(finite_steady_attitude(b, eps))
    both = Pin("bushing", bearing=b, model="finite").torque(w, load)
    shear = Pin("bushing", bearing=b, model="finite", terms="shear").torque(w, load)
    np.testing.assert_allclose(both - shear, pressure, rtol=1e-9)
