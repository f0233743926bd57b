"""The roller's speed marched as a state of the elastic train (camtrain.dynamics.spin): its
limits against the roller effect's own solvers on the same deck and load, and the observed
orders of the march (docs/rollers.md, "In the elastic train")."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from camtrain import api
from camtrain.assemble.dynamics import setup
from camtrain.contact.model import CamContact
from camtrain.dynamics import march
from camtrain.effects.roller import pin_of
from camtrain.roller.solve import RollerSettings, quasi_static_speed, solve_roller
from camtrain.roller.traction import Traction
from tests.roller.conftest import DECKS, chain

FINGER = DECKS / "roller_finger.toml"
DYNAMICS = ("dynamics.follower_mass=0.02", "dynamics.contact_stiffness=2.0e5",
            "dynamics.rocker_stiffness=1.5e4", "dynamics.seat_stiffness=2.0e5")
#: the load tables' interpolation error: linear in sqrt(W) over the 17 default levels, second
#: order in the level spacing (test_load_tables_converge_at_second_order); measured on this
#: deck without inertia 3.4e-3 of the largest speed at 17 levels, 1.2e-2 at 9 and 7.0e-4 at 33
#: (the largest at the lightest loads, 10 N, where the roller slips most)
TABLE_TOLERANCE = 5e-3


def _deck(*changes):
    return api.load(FINGER, DYNAMICS + changes).model


def _kinematics(deck):
    return chain(deck, upto=("kinematics",))["TrainKinematics"].main


def _marched(deck, kin, *, stiffness_scale=1.0, inertia=None, substeps=None):
    """The marched response and the roller's tables, with the spin inertia replaced."""
    s = setup(deck, kin, stiffness_scale=stiffness_scale)
    model = s.model
    if inertia is not None:
        model = replace(model, roller=replace(model.roller, inertia=inertia))
    settings = s.settings if substeps is None else replace(s.settings, substeps=substeps)
    return march(model, s.cam, s.base, settings), model.roller


def _traction(deck, kin, resp):
    """The roller effect's traction on the marched load (the valve-referred cam force times
    the load ratio at the grid angles)."""
    load = np.maximum(resp.contact_force[0] * np.asarray(kin.rocker_ratio), 0.0)
    contact = CamContact.from_deck(deck)
    r = deck.roller
    return Traction(contact, kin, load, contact.hertz(kin, load), r.traction,
                    r.rolling_resistance)


@pytest.fixture(scope="module")
def finger():
    deck = _deck()
    return deck, _kinematics(deck)


@pytest.mark.derived
def test_a_roller_without_inertia_on_a_frictionless_pin_rolls():
    """J = 0 and no pin torque: the balance r F_t(u_s) = 0 holds only at u_s = 0, so the
    marched roller rolls wherever the cam carries it (slip 0 to round-off)."""
    deck = _deck("roller.pin=frictionless")
    kin = _kinematics(deck)
    resp, tables = _marched(deck, kin, inertia=0.0)
    loaded = (resp.contact_force[0] > 0.0) & (np.abs(tables.v_s0)
                                               > 1e-3 * np.max(np.abs(tables.v_s0)))
    assert np.count_nonzero(loaded) > 100
    slip = resp.roller[1][loaded] / tables.v_s0[loaded]
    assert np.max(np.abs(slip)) < 1e-9


@pytest.mark.derived
def test_without_inertia_the_marched_speed_is_the_quasi_static_balance(finger):
    """J = 0 on the needle pin: the march solves the roller effect's quasi-static balance
    F_t r = T_pin at the marched load, to the load tables' interpolation."""
    deck, kin = finger
    resp, tables = _marched(deck, kin, inertia=0.0)
    traction = _traction(deck, kin, resp)
    w = quasi_static_speed(traction, pin_of(deck), tables.radius)
    err = np.max(np.abs(resp.roller[0] - w)) / np.max(np.abs(w))
    assert err < TABLE_TOLERANCE, err


@pytest.mark.derived
def test_stiff_train_marched_speed_is_the_roller_effects_periodic_speed(finger):
    """Contact, elements and seat 100 times stiffer (the load then follows the rigid train's
    without ringing between grid angles, which the roller effect could not see): the marched
    speed is the roller effect's inertial periodic speed at the train's load, with the same
    inertia, to the load tables' interpolation (the effect's march refined to 64 substeps on 801
    table points so that its own step error, first order, stays below 1e-4 of the speed)."""
    deck, kin = finger
    resp, tables = _marched(deck, kin, stiffness_scale=100.0)
    field = solve_roller(_traction(deck, kin, resp), pin_of(deck), tables.radius,
                         tables.inertia, RollerSettings(solver="inertial", substeps=64,
                                                        table_points=801))
    w = field.omega_roller
    err = np.max(np.abs(resp.roller[0] - w)) / np.max(np.abs(w))
    assert err < TABLE_TOLERANCE, err


