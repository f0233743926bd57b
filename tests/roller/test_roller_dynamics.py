"""A deck with [dynamics] and [roller]: the roller turns on the elastic train's contact load
(the dynamics effect's ContactLoad, rank 1 over the rigid one), one way (docs/rollers.md)."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain import api
from camtrain.effects.roller import pin_of
from tests.roller.conftest import DECKS

FINGER = DECKS / "roller_finger.toml"
DYNAMICS = ("dynamics.follower_mass=0.02", "dynamics.contact_stiffness=2.0e5",
            "dynamics.rocker_stiffness=1.5e4", "dynamics.seat_stiffness=2.0e5")


@pytest.fixture(scope="module", params=["quasi_static", "inertial"])
def elastic(request):
    loaded = api.load(FINGER, DYNAMICS + (f"roller.solver={request.param}",))
    return loaded.model, api.run(loaded)


def test_the_roller_runs_after_the_dynamic_load(elastic):
    _, run = elastic
    order = [spec.name for spec in run.plan.effects]
    assert "loads" not in order
    assert order.index("dynamics") < order.index("roller")


@pytest.mark.derived
def test_the_pin_carries_the_dynamic_load(elastic):
    """The needle pin's torque M_0(w) + f_1 W d_m is that of the elastic train's load W (the
    `load` column), not of the rigid train's (`rigid_load`), which differs by tens of per cent."""
    deck, run = elastic
    load, rigid = np.maximum(run["load"], 0.0), np.maximum(run["rigid_load"], 0.0)
    assert np.max(np.abs(load - rigid)) > 0.1 * np.max(rigid)
    pin = pin_of(deck)
    w = run["roller_speed"]
    np.testing.assert_allclose(run["pin_torque"], pin.torque(w, load), rtol=1e-12, atol=1e-15)
    assert not np.allclose(run["pin_torque"], pin.torque(w, rigid), rtol=1e-3)
    # where the elastic train separates from the cam the roller carries no traction
    free = run["load"] <= 0.0
    assert np.all(run["roller_traction"][free] == 0.0)


def test_the_dynamics_run_marches_the_roller(elastic):
    """The roller's speed is a state of the elastic train's march: its columns and key metric
    come from the dynamics effect, and its panel is on the dynamics sheet (docs/rollers.md)."""
    from camtrain.catalogue import declared_panels

    _, run = elastic
    w, rolling = run["roller_speed_marched"], run["roller_speed_rolling"]
    loaded = run["load"] > 0.0
    assert np.all(np.isfinite(w))
    # a turning roller on its needle pin: near rolling where it carries load
    assert np.max(np.abs(w - rolling)[loaded]) < 0.2 * np.max(np.abs(rolling))
    assert 0.0 <= run.metrics["roller_slip_max_marched"].value < 0.2
    assert "roller_spin" in declared_panels(run.plan)
    assert "roller speed marched" in next(s.reason for s in run.plan.steps
                                          if s.effect == "dynamics")


