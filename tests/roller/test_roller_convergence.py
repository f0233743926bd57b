"""The periodic march of the roller's speed converges at its observed order (implicit Euler:
first order in the time step), fitted over substeps of the cycle grid."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.roller.pin import Pin
from camtrain.roller.solve import RollerSettings, inertial_speed
from tests.roller.conftest import roller_deck, traction_of

pytestmark = pytest.mark.convergence


def test_periodic_march_first_order_in_the_step():
    deck = roller_deck(points=360, spring=dict(rate=38254.0 * 0.7))
    tr = traction_of(deck)
    pin = Pin("needle", pitch_diameter=0.008, kinematic_viscosity=0.05 / 850.0)
    radius, inertia = 0.012, 0.5 * 0.02 * 0.012 ** 2

    def speeds(substeps):
        s = RollerSettings(solver="inertial", substeps=substeps, tolerance=1e-10,
                           revolutions=200)
        w, revs, change = inertial_speed(tr, pin, radius, inertia, tr.kin.omega, s)
        assert change <= 1e-10
        return w

    ladder = [2, 4, 8, 16]
    ref = speeds(128)
    errors = np.array([np.max(np.abs(speeds(m) - ref)) for m in ladder])
    order = -np.polyfit(np.log(ladder), np.log(errors), 1)[0]
    assert 0.8 < order < 1.3, (errors, order)
