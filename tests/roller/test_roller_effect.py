"""The roller effect on the shipped roller deck: the locked limit through the whole chain, the
plan, the outputs, and bad input."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain import api
from camtrain.errors import InputError
from tests.roller.conftest import DECKS

NEEDLE = DECKS / "harrison_roller_needle.toml"
LOCKED = ("roller.pin=locked", "roller.traction=contact", "roller.rolling_resistance=none")


@pytest.fixture(scope="module")
def runs():
    rotating = api.run(api.load(NEEDLE))
    locked = api.run(api.load(NEEDLE, LOCKED))
    plain = api.run(api.load(DECKS / "harrison_roller.toml"))
    return rotating, locked, plain


@pytest.mark.derived
def test_locked_roller_every_column_equals_the_non_rotating_follower(runs):
    """Infinite pin friction with the deck's friction law and no rolling resistance: every
    column and metric the non-rotating roller deck computes is the same to 1e-9."""
    _, locked, plain = runs
    assert set(plain.columns) <= set(locked.columns)
    for name, col in plain.columns.items():
        a, b = np.asarray(locked[name], dtype=float), np.asarray(col.values, dtype=float)
        np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-12 * np.nanmax(np.abs(b)) + 0.0,
                                   equal_nan=True, err_msg=name)
    for name, m in plain.metrics.items():
        assert locked.metrics[name].value == pytest.approx(m.value, rel=1e-9, abs=1e-15), name
    assert np.all(locked["roller_speed"] == 0.0)


def test_the_plan_takes_film_and_friction_from_the_roller(runs):
    rotating, _, plain = runs
    chosen = rotating.plan.chosen
    assert "roller" in chosen and "film" not in chosen and "friction" not in chosen
    assert "roller" not in plain.plan.chosen and "film" in plain.plan.chosen


def test_the_roller_saves_friction_and_reports_it_by_part(runs):
    rotating, _, plain = runs
    m = rotating.metrics
    parts = [m[k].value for k in ("roller_power_sliding", "roller_power_rolling",
                                  "roller_power_pin")]
    assert m["roller_power_total"].value == pytest.approx(sum(parts), rel=1e-12)
    assert m["power_loss_mean"].value < 0.2 * plain.metrics["power_loss_mean"].value
    assert rotating.columns["roller_slip"].unit == "-"
    assert rotating.columns["roller_speed"].unit == "rad/s"
    srr = rotating["slide_roll_ratio"][rotating["load"] > 0]
    assert np.nanmin(srr) < 0.0 < np.nanmax(srr)


@pytest.mark.parametrize("sets, field", [
    (("roller.pin=bushing",), "roller.pin_diameter"),
    (("mechanism.follower_shape=spherical",), "mechanism.follower_shape"),
    (("tribology.film_model=squeeze",), "tribology.film_model"),
])
def test_bad_roller_input_names_the_field(sets, field):
    with pytest.raises(InputError) as exc:
        api.load(NEEDLE, sets)
    assert field in str(exc.value)


@pytest.mark.derived
def test_the_losses_by_part_sum_to_the_contact_dissipation():
    """Quasi-static: the traction's power F_t V_s0 goes to sliding and to the pin, the rolling
    force's to rolling, so sliding + rolling + pin = F |V_s| (the power effect's dissipation)."""
    m = api.run(api.load(NEEDLE, ("roller.solver=quasi_static",))).metrics
    assert m["roller_power_total"].value == pytest.approx(m["dissipation_mean"].value, rel=1e-8)


@pytest.mark.parametrize("deck", ["pinto_finger", "rover_2300_rocker"])
def test_a_pivoted_curved_follower_carries_a_roller(deck):
    """The roller reads only the kinematics' speeds and radius: an end-pivoted finger and a
    centre-pivoted rocker with a curved face turn it as well, and it saves most of the sliding
    friction of the same follower."""
    sets = ("roller.pin=needle", "roller.needle_pitch_diameter=8")
    rolling = api.run(api.load(DECKS / f"{deck}.toml", sets))
    sliding = api.run(api.load(DECKS / f"{deck}.toml"))
    assert "roller" in rolling.plan.chosen
    assert rolling.metrics["roller_slip_max"].value < 0.2
    assert rolling.metrics["power_loss_mean"].value < 0.1 * sliding.metrics[
        "power_loss_mean"].value