@pytest.mark.derived
def test_the_roller_effect_takes_the_marched_speed(elastic):
    """With dynamics.roller = "marched" the marched speed is the run's roller speed (the
    dynamics effect's RollerSpin): the roller effect's speed, slip and sliding are the marched
    ones, its traction the one the march balanced that speed with (near rolling the law is
    too steep in the sliding to be read at a speed within the tables' error), its film and
    pin torque the laws' at that speed and the train's load, whatever roller.solver says; its
    plan step says so."""
    from camtrain.contact.model import CamContact
    from camtrain.roller.traction import Traction
    from tests.roller.conftest import chain

    deck, run = elastic
    np.testing.assert_array_equal(run["roller_speed"], run["roller_speed_marched"])
    # the sliding V_c - V_f - w_r r_r, and the slip, to round-off of the marched ones
    top = np.max(np.abs(run["roller_sliding_marched"]))
    np.testing.assert_allclose(run["roller_sliding"], run["roller_sliding_marched"], rtol=0,
                               atol=1e-12 * top)
    fin = np.isfinite(run["roller_slip_marched"]) & (run["load"] > 0.0)
    np.testing.assert_allclose(run["roller_slip"][fin], run["roller_slip_marched"][fin],
                               rtol=0, atol=1e-9)
    kin = chain(deck, upto=("kinematics",))["TrainKinematics"].main
    load = np.maximum(run["load"], 0.0)
    contact = CamContact.from_deck(deck)
    traction = Traction(contact, kin, load, contact.hertz(kin, load), deck.roller.traction,
                        deck.roller.rolling_resistance)
    np.testing.assert_array_equal(run["roller_traction"], run["roller_traction_marched"])
    film = traction.film(run["roller_sliding"]).min
    loaded = load > 0.0
    np.testing.assert_allclose(run["film_min"][loaded], film[loaded], rtol=1e-12)
    np.testing.assert_allclose(run["pin_torque"], pin_of(deck).torque(run["roller_speed"], load),
                               rtol=1e-12, atol=1e-15)
    assert run.metrics["roller_slip_max"].value == pytest.approx(
        run.metrics["roller_slip_max_marched"].value, rel=1e-12)
    reason = next(s.reason for s in run.plan.steps if s.effect == "roller")
    assert "marched with the elastic train" in reason


@pytest.mark.derived
def test_the_marched_rollers_energy_closes_over_the_cycle(elastic):
    """In the periodic state the spin's kinetic energy returns: the cycle mean of
    (r F_t - T_pin) w_r, the power into the spin, vanishes to the pin table's interpolation
    (below 1 % of the pin loss), so the cam's traction power F_t V_s0 is the sliding and pin
    losses. With the law's traction at the marched speed it missed by 26 % of the pin loss on
    decks/roller_finger_hla.toml."""
    deck, run = elastic
    w, r = run["roller_speed"], float(deck.mechanism.follower_radius)
    assert r == pytest.approx(8.75e-3)   # SI
    into_spin = np.mean((r * run["roller_traction"] - run["pin_torque"]) * w)
    assert abs(into_spin) < 1e-2 * np.mean(run["power_pin"]), (into_spin,
                                                              np.mean(run["power_pin"]))


def test_after_the_roller_effect_solves_its_own_speed():
    """dynamics.roller = "after": the train marches no roller (RollerSpin without a speed) and
    the roller effect solves its own speed at the train's load, as its plan step says."""
    from camtrain.contact.model import CamContact
    from camtrain.roller.solve import quasi_static_speed
    from camtrain.roller.traction import Traction
    from tests.roller.conftest import chain

    loaded = api.load(FINGER, DYNAMICS + ("dynamics.roller=after",))
    run = api.run(loaded)
    assert "roller_speed_marched" not in run.columns
    reason = next(s.reason for s in run.plan.steps if s.effect == "roller")
    assert "marched" not in reason and "quasi-static" in reason
    marched = api.run(api.load(FINGER, DYNAMICS))
    # the train's load is the same march (the roller does not act back on the train) ...
    np.testing.assert_allclose(run["load"], marched["load"], rtol=1e-9, atol=1e-9)
    # ... the roller's speed is its own quasi-static balance at that load ...
    deck = loaded.model
    kin = chain(deck, upto=("kinematics",))["TrainKinematics"].main
    load = np.maximum(run["load"], 0.0)
    contact = CamContact.from_deck(deck)
    traction = Traction(contact, kin, load, contact.hertz(kin, load), deck.roller.traction,
                        deck.roller.rolling_resistance)
    w = quasi_static_speed(traction, pin_of(deck), float(np.max(kin.follower_radius)))
    np.testing.assert_allclose(run["roller_speed"], w, rtol=1e-12, atol=1e-12)
    # ... which differs from the marched one (the spin inertia, the tables)
    assert not np.allclose(run["roller_speed"], marched["roller_speed"], rtol=1e-6)
