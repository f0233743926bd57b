"""The chain's shared pieces over a leading case axis equal a run of each case alone.

A run and the sweep batch share one friction/load iteration (`loads.iteration.iterate_cases`),
one translating-follower kinematics builder, one set of geometry predicates and the effects'
metric definitions (`camtrain.metric_rows`): with two cases stacked, each row must be the
one-case result, bit for bit (the same operations on the same numbers).
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from camtrain.effects.kinematics import zero_crossings, zero_crossings_rows
from camtrain.effects.loads import load_metrics
from camtrain.loads import contact_load, iterate_load
from camtrain.loads.bounce import bounce_speeds
from camtrain.loads.iteration import iterate_cases
from camtrain.mechanisms.checks import cases_pass
from camtrain.metric_rows import one_case, per_case

pytestmark = pytest.mark.derived

K, DELTA, M = 38254.0, 6.4e-3, 0.172


def _with_friction_arm(kin, ratio=0.3):
    """A follower whose load depends on mu (as a pivoted one): arm_friction = ratio arm_normal."""
    return replace(kin, arm_friction=ratio * kin.arm_normal)


def _stacked(kin, n):
    """The kinematics of ``n`` identical cases, as (cases, angles) arrays."""
    fields = {k: np.broadcast_to(v, (n, v.size)) for k, v in vars(kin).items()
              if isinstance(v, np.ndarray)}
    inertia = {k: np.broadcast_to(v, (n, v.size)) for k, v in kin.inertia.items()}
    return replace(kin, inertia=inertia, **fields)


def test_iteration_per_case_equals_each_case_alone(harrison_kin):
    """A load-dependent coefficient mu = c sqrt(W / 1 kN): the two levels of c need different
    iteration counts, and each row stops at its own."""
    kin = _with_friction_arm(harrison_kin)
    rates = np.array([[K], [0.6 * K]])
    coefficients = np.array([[0.02], [0.3]])
    both = _stacked(kin, 2)
    cases = iterate_cases(lambda mu: contact_load(both, mu, rate=rates, preload_compression=DELTA,
                                                  valve_mass=M),
                          lambda w: coefficients * w * np.sqrt(np.abs(w) / 1e3), mu0=0.08,
                          tolerance=1e-12)
    for r in range(2):
        alone = iterate_load(lambda mu, r=r: contact_load(kin, mu, rate=rates[r, 0],
                                                          preload_compression=DELTA,
                                                          valve_mass=M),
                             lambda w, r=r: coefficients[r, 0] * w * np.sqrt(np.abs(w) / 1e3),
                             mu0=0.08, tolerance=1e-12)
        np.testing.assert_array_equal(cases.load[r], alone.load)
        np.testing.assert_array_equal(cases.mu[r], alone.mu)
        np.testing.assert_array_equal(cases.friction[r], alone.friction)
        assert cases.iterations[r] == alone.iterations and cases.converged[r]
    assert cases.iterations[0] != cases.iterations[1]


def test_iteration_reports_the_case_that_does_not_converge(harrison_kin):
    """The frictionless case starts at its fixed point (one pass); the other needs more."""
    kin = _stacked(_with_friction_arm(harrison_kin), 2)
    cases = iterate_cases(lambda mu: contact_load(kin, mu, rate=K, preload_compression=DELTA,
                                                  valve_mass=M),
                          lambda w: np.array([[0.0], [0.05]]) * w,
                          mu0=np.array([[0.0], [0.08]]), tolerance=1e-14, max_iterations=1)
    assert cases.converged.tolist() == [True, False]


def test_metrics_of_stacked_cases_are_the_run_metrics(harrison_kin):
    kin = harrison_kin
    both = _stacked(kin, 2)
    kw = dict(rate=K, preload_compression=DELTA, valve_mass=M)
    load = contact_load(kin, **kw)
    inside = kin.valve_lift > 0.0
    run = one_case(load_metrics(kin.theta, load, inside, 1, 1e-6, bounce_speeds(kin, **kw)))
    rows = per_case(load_metrics(both.theta, np.broadcast_to(load, both.theta.shape), inside,
                                 np.ones(2, dtype=int), 1e-6, bounce_speeds(both, **kw)), 2)
    assert rows[0] == rows[1] == [(name, float(value), unit) for name, value, unit, *_ in run]


def test_zero_crossings_rows_are_the_single_crossings():
    theta = np.linspace(-np.pi, np.pi, 360, endpoint=False)
    values = np.vstack([np.sin(3.0 * theta + 0.1), np.where(np.abs(theta) < 0.5, 0.0, 1.0),
                        np.ones_like(theta)])
    rows = zero_crossings_rows(theta, values)
    assert rows == [zero_crossings(theta, v) for v in values]
    assert len(rows[0]) == 6 and rows[2] == []


def test_geometry_predicates_per_case(harrison_kin):
    """A base radius below Ball's convexity limit fails the flat-face check only in its row."""
    kin = harrison_kin
    rc = kin.cam_radius
    concave = replace(kin, cam_radius=rc - (rc.min() + 1e-3))
    both = _stacked(kin, 2)
    stacked = replace(both, cam_radius=np.vstack([rc, concave.cam_radius]))
    assert cases_pass(stacked, flat=True).tolist() == [True, False]
    assert cases_pass(stacked, flat=True, face_length=1e-6).tolist() == [False, False]
