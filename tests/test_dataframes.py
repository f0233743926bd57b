"""pandas views: a run's columns in deck units by default (cam angle in degrees, SI on request),
its metrics, and a sweep's outcomes from camtrain.api."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain import api
from tests.conftest import DECKS

pd = pytest.importorskip("pandas")


@pytest.fixture(scope="module")
def harrison():
    return api.run(api.load(DECKS / "harrison_flat.toml", ["solver.angle_points=360"]))


def test_columns_in_deck_units_by_default(harrison):
    df = harrison.to_dataframe()
    assert df.index.name == "cam_angle" and df.attrs["units"]["cam_angle"] == "deg"
    np.testing.assert_allclose(df.index.to_numpy(), np.degrees(harrison["cam_angle"]))
    assert df.attrs["units"]["film_min"] == "µm"
    np.testing.assert_allclose(df["film_min"].to_numpy(), harrison["film_min"] * 1e6)
    assert df.attrs["units"]["hertz_pmax"] == "MPa"


def test_columns_in_si_on_request(harrison):
    df = harrison.to_dataframe(units="si")
    assert df.attrs["units"]["cam_angle"] == "rad"
    np.testing.assert_array_equal(df.index.to_numpy(), harrison["cam_angle"])
    np.testing.assert_array_equal(df["film_min"].to_numpy(), harrison["film_min"])


def test_metrics_frame(harrison):
    frame = harrison.metrics_frame()
    row = frame.loc["hertz_max"]
    m = harrison.metrics["hertz_max"]
    assert row["unit"] == "MPa" and row["value"] == pytest.approx(m.value * 1e-6)
    assert row["angle"] == pytest.approx(math.degrees(m.angle))
    si = harrison.metrics_frame(units="si").loc["hertz_max"]
    assert si["unit"] == "Pa" and si["value"] == m.value
    assert set(frame.index) == set(harrison.metrics)


def test_sweep_from_the_api_gives_a_dataframe(tmp_path):
    outcome = api.sweep(DECKS / "harrison_flat.toml", {"base_radius": [17.0, 19.0]},
                        tmp_path / "rb", sets=["solver.angle_points=360"])
    df = outcome.to_dataframe()
    assert list(df.index) == [0, 1] and df.index.name == "case"
    assert list(df["base_radius"]) == [17.0, 19.0]
    assert (df["status"] == "ok").all()
    assert "power_loss_mean[W]" in df.columns
    ranged = api.sweep(DECKS / "harrison_flat.toml", {"base_radius": "range:17:19:3"},
                       tmp_path / "rb3", sets=["solver.angle_points=360"]).to_dataframe()
    assert list(ranged["base_radius"]) == [17.0, 18.0, 19.0]
    np.testing.assert_allclose(ranged["power_loss_mean[W]"].iloc[[0, 2]],
                               df["power_loss_mean[W]"], rtol=1e-12)
