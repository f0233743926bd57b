"""The elastic train's limits back to the rigid train camtrain already has (reference notes
wave2 §1.5, L1, L2, L8): stiffnesses x 1e3 give the rigid-train load (Zeta intake, 1500 rpm cam)
and its friction power; the first separation speed of the stiff train is the closed-form bounce
speed, at the same angle."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.assemble.dynamics import rigid_load, separation_check

# imported under another name: a module-level function called setup is a nose-style setup
# hook to pytest < 8 (the declared minimum is 7.4)
from camtrain.assemble.dynamics import setup as dynamic_setup
from camtrain.dynamics import march
from camtrain.dynamics.speed import first_separation_speed
from camtrain.loads import bounce_speed, contact_mask
from tests.dynamics.conftest import SINGLE_RATE, deck_of, zeta_raw

pytestmark = pytest.mark.derived

STIFF = 1e3


def _edges_excluded(kin, width_deg=2.0):
    """Angles farther than width from an edge of the rigid contact window. The rigid valve
    enters its window already moving (the lift crosses the base-circle tolerance at 3.9 mm/s):
    a momentum step the rigid load does not carry, an impact for the elastic train whose ringing
    does not vanish pointwise but within a window shrinking like k^-1/2 (1.8 deg at x 1e3;
    test_dyn_stiff_edges.py)."""
    inside = contact_mask(kin.valve_lift)
    edges = np.nonzero(np.diff(inside.astype(int)))[0]
    theta = kin.theta
    keep = np.ones(theta.shape, dtype=bool)
    for i in edges:
        near = np.abs(np.angle(np.exp(1j * (theta - theta[i])))) <= math.radians(width_deg) + 1e-9
        keep &= ~near
    return keep


def test_stiff_train_carries_the_rigid_load(zeta_single_rate):
    deck, kin = zeta_single_rate
    s = dynamic_setup(deck, kin, stiffness_scale=STIFF)
    resp = march(s.model, s.cam, s.base, s.settings)
    assert resp.converged
    dyn = resp.contact_force[0] * kin.rocker_ratio
    rigid = rigid_load(deck, kin)
    keep = _edges_excluded(kin)
    err = np.max(np.abs(dyn - rigid)[keep]) / np.max(rigid)
    assert err < 5e-3
    assert np.max(dyn) == pytest.approx(np.max(rigid), rel=5e-3)


def test_stiff_train_friction_power_equals_the_rigid_trains():
    from camtrain import api

    stiff = {k: v for k, v in SINGLE_RATE.items()}
    raw = zeta_raw({"dynamics": stiff})
    for key in ("contact_stiffness", "stem_stiffness", "seat_stiffness"):
        raw["dynamics"][key] *= STIFF
    dynamic = api.run(deck_of(raw))
    rigid_raw = zeta_raw()
    del rigid_raw["dynamics"]
    rigid = api.run(deck_of(rigid_raw))
    assert "dynamics" in dynamic.plan.chosen and "loads" in rigid.plan.chosen
    p_dyn = dynamic.metrics["power_loss_mean"].value
    p_rigid = rigid.metrics["power_loss_mean"].value
    assert p_dyn == pytest.approx(p_rigid, rel=5e-3)


def test_first_separation_speed_of_the_stiff_train_is_the_bounce_speed(zeta_single_rate):
    deck, kin = zeta_single_rate
    rigid = bounce_speed(kin, 0.0, rate=deck.spring.rate,
                         preload_compression=deck.spring.preload_compression,
                         valve_mass=deck.masses.valve_side)
    search = first_separation_speed(
        separation_check(deck, kin, stiffness_scale=STIFF, overrides={"cycles_max": 6}),
        0.9 * rigid.omega, rtol=2e-3)
    assert search.upper / search.omega - 1 <= 2e-3 * 1.0001
    assert search.upper == pytest.approx(rigid.omega, rel=0.02)
    assert abs(math.degrees(search.angle - rigid.angle)) < 2.0
