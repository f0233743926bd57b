"""The roller finger follower deck turns its roller; a pivoted follower's roller takes its inertia
from mechanism.roller.mass when [roller] gives none."""
from __future__ import annotations

import pytest

from camtrain import api
from tests.roller.conftest import DECKS

FINGER = DECKS / "roller_finger.toml"
ROCKER_ROLLER = ("mechanism.follower=roller", "roller.pin=needle",
                 "roller.needle_pitch_diameter=8")


def test_the_roller_finger_deck_turns_and_reports_losses_by_part():
    turning = api.run(api.load(FINGER))
    locked = api.run(api.load(FINGER, ("roller.pin=locked",)))
    assert "roller" in turning.plan.chosen
    m = turning.metrics
    parts = [m[k].value for k in ("roller_power_sliding", "roller_power_rolling",
                                  "roller_power_pin")]
    assert all(p > 0.0 for p in parts)
    assert m["roller_power_total"].value == pytest.approx(sum(parts), rel=1e-12)
    assert m["power_loss_mean"].value < 0.2 * locked.metrics["power_loss_mean"].value


@pytest.mark.derived
@pytest.mark.parametrize("deck, sets", [
    ("roller_finger", ()),
    ("rover_2300_rocker", ROCKER_ROLLER),
])
def test_the_roller_inertia_falls_back_on_the_mechanism_roller_mass(deck, sets):
    """[roller] without mass or inertia: J = m r^2 / 2 with m = mechanism.roller.mass, the same
    run (every metric) as the inertia given in [roller]."""
    path = DECKS / f"{deck}.toml"
    mass = 0.02
    # on a 1 deg grid (the decks' 0.25 deg costs four times the marching): the two routes to J
    # give the same run on any grid
    base = sets + ("roller.solver=inertial", f"mechanism.roller.mass={mass}",
                   "solver.angle_points=360")
    model = api.load(path, base).model
    radius = model.mechanism.follower_radius
    fallback = api.run(api.load(path, base))
    given = api.run(api.load(path, base + (f"roller.inertia={0.5 * mass * radius ** 2!r}",)))
    for name, metric in given.metrics.items():
        assert fallback.metrics[name].value == pytest.approx(metric.value, rel=1e-12,
                                                             abs=1e-15), name
    heavier = api.run(api.load(path, base + (f"roller.inertia={2.0 * mass * radius ** 2!r}",)))
    assert heavier.metrics["roller_slip_max"].value != pytest.approx(
        given.metrics["roller_slip_max"].value, rel=1e-6)


def test_the_roller_owns_the_entrainment_finding():
    """The non-rotating rocker's entrainment passes through zero; a turning roller's does not, so
    no zero-entrainment warning or event (the roller effect supersedes the kinematics' finding);
    a locked roller warns as the non-rotating face does."""
    path = DECKS / "rover_2300_rocker.toml"
    plain = api.run(api.load(path, ("mechanism.follower=roller",)))
    turning = api.run(api.load(path, ROCKER_ROLLER))
    locked = api.run(api.load(path, ("mechanism.follower=roller", "roller.pin=locked")))

    def zero(run):
        return [w for w in run.warnings if "entrainment velocity passes through zero" in w]

    assert len(zero(plain)) == 1
    assert zero(turning) == []
    assert zero(locked) == zero(plain)
    assert "zero_entrainment_1" in turning.metrics   # the face's kinematics stay reported
    assert turning.events_of("zero_entrainment") == []
    assert [e.at for e in locked.events_of("zero_entrainment")] == pytest.approx(
        [e.at for e in plain.events_of("zero_entrainment")], abs=1e-9)


@pytest.mark.derived
def test_the_locked_roller_finger_is_the_sliding_finger():
    """The RFF against a sliding finger follower of the same design: the deck without [roller]
    (a sliding pad of the roller's radius) equals the locked roller with the deck's friction
    law and no rolling resistance, in every metric."""
    import tomllib

    raw = tomllib.loads(FINGER.read_text(encoding="utf-8"))
    raw.pop("roller")
    import tomli_w

    sliding = api.run(api.loads(tomli_w.dumps(raw), "roller_finger_sliding.toml"))
    locked = api.run(api.load(FINGER, ("roller.pin=locked", "roller.traction=contact",
                                       "roller.rolling_resistance=none")))
    for name, m in sliding.metrics.items():
        assert locked.metrics[name].value == pytest.approx(m.value, rel=1e-9, abs=1e-15), name
