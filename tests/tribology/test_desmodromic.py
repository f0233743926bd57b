"""Desmodromic loads (Ball 1988 App D, App F rig): control of the valve, handover, both pairs.

Printed: 1.82 W (opening pair, Fig F.1a) and 6.46 W (closing pair, Fig F.2a) at 2000 rpm. The
App F.1.1 multipol gives a 7.29 mm peak valve lift against the printed 10.50 mm, so the lift
Ball ran is not the lift in the table; the comparison below says which parts survive that.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from camtrain.deck.load import load_deck
from camtrain.loads import desmodromic_loads
from camtrain.runner import run_plan
from tests.tribology.conftest import DECKS

BALL_OPENING, BALL_CLOSING = 1.82, 6.46     # W, Ball (1988) Figs F.1a, F.2a, 2000 rpm


@pytest.fixture(scope="module")
def deck():
    return load_deck(str(DECKS / "desmo_rig.toml")).model


@pytest.fixture(scope="module")
def result(deck):
    return run_plan(deck)


def with_entrainment(deck, how):
    return replace(deck, tribology=replace(deck.tribology, entrainment=how))


def test_app_d_table(deck, result):
    """W_o = RR_o (M x'' + S) while that is positive; W_c = RR_c max(S, -M x'')."""
    S = 10.0e3 * 5.0e-3                                    # App F: k delta = 50 N
    assert result.metrics["closing_spring_force"].value == pytest.approx(S)
    lifted = result["valve_lift"] > 0.0
    force = result["valve_force"]
    rr_o, rr_c = result["rocker_ratio"], result["closing_rocker_ratio"]
    drives = lifted & (force > 0.0)
    np.testing.assert_allclose(result["load"], np.where(drives, rr_o * force, 0.0))
    inertia = np.where(lifted, force - S, 0.0)
    np.testing.assert_allclose(result["closing_load"], rr_c * np.maximum(S, -inertia))
    np.testing.assert_array_equal(result["in_control"], np.where(drives, 1, -1))
    assert np.all(result["closing_load"] >= rr_c.min() * S - 1e-9)   # never loses control
    assert not np.any(drives & (result["closing_load"] > rr_c * S * (1 + 1e-12)))


def test_handover_where_inertia_equals_spring(deck, result):
    h1, h2 = result.metrics["handover_1"].value, result.metrics["handover_2"].value
    # symmetric multipol: control passes to the closing cam before the nose and back after it
    assert h1 < 0.0 < h2 and h1 == pytest.approx(-h2, abs=1e-6)
    assert np.degrees(h2) == pytest.approx(28.7, abs=0.1)
    theta = result["cam_angle"]
    f = np.interp(h2, theta, result["valve_force"])
    assert abs(f) < 0.02 * 50.0                           # M x'' + S = 0 (D.10 corrected)
    assert any("control of the valve passes" in w for w in result.warnings)


def test_no_bounce_for_a_desmodromic_train(result):
    assert "bounce_speed" not in result.metrics
    assert not any("bounce:" in w or "jams" in w for w in result.warnings)


def test_jam_is_reported(deck, result):
    from camtrain.assemble import mechanism as ME
    from camtrain.assemble.lift_law import build_lift_law
    from camtrain.lift import angle_grid
    curve = build_lift_law(deck.lift).evaluate(angle_grid(360))
    ko, kc = ME.kinematics(deck, curve)
    bad = replace(kc, rocker_ratio=-np.asarray(kc.rocker_ratio))
    d = desmodromic_loads(ko, bad, closing_spring=50.0, valve_mass=deck.masses.valve_side)
    assert d.jammed.all()
    ok = desmodromic_loads(ko, kc, closing_spring=50.0, valve_mass=deck.masses.valve_side)
    assert not ok.jammed.any()


def test_pair_columns_and_total(result):
    for name in ("closing_hertz_pmax", "closing_film_min", "closing_friction_force",
                 "closing_power_loss"):
        assert name in result.columns
        assert np.all(np.isfinite(result[name][result["closing_load"] > 0]))
    m = result.metrics
    assert m["power_loss_total"].value == pytest.approx(
        m["power_loss_mean"].value + m["closing_power_loss_mean"].value)


def test_power_against_ball(deck, result):
    """Closing pair, Ball Fig F.2a 6.46 W: 6.447 W (-0.2 %) with Ball's 'sum' entraining velocity,
    the deck's; the mean gives 10.40 W (+61 %; h ~ u^0.68, Dowson-Toyoda: 2^0.68 = 1.6). The
    closing loss is mostly the base circle (RR_c S = 100-125 N at 5.2 m/s sliding) and the nose,
    where the lift amplitude matters little. Opening pair, Fig F.1a 1.82 W: 0.61 W (sum) /
    0.97 W (mean), unexplained: camtrain follows App D, the opening load is the flank inertia of
    a lift law that is not the one Ball ran (7.29 vs 10.50 mm peak), and scaling the multipol to
    10.50 mm changes the opening loss by only -1.5 % (ramp kept) to +12 % (ramp scaled too)
    while driving the closing pair to 14-22 W."""
    m = result.metrics
    assert m["closing_power_loss_mean"].value == pytest.approx(BALL_CLOSING, rel=0.15)
    assert m["power_loss_mean"].value < 0.5 * BALL_OPENING     # documented residual
    # camtrain's own values (sum and mean entrainment) are pinned in the golden files
    # desmo_rig and desmo_rig+mean_entrainment; the mean convention moves the closing loss away
    mean = run_plan(with_entrainment(deck, "mean")).metrics
    assert mean["closing_power_loss_mean"].value > 1.15 * BALL_CLOSING
