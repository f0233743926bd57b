"""The compiled quasi-static balance (camtrain/roller/_balance.py) is the array solve written per
angle: the same roots on the angles it takes (derived tier: two implementations of one solve)."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.roller import solve
from camtrain.roller.pin import Pin
from tests.roller.conftest import roller_deck, traction_of

pytestmark = pytest.mark.derived
RADIUS = 0.012


@pytest.mark.parametrize("law", ["limiting_shear", "eyring"])
@pytest.mark.parametrize("f0, f1", [(3.0, 0.0005), (30.0, 0.005)])
def test_compiled_balance_equals_the_array_solve(law, f0, f1, monkeypatch):
    """On the Harrison roller (full film over its loaded angles) the compiled balance solves
    most loaded angles and returns the array solve's speeds to 1e-12."""
    tr = traction_of(roller_deck(), law=law)
    pin = Pin("needle", pitch_diameter=0.008, kinematic_viscosity=0.05 / 850.0, f0=f0, f1=f1)
    loaded = np.flatnonzero((tr.load > 0.0) & (tr.v_s0 != 0.0))
    taken = solve._compiled_records(tr, pin, RADIUS, loaded)
    assert taken is not None and np.count_nonzero(taken[0]) > loaded.size // 2
    compiled = solve.quasi_static_speed(tr, pin, RADIUS)
    monkeypatch.setattr(solve, "_compiled_records", lambda *args: None)
    array = solve.quasi_static_speed(tr, pin, RADIUS)
    np.testing.assert_allclose(compiled, array, rtol=1e-12, atol=0.0)
    assert np.any((compiled > 0.0) & (compiled < tr.v_s0 / RADIUS))   # some angles slip


def test_contact_law_and_frictionless_pin_keep_the_array_solve(harrison_traction):
    """The deck's own friction law and pins other than a needle are not taken by the compiled
    balance."""
    loaded = np.flatnonzero(harrison_traction.load > 0.0)
    needle = Pin("needle", pitch_diameter=0.008, kinematic_viscosity=1e-4)
    assert solve._compiled_records(traction_of(roller_deck(), law="contact"), needle, RADIUS,
                                   loaded) is None
    assert solve._compiled_records(harrison_traction, Pin("frictionless"), RADIUS,
                                   loaded) is None
