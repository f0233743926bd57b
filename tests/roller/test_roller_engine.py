"""An engine deck includes roller valve trains ([[flame.valve_trains]]): a camshaft of roller
followers, whose camshaft bearings and drive take the roller's friction torque, and the roller
finger follower deck, whose valve pad and pivot FLAME counts beside its cam."""
from __future__ import annotations

import tomllib

import pytest
import tomli_w

from camtrain import api
from tests.roller.conftest import DECKS

ROLLER = {"width": 10.0, "pin": "needle", "needle_pitch_diameter": 10.0,
          "solver": "quasi_static"}
LOCKED = dict(ROLLER, pin="locked", traction="contact", rolling_resistance="none")


def _raw(name):
    return tomllib.loads((DECKS / f"{name}.toml").read_text(encoding="utf-8"))


def roller_camshaft(roller=ROLLER):
    """The Zeta intake camshaft (eight cams, five bearings) on 10 mm roller followers: the
    cam without its taper, so that the roller's contact is a line."""
    raw = _raw("zeta_intake_camshaft")
    raw["mechanism"] = {"type": "domed", "follower_radius": 10.0,
                        "follower_shape": "cylindrical"}
    raw["cam"].pop("taper_angle")
    if roller is not None:
        raw["roller"] = roller
    return raw


def _run(raw, name="roller_camshaft.toml"):
    return api.run(api.loads(tomli_w.dumps(raw), str(DECKS / name)))


@pytest.fixture(scope="module")
def camshafts():
    return {k: _run(roller_camshaft(r)) for k, r in
            (("turning", ROLLER), ("locked", LOCKED), ("plain", None))}


def test_the_camshaft_takes_the_roller_torque(camshafts):
    """The camshaft's drive and bearings run on the roller's friction: a locked roller with the
    deck's friction law is the non-rotating cylinder; the turning roller cuts the drive power."""
    turning, locked, plain = camshafts["turning"], camshafts["locked"], camshafts["plain"]
    assert {"roller", "camshaft_torque", "bearings"} <= set(turning.plan.chosen)
    for name in ("drive_power_mean", "bearings_power_total"):
        assert locked.metrics[name].value == pytest.approx(plain.metrics[name].value,
                                                           rel=1e-9), name
    assert turning.metrics["drive_power_mean"].value < 0.5 * plain.metrics[
        "drive_power_mean"].value
    assert turning.metrics["bearings_power_total"].value != plain.metrics[
        "bearings_power_total"].value


def test_an_engine_includes_roller_valve_trains(tmp_path, camshafts):
    """FLAME's valve train of an engine that includes the roller camshaft and 16 roller finger
    followers: the camshaft's drive and bearing power, and the fingers' cam power plus their
    valve pad and pivot, as the included decks' own runs give them."""
    (tmp_path / "roller_camshaft.toml").write_text(tomli_w.dumps(roller_camshaft()),
                                                   encoding="utf-8")
    raw = _raw("zeta_engine")
    raw["flame"]["valve_trains"] = [
        {"name": "roller camshaft", "deck": str(tmp_path / "roller_camshaft.toml")},
        {"name": "roller fingers", "deck": str(DECKS / "roller_finger.toml"), "trains": 16}]
    engine = _run(raw, str(tmp_path / "engine.toml"))
    m = engine.metrics
    shaft = camshafts["turning"].metrics      # the engine runs it at 1500 rpm camshaft, as here
    assert m["roller_camshaft_cams_power"].value == pytest.approx(
        shaft["drive_power_mean"].value, rel=1e-9)
    assert m["roller_camshaft_bearings_power"].value == pytest.approx(
        shaft["bearings_power_total"].value, rel=1e-9)
    finger = api.run(api.load(DECKS / "roller_finger.toml")).metrics   # 1500 rpm camshaft
    assert m["roller_fingers_cams_power"].value == pytest.approx(
        16 * finger["power_loss_mean"].value, rel=1e-9)
    assert m["roller_fingers_arms_power"].value == pytest.approx(
        16 * finger["arm_power_mean"].value, rel=1e-9)
    parts = [m[f"{vt}_power"].value for vt in ("roller_camshaft", "roller_fingers")]
    assert m["flame_valve_train"].value == pytest.approx(sum(parts), rel=1e-12)
