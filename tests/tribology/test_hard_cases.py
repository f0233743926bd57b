"""Hard cases under np.errstate(all="raise"): zero entrainment, loads near zero, loss of contact,
a friction arm (pivoted-like) iteration through the effects."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from camtrain.contact.model import contact_film, contact_friction
from camtrain.loads import bounce_speed
from camtrain.runner import run_plan

from .conftest import harrison_kinematics, with_speed

NUMERIC = ("load", "hertz_pmax", "hertz_half_width", "friction_force", "friction_coefficient",
           "friction_torque", "power_loss")


def test_entrainment_exactly_zero(harrison_deck, harrison_kin):
    """Force u = 0 at the nose: h = 0, friction falls back to the boundary cap, all finite."""
    kin = harrison_kin
    i = int(np.argmax(kin.valve_lift))
    vf = kin.v_follower.copy()
    vf[i] = -kin.v_cam[i]
    kin = replace(kin, v_follower=vf)
    load = np.where(kin.valve_lift > 0, 300.0, 0.0)
    with np.errstate(all="raise"):
        film = contact_film(harrison_deck, kin, load)
        fr = contact_friction(harrison_deck, kin, load)
    assert film.min[i] == 0.0 and film.central[i] == 0.0
    assert fr.force[i] == pytest.approx(0.08 * 300.0)
    assert np.all(np.isfinite(fr.force))


@pytest.mark.parametrize("factor", [1 - 1e-9, 1 - 1e-4])
def test_load_near_zero_at_bounce_speed(harrison_deck, factor):
    kin = harrison_kinematics(harrison_deck, harrison_deck.solver.angle_points)  # the run's grid
    s, m = harrison_deck.spring, harrison_deck.masses
    b = bounce_speed(kin, rate=s.rate, preload_compression=s.preload_compression,
                     valve_mass=m.valve_side, clearance=harrison_deck.clearance.valve_clearance)
    deck = with_speed(harrison_deck, b.omega * factor)
    with np.errstate(all="raise"):
        res = run_plan(deck)
    assert 0.0 < res.metrics["load_min"].value < 1.0
    for name in NUMERIC:
        assert np.all(np.isfinite(res[name])), name
    assert np.isfinite(res.metrics["power_loss_mean"].value)


def test_above_bounce_warns_and_stays_finite(harrison_deck):
    deck = with_speed(harrison_deck, 4000 * np.pi / 30)
    with np.errstate(all="raise"):
        res = run_plan(deck)
    assert any("valve bounce" in w for w in res.warnings)
    assert res.metrics["load_min"].value < 0
    for name in NUMERIC:
        assert np.all(np.isfinite(res[name])), name


def test_friction_arm_iterates_through_effects(harrison_deck, monkeypatch):
    """A follower whose load depends on mu runs Ball's iteration with the real friction chain."""
    from camtrain.effects import loads as eff
    kin = harrison_kinematics(harrison_deck)
    kin = replace(kin, arm_friction=0.2 * kin.arm_normal)
    with np.errstate(all="raise"):
        sol = eff.solve_loads(harrison_deck, kin)
    # Ball §4.2.3.2: "usually only three iterations"; the budget (friction_max_iterations, 50)
    # would raise, so the bound that can fail is Ball's count, with room for one more pass
    assert 2 <= sol.iterations <= 4
    assert sol.residual <= harrison_deck.solver.friction_tolerance
    lifted = sol.load > 0
    assert np.all(sol.mu[lifted] <= 0.08 + 1e-12)
