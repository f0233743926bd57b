"""The lash adjuster's check valve as a dynamic ball (check_valve = "ball"): its free oscillation,
its massless limit (the quasi-static orifice), its closing on the base circle, the march's
step-size study with it; and the chamber's mass balance over the periodic revolution (the oil
refilled through the check valve equals the oil leaked down through the annulus)."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from camtrain.dynamics.hla import (
    ball_cracking_pressure,
    ball_end,
    hydraulic_record,
    quasi_static_equivalent,
    with_element,
)
from tests.conftest import DECKS
from tests.dynamics.test_hla import ADJUSTER

BALL = replace(ADJUSTER, check_valve="ball")


@pytest.fixture(scope="module")
def zeta_hla():
    from camtrain.api import load
    from camtrain.assemble.dynamics import setup
    from tests.dynamics.conftest import kinematics_of

    deck = load(str(DECKS / "zeta_intake_hla.toml")).model
    return setup(deck, kinematics_of(deck))


def _march(s, adjuster, refine=1, cycles=4):
    from camtrain.dynamics import march

    run = replace(s.settings, substeps=s.settings.substeps * refine, cycles_min=cycles,
                  cycles_max=cycles)
    return march(with_element(s.model, adjuster), s.cam, s.base, run)


# --------------------------------------------------------------------------- the ball alone

def _free_ball(adj, steps_per_period, periods, lift0):
    """The ball released at rest from ``lift0`` under a constant chamber pressure whose force
    balances it at the middle of its travel, marched by :func:`ball_end` alone."""
    hr = hydraulic_record(adj, 0, 0, 1.0, 0.0)
    middle = 0.5 * adj.ball_lift
    pressure = adj.supply_pressure - (adj.ball_preload + adj.ball_spring_rate * middle) \
        / adj.seat_area
    h = 2.0 * math.pi / adj.ball_frequency() / steps_per_period
    y, yd, force = lift0, 0.0, adj.ball_spring_rate * (middle - lift0)
    lifts = [y]
    for _ in range(int(periods * steps_per_period)):
        y, yd, _ = ball_end(pressure, y, yd, force, h, hr)
        force = adj.ball_spring_rate * (middle - y) - hr.ball_c * yd
        lifts.append(y)
    return np.array(lifts) - middle, h


def _period(offset, h):
    """Mean period [s] from the upward zero crossings (linear between steps)."""
    up = np.flatnonzero((offset[:-1] < 0.0) & (offset[1:] >= 0.0))
    times = (up + offset[up] / (offset[up] - offset[up + 1])) * h
    return float(np.mean(np.diff(times)))


@pytest.mark.derived
def test_free_ball_oscillates_at_sqrt_k_over_m():
    """Undamped, between its stops, the ball swings about its balance at omega = sqrt(k/m). The
    trapezoidal ball (Newmark's average acceleration) keeps its amplitude (the samples' peak
    within (omega h)^2/8 of it) and swings at its known discrete frequency, 2 arctan(omega h/2)
    per step: within 1e-6 at 200 steps a period (8e-5 from sqrt(k/m) itself). Backward Euler
    (the default scheme) swings at sqrt(k/m) within 5e-3 there and loses amplitude."""
    adj = replace(BALL, scheme="trapezoidal")
    steps = 200
    offset, h = _free_ball(adj, steps, 10, 0.2 * adj.ball_lift)
    omega = adj.ball_frequency()
    assert _period(offset, h) == pytest.approx(2 * math.pi * h / (2 * math.atan(omega * h / 2)),
                                               rel=1e-6)
    assert _period(offset, h) == pytest.approx(2 * math.pi / omega, rel=1e-4)
    assert np.max(np.abs(offset[-steps:])) == pytest.approx(
        0.3 * adj.ball_lift, rel=(omega * h) ** 2 / 8)
    euler, h = _free_ball(BALL, steps, 10, 0.2 * BALL.ball_lift)
    assert BALL.scheme == "backward_euler"
    assert _period(euler, h) == pytest.approx(2 * math.pi / omega, rel=5e-3)
    assert np.max(np.abs(euler[-steps:])) < 0.9 * 0.3 * BALL.ball_lift


@pytest.mark.derived
def test_ball_cracks_at_preload_over_seat_area_and_stops_at_its_lift():
    """Seated, the ball stays down below the cracking pressure F_0/A_seat and lifts above it;
    at a large drop it rests on its lift stop."""
    hr = hydraulic_record(BALL, 0, 0, 1.0, 0.0)
    crack = ball_cracking_pressure(BALL)
    assert crack == pytest.approx(BALL.ball_preload / (math.pi / 4 * BALL.seat_diameter ** 2))
    h = 1e-5
    below = ball_end(BALL.supply_pressure - 0.99 * crack, 0.0, 0.0, 0.0, h, hr)
    above = ball_end(BALL.supply_pressure - 1.01 * crack, 0.0, 0.0, 0.0, h, hr)
    assert below[0] == 0.0 and below[1] == 0.0
    assert above[0] > 0.0 and above[1] > 0.0
    y = 0.0
    yd = 0.0
    for _ in range(2000):
        y, yd, _ = ball_end(BALL.supply_pressure - 1e6, y, yd, 0.0, h, hr)
    assert y == BALL.ball_lift and yd == 0.0


# --------------------------------------------------------------------------- in the train

@pytest.mark.derived
def test_massless_ball_tends_to_the_quasi_static_orifice(zeta_hla):
    """The ball's mass to zero: the ball in force balance is the quasi-static orifice cracking
    at F_0/A_seat and fully open k y_max/A_seat above it, of area pi d y_max. The Zeta deck's
    four revolutions: chamber pressure, plunger extension and valve lift approach that orifice's
    linearly in the mass (a decade of mass, about a decade of difference), and at 1e-11 kg
    agree to 1e-5 of the peak pressure and 1e-4 of the collapse."""
    s = zeta_hla
    ball = replace(s.model.series.adjuster, check_valve="ball")
    ref = _march(s, quasi_static_equivalent(ball))
    v = s.model.valve
    diffs = []
    for mass in (1e-9, 1e-10, 1e-11):
        r = _march(s, replace(ball, ball_mass=mass))
        diffs.append((np.max(np.abs(r.hydraulic[0] - ref.hydraulic[0])),
                      np.max(np.abs(r.hydraulic[3] - ref.hydraulic[3])),
                      np.max(np.abs(r.u[v] - ref.u[v]))))
    diffs = np.array(diffs)
    assert np.all(diffs[1:] < 0.2 * diffs[:-1])
    collapse = ref.hydraulic[3].max() - ref.hydraulic[3].min()
    assert diffs[-1, 0] < 1e-5 * ref.hydraulic[0].max()
    assert diffs[-1, 1] < 1e-4 * collapse


@pytest.fixture(scope="module")
def zeta_ball(zeta_hla):
    return _march(zeta_hla, replace(zeta_hla.model.series.adjuster, check_valve="ball"), cycles=6)


def test_ball_stays_shut_over_the_lift_and_closes_on_the_base_circle(zeta_hla, zeta_ball):
    """With the chamber above the supply the ball is pushed onto its seat: shut while the cam
    lifts the valve (above 5 % of its lift: the chamber carries the train's load), open only in
    the pressure dips of the valve's landing, and shut again on the base circle, where the
    chamber stays above the supply up to the next opening. While it is still off its seat with
    the chamber above the supply, oil flows back out through it (negative check flow), which
    the quasi-static orifice cannot show."""
    s, r = zeta_hla, zeta_ball
    h = r.hydraulic
    supply = s.model.series.adjuster.supply_pressure
    seated = r.contact_force[1] > 0.0
    lifted = np.asarray(r.cam[0]) > 0.05 * np.max(r.cam[0])   # the event, landing aside
    assert np.all(h[6][lifted] == 0.0)
    assert np.any(h[6] > 0.0)
    back = h[1] < 0.0
    # (the chamber solve returns the flows of its last iterate, within 1e-8 of the pressure)
    assert back.any() and np.all(h[6][back] > 0.0)
    assert np.all(h[0][back] > supply - 1e-8 * (supply + 101_325.0))
    # the last quarter revolution of the base circle before the cam lifts: chamber above the
    # supply, the ball on its seat, no flow through it
    cam = np.asarray(r.cam[0])
    rise = int(np.flatnonzero((cam > 0.0) & (np.roll(cam, 1) <= 0.0))[0])
    before = (rise - np.arange(1, r.theta.size // 4)) % r.theta.size
    assert np.all(cam[before] <= 0.0) and np.all(seated[before])
    assert np.all(h[0][before] > supply)
    assert np.all(h[6][before] == 0.0) and np.all(h[1][before] == 0.0)


@pytest.mark.convergence
def test_march_with_the_ball_converges_and_is_accurate_at_the_default_step(zeta_hla):
    """Step-size study with the ball (backward Euler, the default scheme): steps 1, 2, 4 times
    finer than the default against 16 times, four revolutions from rest. The ball's lift, the
    chamber pressure and the plunger extension converge at a fitted order above 1.3 (observed
    1.6-1.8: the backward-Euler ball and chamber are first order in the flows, a small share
    of the motion, as without the ball); at the default step the valve lift is within 2e-5 of
    the lift of the finest march (observed 9e-6) and the ball's lift within 5 % of its stop
    (observed 2.7 %)."""
    s = zeta_hla
    ball = replace(s.model.series.adjuster, check_valve="ball")
    runs = [_march(s, ball, f) for f in (1, 2, 4, 16)]
    ref = runs[-1]
    for row in (6, 0, 3):
        errors = [float(np.max(np.abs(r.hydraulic[row] - ref.hydraulic[row])))
                  for r in runs[:-1]]
        order = float(np.polyfit(np.log([1.0, 0.5, 0.25]), np.log(errors), 1)[0])
        assert order > 1.3
    v = s.model.valve
    lift = float(np.max(ref.u[v]))
    assert np.max(np.abs(runs[0].u[v] - ref.u[v])) < 2e-5 * lift
    assert np.max(np.abs(runs[0].hydraulic[6] - ref.hydraulic[6])) < 0.05 * ball.ball_lift


# --------------------------------------------------------------------------- mass balance

@pytest.mark.derived
@pytest.mark.parametrize("valve", ["quasi_static", "ball"])
def test_refill_balances_the_leakdown_over_the_periodic_revolution(zeta_hla, valve):
    """The chamber's mass balance: over a periodic revolution the oil drawn in through the
    check valve equals the oil pushed out through the annulus. The march integrates
    d ln(V/phi) = (Q_in - Q_out)/V dt; the flows weighted by 1/V balance exactly, the plain
    volumes to the chamber's volume swing over the revolution, dV/V (here about 5e-3), times
    the volumes that flowed either way (the ball lets oil back out while it closes). The refill
    is visibly above nothing: of the order of the leak-down during the event."""
    s = zeta_hla
    r = _march(s, replace(s.model.series.adjuster, check_valve=valve), cycles=12)
    assert r.change < 1e-9
    area = s.model.series.adjuster.area
    refill, leak = r.hydraulic[4].sum() / area, r.hydraulic[5].sum() / area
    volume = s.model.series.adjuster.dead_volume + area * r.hydraulic[3]
    swing = (volume.max() - volume.min()) / volume.min()
    gross = (np.abs(r.hydraulic[4]).sum() + np.abs(r.hydraulic[5]).sum()) / area
    assert refill > 1e-6
    assert abs(refill - leak) <= swing * gross


@pytest.mark.derived
def test_refill_equals_the_collapse_of_an_incompressible_chamber(zeta_hla):
    """Without air and with a stiff oil (1e11 Pa: the chamber's compression under the event's
    5.6 MPa is 0.01 um) the plunger's collapse during the event is all leak-down: it equals
    the oil leaked from the valve's opening to the lowest extension (over the plunger area), and
    over the periodic revolution the refill through the check valve equals the collapse plus the
    oil leaked outside that window (the base circle and the landing), within 2 %."""
    from camtrain.dynamics import march
    from camtrain.dynamics.hla import rigid_adjuster
    from camtrain.dynamics.hla.findings import adjuster_findings

    s = zeta_hla
    stiff = replace(s.model.series.adjuster, air_fraction=0.0, bulk_modulus=1e11)
    model = with_element(s.model, stiff)
    run = replace(s.settings, cycles_min=20, cycles_max=20)
    r = march(model, s.cam, s.base, run)
    assert r.change < 1e-9
    found = adjuster_findings(r, march(rigid_adjuster(model), s.cam, s.base, run), model, 1e-3)
    h = r.hydraulic
    open_ = r.contact_force[1] <= 0.0
    first = int(np.flatnonzero(open_ & ~np.roll(open_, 1))[0])
    lowest = int(np.argmin(np.where(open_, h[3], np.inf)))
    window = np.arange(first + 1, lowest + 1) % r.theta.size   # the volumes of its intervals
    leak_in_window = h[5][window].sum() / stiff.area
    assert found.collapse > 1e-6
    assert found.collapse == pytest.approx(leak_in_window, rel=0.02)
    assert found.refill == pytest.approx(found.collapse + found.leakdown - leak_in_window,
                                         rel=0.02)
