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
