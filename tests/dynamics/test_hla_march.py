"""The shipped Zeta deck with its hydraulic lash adjuster (decks/zeta_intake_hla.toml) marched:
trends of the adjuster's physics, pump-up against the separation speed, the march's observed
order and its behaviour at the default step."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from tests.conftest import DECKS


@pytest.fixture(scope="module")
def hla_deck():
    from camtrain.api import load
    from tests.dynamics.conftest import kinematics_of

    deck = load(str(DECKS / "zeta_intake_hla.toml")).model
    return deck, kinematics_of(deck)


def _run(deck, kin, rpm=None, adjuster=None, refine=1, **settings):
    """(response, constant-load adjuster's response, findings, setup) at ``rpm``, the step
    ``refine`` times finer than the deck's."""
    from camtrain.assemble.dynamics import setup
    from camtrain.dynamics import march
    from camtrain.dynamics.hla import rigid_adjuster, with_element
    from camtrain.dynamics.hla.findings import adjuster_findings

    s = setup(deck, kin, omega=None if rpm is None else rpm * math.pi / 30)
    model = s.model if adjuster is None else with_element(s.model, adjuster(s.model.series.adjuster))
    run = replace(s.settings, substeps=s.settings.substeps * refine, **settings)
    resp = march(model, s.cam, s.base, run)
    rigid = march(rigid_adjuster(model), s.cam, s.base, run)
    return resp, rigid, adjuster_findings(resp, rigid, model, 1e-3), s


def test_more_air_is_softer_and_loses_more_lift(hla_deck):
    deck, kin = hla_deck
    out = {}
    for air in (0.001, 0.03):
        resp, _, found, s = _run(deck, kin, adjuster=lambda a, air=air: replace(
            a, air_fraction=air))
        own = replace(s.model.series.adjuster, air_fraction=air)
        out[air] = (s.model.series.stiffness(), own.stiffness(),
                    float(found.lift_loss[np.argmax(resp.u[s.model.valve])]))
    assert out[0.03][1] < 0.5 * out[0.001][1]
    assert out[0.03][2] > out[0.001][2] > 0.0


def test_larger_leak_clearance_collapses_more_per_event(hla_deck):
    deck, kin = hla_deck
    collapse = [_run(deck, kin, adjuster=lambda a, c=c: replace(a, radial_clearance=c))[2]
                .collapse for c in (3e-6, 8e-6)]
    assert collapse[1] > 1.5 * collapse[0] > 0.0


def test_pump_up_above_the_separation_speed_and_not_below(hla_deck):
    """The constant-load train first separates between 1900 and 2100 rpm (camshaft): at 1800
    rpm neither does it separate nor does the adjuster pump up; at 2200 rpm it separates and
    the adjuster, taking up the gap, holds the valve open on the base circle."""
    from camtrain.dynamics.findings import findings

    deck, kin = hla_deck
    for rpm, above in ((1800.0, False), (2200.0, True)):
        _, rigid, found, _ = _run(deck, kin, rpm)
        separated = any(s.in_flight for s in findings(rigid).separations)
        assert separated is above
        assert found.pumped_up is above
        if above:
            assert found.extension_gain > found.held_open > 0.05e-3


def _march_only(deck, kin, scheme, refine, cycles=4):
    from camtrain.assemble.dynamics import setup
    from camtrain.dynamics import march
    from camtrain.dynamics.hla import with_element

    s = setup(deck, kin)
    model = with_element(s.model, replace(s.model.series.adjuster, scheme=scheme))
    return march(model, s.cam, s.base, replace(s.settings, substeps=s.settings.substeps * refine,
                                               cycles_min=cycles, cycles_max=cycles)), s


@pytest.mark.convergence
@pytest.mark.parametrize("scheme, low", [("backward_euler", 1.4), ("trapezoidal", 1.8)])
def test_march_with_the_adjuster_converges_at_its_observed_order(hla_deck, scheme, low):
    """Steps 1, 2, 4 times finer than the default against 16 times (four revolutions from
    rest each): fitted order of the valve lift, the plunger extension and the chamber
    pressure. Newmark is second order; the backward-Euler chamber is first order in its flows,
    whose share of the motion is small (observed 1.6-2.0; trapezoidal 2.0-2.3)."""
    deck, kin = hla_deck
    runs = [_march_only(deck, kin, scheme, f)[0] for f in (1, 2, 4, 16)]
    v = _march_only(deck, kin, scheme, 1, cycles=1)[1].model.valve
    ref = runs[-1]
    for rows in (lambda r: r.u[v], lambda r: r.hydraulic[3], lambda r: r.hydraulic[0]):
        errors = [float(np.max(np.abs(rows(r) - rows(ref)))) for r in runs[:-1]]
        assert low < _fitted_order(errors) < 2.5


@pytest.mark.convergence
def test_default_step_is_stable_and_accurate(hla_deck):
    """At the deck's default step the valve lift is within 2e-5 of the lift and the chamber
    pressure within 1 % of its peak of a march 16 times finer; at a step 3.5 times coarser
    (2 per grid interval) the backward-Euler chamber stays bounded (no growing oscillation
    while the check valve is open, where the chamber is stiffest)."""
    deck, kin = hla_deck
    fine, s = _march_only(deck, kin, "backward_euler", 16)
    default = _march_only(deck, kin, "backward_euler", 1)[0]
    v = s.model.valve
    lift = float(np.max(fine.u[v]))
    assert np.max(np.abs(default.u[v] - fine.u[v])) < 2e-5 * lift
    peak = float(np.max(fine.hydraulic[0]))
    assert np.max(np.abs(default.hydraulic[0] - fine.hydraulic[0])) < 0.01 * peak
    from camtrain.dynamics import march

    coarse_steps = max(2, s.settings.substeps // 4)
    coarse = march(s.model, s.cam, s.base, replace(s.settings, substeps=coarse_steps,
                                                   cycles_min=4, cycles_max=4))
    assert np.all(np.isfinite(coarse.hydraulic))
    assert np.max(coarse.hydraulic[0]) < 1.5 * peak


def _fitted_order(errors):
    h = np.array([1.0, 0.5, 0.25])
    return float(np.polyfit(np.log(h), np.log(errors), 1)[0])


@pytest.mark.parametrize("rpm", [1500.0, 3000.0, 6000.0])
def test_one_step_per_grid_interval_gives_a_finite_march(hla_deck, rpm):
    """The coarsest step the deck can ask for (steps_per_degree low enough that one step spans
    a grid interval: 1440 steps a revolution), below and far above the pump-up speed, with the
    trapezoidal chamber too: the march ends with finite states and chamber pressures, bounded
    by the adjuster's stroke (the chamber solve once bisected its whole bracket here)."""
    from camtrain.assemble.dynamics import setup
    from camtrain.dynamics import march
    from camtrain.dynamics.hla import with_element

    deck, kin = hla_deck
    s = setup(deck, kin, omega=rpm * math.pi / 30)
    for scheme in ("backward_euler", "trapezoidal"):
        model = with_element(s.model, replace(s.model.series.adjuster, scheme=scheme))
        resp = march(model, s.cam, s.base, replace(s.settings, substeps=1))
        assert resp.steps == kin.theta.size
        assert np.all(np.isfinite(resp.u)) and np.all(np.isfinite(resp.hydraulic))
        assert np.all(resp.hydraulic[3] <= model.series.adjuster.stroke + 1e-4)
