"""Results with axes, components and events; saved and loaded back; a DataFrame per axis."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain import api
from camtrain.result import Result
from tests.conftest import DECKS


@pytest.fixture(scope="module")
def desmo():
    return api.run(DECKS / "desmo_rig.toml")


@pytest.fixture(scope="module")
def camshaft():
    return api.run(DECKS / "zeta_intake_camshaft.toml")


def test_every_column_knows_its_axis(desmo):
    assert desmo.axes == ["cam_angle"]
    assert all(c.axis == "cam_angle" for c in desmo.columns.values())
    bearing = api.run(DECKS / "bearing_ocvirk_check.toml")
    assert bearing.axes == ["angle"] and bearing.columns["eccentricity"].axis == "angle"


def test_components_instead_of_prefixes(desmo, camshaft):
    assert desmo.components == ["closing"]
    closing = desmo.component("closing")
    np.testing.assert_array_equal(closing["load"], desmo["closing_load"])
    assert closing.metrics["load_max"] is desmo.metrics["closing_load_max"]
    assert "load" in desmo.component(None).columns       # the train itself
    assert camshaft.components[:3] == ["bearing_1", "bearing_2", "bearing_3"]
    b3 = camshaft.component("bearing_3")
    assert {"load_x", "eccentricity", "min_film"} <= set(b3.columns)
    assert b3.metrics["power_mean"].value == camshaft.metrics["bearing_3_power_mean"].value
    with pytest.raises(KeyError, match="no component"):
        camshaft.component("bearing_99")


def test_events_carry_their_angles(desmo):
    handovers = desmo.events_of("handover")
    assert [e.at for e in handovers] == [desmo.metrics[f"handover_{j + 1}"].value
                                         for j in range(len(handovers))]
    assert handovers and all(e.axis == "cam_angle" for e in handovers)
    zero = api.run(DECKS / "harrison_flat.toml").events_of("zero_entrainment")
    assert zero and all(-np.pi <= e.at <= np.pi for e in zero)


def test_contact_loss_events_bracket_the_lost_angles():
    from dataclasses import replace

    deck = api.load(DECKS / "harrison_flat.toml").model
    fast = replace(deck, speed=replace(deck.speed, camshaft=4000 * np.pi / 30))
    res = api.run(fast)
    loss, back = res.events_of("contact_loss"), res.events_of("contact_regained")
    assert loss and len(loss) == len(back)
    theta, load = res["cam_angle"], res["load"]
    for start, end in zip(loss, back, strict=True):
        inside = (theta >= start.at) & (theta <= end.at)
        assert np.all(load[inside] <= 0.0)


def test_save_and_load_give_the_same_result(desmo, tmp_path):
    back = Result.load(desmo.save(tmp_path / "desmo.npz"))
    assert list(back.columns) == list(desmo.columns)
    for k, c in desmo.columns.items():
        np.testing.assert_array_equal(back[k], c.values)
        assert (back.columns[k].unit, back.columns[k].axis, back.columns[k].component) == \
            (c.unit, c.axis, c.component)
    assert repr(back.metrics) == repr(desmo.metrics)  # (NaN metrics: compare the text)
    assert back.events == desmo.events and back.warnings == desmo.warnings
    assert back.plan.as_dict() == desmo.plan.as_dict()
    assert back.components == desmo.components


def test_dataframe_per_axis(desmo):
    pd = pytest.importorskip("pandas")
    df = desmo.to_dataframe("cam_angle")
    assert isinstance(df, pd.DataFrame) and df.index.name == "cam_angle"
    assert len(df) == desmo["cam_angle"].size and "closing_load" in df.columns
    assert df.attrs["units"]["load"] == "N"
    with pytest.raises(KeyError, match="no axis"):
        desmo.to_dataframe("time")


def test_repr_is_short(desmo):
    text = repr(desmo)
    assert len(text) < 600 and "kinematics" in text and "closing" in text
    assert "array" not in text


def test_a_second_axis():
    r = Result()
    r.add_axis("cam_angle", np.linspace(0, 1, 5), "rad", "cam angle")
    r.add_axis("time", np.linspace(0, 2, 9), "s", "time")
    r.add_column("lift", np.zeros(5), "m", "lift")
    r.add_column("x", np.ones(9), "m", "valve position", axis="time", component="valve_1")
    assert r.columns["lift"].axis == "cam_angle" and set(r.on_axis("time")) == {"time", "valve_1_x"}
    with pytest.raises(KeyError):
        r.add_column("y", np.ones(9), "m", "y", axis="crank_angle")