@pytest.mark.derived
def test_tables_from_the_tabulated_integrals_are_the_exact_ones(monkeypatch):
    """The traction tables with the Greenwood-Tripp integrals from their table are those with
    the exact integrals (parabolic-cylinder functions at every table point) to 1e-12 of the
    largest traction, on the shipped roller finger with its adjuster (mixed film at light load
    and low entrainment)."""
    from camtrain.assemble.roller import spin_tables
    from camtrain.formulas import mixed

    deck = api.load(DECKS / "roller_finger_hla.toml").model
    kin = _kinematics(deck)
    fast = spin_tables(deck, kin, 1500.0).traction
    monkeypatch.setattr(mixed, "greenwood_tripp_tabulated", mixed.greenwood_tripp_function)
    exact = spin_tables(deck, kin, 1500.0).traction
    assert np.count_nonzero(exact != fast) > 1000   # the mixed film is in the tables
    assert np.max(np.abs(fast - exact)) < 1e-12 * np.max(np.abs(exact))


@pytest.mark.convergence
def test_load_tables_converge_at_second_order(finger):
    """The marched speed's distance from the roller effect's balance at the marched load falls
    as the square of the load-level spacing (J = 0, so the time step does not enter)."""
    deck, kin = finger
    levels = np.array([9, 17, 33])
    errors = []
    for n in levels:
        d = replace(deck, dynamics=replace(deck.dynamics, roller_load_levels=int(n)))
        resp, tables = _marched(d, kin, inertia=0.0)
        w = quasi_static_speed(_traction(d, kin, resp), pin_of(d), tables.radius)
        errors.append(np.max(np.abs(resp.roller[0] - w)))
    order = -np.polyfit(np.log(levels - 1), np.log(errors), 1)[0]
    assert 1.6 < order < 2.6, (errors, order)


@pytest.mark.convergence
def test_march_with_the_roller_converges_at_first_order(finger):
    """The roller's backward-Euler step is first order in the time step (the train's Newmark
    step is second): successive differences of the marched speed over halved steps fall at an
    observed order near 1."""
    deck, kin = finger
    ladder = [1, 2, 4, 8, 16]
    speeds = [_marched(deck, kin, substeps=m)[0].roller[0] for m in ladder]
    diffs = [np.max(np.abs(a - b)) for a, b in zip(speeds, speeds[1:], strict=False)]
    order = -np.polyfit(np.log(ladder[:-1]), np.log(diffs), 1)[0]
    assert 0.7 < order < 1.4, (diffs, order)


def test_the_default_step_is_stable(finger):
    """At the deck's default step the march reaches its periodic state and the marched speed
    stays between standing and the fastest rolling speed of the cycle (the roller is driven
    towards rolling and braked by its pin: backward Euler damps the stiff rolling mode instead
    of overshooting it), with no step-to-step ringing where the cam carries it."""
    deck, kin = finger
    resp, tables = _marched(deck, kin)
    assert resp.converged
    rolling = tables.v_s0 / tables.radius
    w = resp.roller[0]
    top = np.max(np.abs(rolling))
    assert np.all(w >= -1e-9 * top)
    assert np.all(w <= top * (1.0 + 1e-9))
    # ringing would alternate the sign of the speed's second difference from sample to sample
    loaded = resp.contact_force[0] > 0.0
    second = np.diff(w, 2)[loaded[1:-1]]
    flips = np.count_nonzero(np.sign(second[1:]) * np.sign(second[:-1]) < 0)
    assert flips < 0.1 * second.size, flips


def test_a_marched_roller_needs_the_newmark_integrator():
    """The roller's step lives in the Newmark march: another integrator is refused, naming the
    field, unless the roller is solved after the march."""
    from camtrain.errors import InputError

    with pytest.raises(InputError) as err:
        api.load(FINGER, DYNAMICS + ("dynamics.integrator=lsoda",))
    assert "dynamics.integrator" in str(err.value)
    after = api.load(FINGER, DYNAMICS + ("dynamics.integrator=lsoda", "dynamics.roller=after"))
    assert after.model.dynamics.roller == "after"


@pytest.mark.derived
def test_the_train_carries_the_finger_and_the_rollers_swing_at_the_valve(finger):
    """The finger's inertia about its pivot and the roller's mass at its centre (m_r A^2) are
    in the elastic train's masses, reduced to the valve by the arm B (Teodorescu 2005 eqs
    A1-A3, I / B^2), beside the valve side and the finger's own valve-referred mass: the total
    is the rigid train's; the roller's spin inertia is not a mass of the train."""
    deck, kin = finger
    model = setup(deck, kin).model
    lever = deck.mechanism.dyson()
    m = deck.masses
    swing = (m.rocker_inertia + deck.mechanism.roller.mass * lever.A ** 2) / lever.B ** 2
    assert model.total_mass() == pytest.approx(m.valve_side + m.follower + swing, rel=1e-12)
    assert model.roller.inertia == pytest.approx(
        0.5 * deck.mechanism.roller.mass * model.roller.radius ** 2, rel=1e-12)


def test_a_turning_roller_is_refused_by_the_two_way_coupled_camshaft():
    """The coupled march's contact friction is the sliding contact's, not the roller's
    traction: the deck says so instead of running a roller as a sliding follower."""
    from camtrain.deck.schema_dynamics import dynamics_problems

    deck = _deck()
    shaft = type("Flexibility", (), {"coupling": "two_way"})()
    camshaft = type("Camshaft", (), {"flexibility": shaft})()
    fields = [p.path for p in dynamics_problems(replace(deck, camshaft=camshaft))]
    assert "camshaft.flexibility.coupling" in fields
    locked = replace(deck, camshaft=camshaft, roller=replace(deck.roller, pin="locked"))
    assert "camshaft.flexibility.coupling" not in [p.path for p in dynamics_problems(locked)]
