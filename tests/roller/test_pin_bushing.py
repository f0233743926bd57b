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
