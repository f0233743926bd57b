"""The elastic camshaft in a deck ([camshaft.flexibility]): its named splits reproduce today's
bearing loads, its statics balance, its mean twist is the closed form of a shaft in torsion, and
the plan says what ran (Teodorescu et al. 2005 §2.6)."""
from __future__ import annotations

import math

import numpy as np
import pytest

import camtrain.api as ct
from camtrain.errors import InputError
from camtrain.scene import resolve

from .conftest import camshaft_deck

BEARINGS = 3
LOBES = (30.0, 80.0, 130.0, 230.0)  # mm, the conftest layout; the drive sits at -35 mm
DRIVE = -35.0


def flexible(split="elastic", response="dynamic", extra=""):
    section = (f'[camshaft.flexibility]\ndiameter = 24.0\nsplit = "{split}"\n'
               f'response = "{response}"\n{extra}\n')
    return ct.loads(camshaft_deck("petroff", extra=section))


@pytest.fixture(scope="module")
def rigid_bays():
    return ct.run(ct.loads(camshaft_deck("petroff")))


def loads_of(result, column="load"):
    return np.array([[result.component(f"bearing_{k}")[f"{column}_{a}"] for a in "xy"]
                     for k in range(1, BEARINGS + 1)])


@pytest.mark.derived
def test_determinate_split_is_todays_bearing_loads(rigid_bays):
    r = ct.run(flexible("determinate"))
    today = loads_of(rigid_bays)
    scale = np.abs(today).max()
    np.testing.assert_allclose(loads_of(r, "reaction"), today, rtol=0, atol=1e-10 * scale)
    np.testing.assert_allclose(loads_of(r), today, rtol=0, atol=1e-10 * scale)


@pytest.mark.derived
def test_equal_share_gives_each_bearing_a_third_of_the_total(rigid_bays):
    r = ct.run(flexible("equal_share"))
    total = loads_of(rigid_bays).sum(axis=0)  # the bays balance: their sum is the applied load
    for k in range(BEARINGS):
        np.testing.assert_allclose(loads_of(r)[k], total / BEARINGS, rtol=0,
                                   atol=1e-10 * np.abs(total).max())


@pytest.mark.derived
def test_static_elastic_shaft_balances_the_applied_forces(rigid_bays):
    r = ct.run(flexible("elastic", "quasi_static"))
    total = loads_of(rigid_bays).sum(axis=0)
    np.testing.assert_allclose(loads_of(r).sum(axis=0), total, rtol=0,
                               atol=1e-9 * np.abs(total).max())
    # an elastic continuous shaft shares the loads differently from simply supported bays
    assert np.abs(loads_of(r) - loads_of(rigid_bays)).max() > 1e-3 * np.abs(total).max()


@pytest.mark.derived
def test_mean_twist_is_the_shaft_in_torsion():
    """Order 0 is static: the mean twist of lobe j is -sum_i T_i min(z_i, z_j) / GJ with z from
    the drive, T_i the mean torque of lobe i (all lobes one side of the drive)."""
    deck = flexible()
    r = ct.run(deck)
    f = deck.model.camshaft.flexibility
    gj = 80e9 * math.pi * f.diameter ** 4 / 32.0
    single = r["cam_torque"]
    n = single.size
    mean_torque = np.full(len(LOBES), single.mean())  # a shifted copy has the same mean
    z = (np.array(LOBES) - DRIVE) * 1e-3
    expected = [-(mean_torque * np.minimum(z, zj)).sum() / gj for zj in z]
    got = [r.component(f"lobe_{j + 1}")["twist"].mean() for j in range(len(LOBES))]
    np.testing.assert_allclose(got, expected, rtol=1e-9)
    assert n > 0 and all(abs(a) < abs(b) for a, b in zip(got, got[1:], strict=False))


def test_plan_names_the_elastic_shaft_and_the_bearings_take_its_loads():
    plan = resolve(flexible().model)
    steps = {s.effect: s for s in plan.steps}
    assert steps["camshaft_elastic"].chosen
    assert "elastic bearing split" in steps["camshaft_elastic"].reason
    assert "loads from the elastic camshaft" in steps["bearings"].reason
    plain = {s.effect: s for s in resolve(ct.loads(camshaft_deck("petroff")).model).steps}
    assert not plain["camshaft_elastic"].chosen
    assert "[camshaft.flexibility]" in plain["camshaft_elastic"].reason
    assert "simply supported bays" in plain["bearings"].reason


def test_outputs_per_bearing_and_lobe():
    r = ct.run(flexible())
    for k in range(1, BEARINGS + 1):
        assert f"bearing_{k}_reaction_order_4" in r.metrics
        assert r.metrics[f"bearing_{k}_reaction_max"].value > 0
    assert r.metrics["shaft_deflection_max"].value > 0
    assert r.metrics["shaft_bending_frequency_1"].value > 0
    assert r.component("lobe_4")["deflection_y"].shape == r["cam_angle"].shape


def test_bore_not_below_diameter_names_the_field():
    with pytest.raises(InputError) as err:
        flexible(extra="bore = 30.0")
    assert "camshaft.flexibility.bore" in str(err.value)


def test_camshaft_sheet_only_with_the_elastic_shaft(tmp_path, rigid_bays):
    from camtrain.report.panels_shaft import SHAFT_PANELS
    from camtrain.report.sheets import write_plots

    deck = flexible()
    written = write_plots(ct.run(deck), deck.model, tmp_path / "elastic", single_panels=False,
                          formats=("png",))
    assert (tmp_path / "elastic" / "sheet_camshaft.png") in written
    plain = write_plots(rigid_bays, ct.loads(camshaft_deck("petroff")).model, tmp_path / "plain",
                        single_panels=False, formats=("png",))
    assert not any(p.name == "sheet_camshaft.png" for p in plain)
    assert set(SHAFT_PANELS) >= {"shaft_reactions", "shaft_orders", "lobe_twist"}
