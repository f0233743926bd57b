"""The rocker shaft as a plain journal bearing (mechanism.arm.pivot_model = "journal")."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain import api
from camtrain.bearings import JournalBearing
from camtrain.deck.templates import render_template
from camtrain.errors import InputError
from camtrain.mechanisms.arm_contacts import journal_pivot_torque

JOURNAL = ("mechanism.arm.pivot_model=journal", "mechanism.arm.pivot_length=20",
           "mechanism.arm.pivot_clearance=20")


def _template(name, sets=()):
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / f"{name}.toml"
        path.write_text(render_template(name), encoding="utf-8")
        return api.load(path, sets)


def _rocker(sets=()):
    return _template("roller_rocker", sets)


@pytest.mark.derived
def test_light_load_journal_pivot_is_petroff():
    """Vanishing load: eps -> 0 and the Couette torque is Petroff's 2 pi eta w r^3 L / c."""
    b = JournalBearing(0.016, 0.020, 20e-6, 0.01)
    w = np.array([50.0, -50.0])
    t = journal_pivot_torque(b, w, np.array([1e-6, 1e-6]))
    petroff = 2.0 * math.pi * 0.01 * 50.0 * 0.008 ** 3 * 0.020 / 20e-6
    assert t == pytest.approx([petroff, petroff], rel=1e-6)
    assert journal_pivot_torque(b, np.array([0.0]), np.array([500.0]))[0] == 0.0


def test_journal_pivot_on_the_rocker_deck():
    """The template's roller rocker with its shaft as a journal bearing: the pivot torque is
    the bearing's under the pivot reaction at the arm's speed, and rises with the load."""
    coulomb = api.run(_rocker())
    loaded = _rocker(JOURNAL)
    journal = api.run(loaded)
    arm = loaded.model.mechanism.arm
    b = JournalBearing(2 * arm.pivot_radius, arm.pivot_length, arm.pivot_clearance,
                       loaded.model.lubricant.viscosity)
    rate = journal["pivot_friction_power"]
    torque = journal["pivot_friction_torque"]
    assert np.all(torque >= 0.0) and np.any(torque > 0.0)
    assert journal.metrics["pivot_power_mean"].value != coulomb.metrics["pivot_power_mean"].value
    moving = torque > 0.0
    speed = rate[moving] / torque[moving]
    np.testing.assert_allclose(
        torque[moving], journal_pivot_torque(b, speed, journal["pivot_reaction"][moving]),
        rtol=1e-9)


@pytest.mark.parametrize("sets, field", [
    (("mechanism.arm.pivot_model=journal",), "mechanism.arm.pivot_length"),
    (("mechanism.arm.pivot_model=journal", "mechanism.arm.pivot_length=20"),
     "mechanism.arm.pivot_clearance"),
])
def test_journal_pivot_bad_input_names_the_field(sets, field):
    with pytest.raises(InputError) as exc:
        _rocker(sets)
    assert field in str(exc.value)


def test_a_finger_refuses_a_journal_pivot():
    loaded = _template("roller_finger", JOURNAL)
    with pytest.raises(InputError) as exc:
        api.run(loaded)
    assert "mechanism.arm.pivot_model" in str(exc.value)
