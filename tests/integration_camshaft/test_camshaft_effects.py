"""Camshaft torque and bearing effects wired into valve-train decks."""
from __future__ import annotations

import math

import numpy as np
import pytest

import camtrain.api as ct
from camtrain.scene import resolve
from tests.conftest import MINIMAL_DECK

from .conftest import VALVE_TRAIN, camshaft_deck

ANGLES = (0.0, 270.0, 90.0, 180.0)
POSITIONS = (30.0, 80.0, 130.0, 230.0)


def test_summed_torque_is_sum_of_shifted_lobe_torques(steady_run):
    r = steady_run
    single = r["cam_torque"]
    n = single.size
    # whole-step delays: the lobe at a reaches its nose a later, i.e. a roll by a n / 360
    expected = sum(np.roll(single, round(a * n / 360.0)) for a in ANGLES)
    np.testing.assert_allclose(r["camshaft_torque"], expected, rtol=0, atol=1e-12)
    assert r.metrics["drive_power_mean"].value == pytest.approx(
        np.mean(expected) * 1500 * math.pi / 30, rel=1e-12)


def test_order_zero_is_mean_and_orders_rebuild_the_torque(steady_run):
    r = steady_run
    t = r["camshaft_torque"]
    theta = r["cam_angle"]
    assert r.metrics["order_0"].value == pytest.approx(np.mean(t), abs=1e-12)
    # in-line four phasing: only multiples of 4 survive (Williams §9.2)
    for n in (1, 2, 3, 5, 6, 7):
        assert r.metrics[f"order_{n}"].value < 1e-9 * r.metrics["order_4"].value
    rebuilt = np.mean(t) + sum(
        r.metrics[f"order_{n}"].value * np.cos(n * theta + r.metrics[f"order_{n}_phase"].value)
        for n in range(1, 13))
    residual = t - rebuilt  # what orders above 12 carry
    assert np.max(np.abs(residual)) < 0.5 * np.ptp(t)
    peak = r.metrics["order_4"].angle  # the first maximum of the order-4 component
    assert math.cos(4 * peak + r.metrics["order_4_phase"].value) == pytest.approx(1.0)


def applied_forces(r):
    """Lobe and hub forces on the shaft rebuilt from the run's columns, as ((z, fx, fy), ...):
    follower axes 90/70/110/90 deg, anticlockwise shaft (friction on the shaft along
    -(z x axis)), belt hub load |T|/r + 2 preload along +y at z = -35 mm."""
    n = r["load"].size
    w, f = np.maximum(r["load"], 0.0), r["friction_force"]
    out = []
    for z, a, ang in zip(POSITIONS, ANGLES, np.radians([90.0, 70.0, 110.0, 90.0]), strict=True):
        k = round(a * n / 360.0)
        ws, fs = np.roll(w, k), -np.roll(f, k)
        out.append((z, -ws * np.cos(ang) - fs * np.sin(ang), -ws * np.sin(ang) + fs * np.cos(ang)))
    hub = np.abs(r["camshaft_torque"]) / 0.05 + 2 * 200.0
    out.append((-35.0, 0.0 * hub, hub))
    return out


def test_bearing_split_force_balance(steady_run):
    """Sum of bearing loads = lobe forces + hub load, at every angle, in x and y."""
    r = steady_run
    forces = applied_forces(r)
    fx = sum(f[1] for f in forces)
    fy = sum(f[2] for f in forces)
    bx = sum(r[f"bearing_{i}_load_x"] for i in (1, 2, 3))
    by = sum(r[f"bearing_{i}_load_y"] for i in (1, 2, 3))
    scale = np.max(np.abs(fy))
    np.testing.assert_allclose(bx, fx, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(by, fy, rtol=0, atol=1e-9 * scale)


def test_lever_overhang_balances_moments():
    """overhang = lever is true beam statics: moments about the shaft datum balance too."""
    r = ct.run(ct.loads(camshaft_deck("petroff", "lever")))
    forces = applied_forces(r)
    for axis in (1, 2):
        applied = sum(f[0] * f[axis] for f in forces)
        reacted = sum(z * r[f"bearing_{i + 1}_load_{'xy'[axis - 1]}"]
                      for i, z in enumerate((0.0, 105.0, 210.0)))
        np.testing.assert_allclose(reacted, applied, rtol=0, atol=1e-9 * np.max(np.abs(applied)))
    assert r.metrics["bearings_power_total"].value == pytest.approx(
        sum(r.metrics[f"bearing_{i}_petroff_power"].value for i in (1, 2, 3)))


def test_bearing_orbit_outputs_mobility():
    r = ct.run(ct.loads(camshaft_deck("mobility", extra="bearing_tolerance = 1e-4")))
    for i in (1, 2, 3):
        eps = r[f"bearing_{i}_eccentricity"]
        assert eps.shape == r["cam_angle"].shape and np.all((eps >= 0) & (eps < 1))
        m = r.metrics[f"bearing_{i}_max_eccentricity"]
        assert m.value == pytest.approx(eps.max())
        hmin = r.metrics[f"bearing_{i}_min_film"]
        assert hmin.value == pytest.approx(25e-6 * (1 - m.value))
        assert r.metrics[f"bearing_{i}_power_mean"].value > 0
    total = sum(r.metrics[f"bearing_{i}_power_mean"].value for i in (1, 2, 3))
    assert r.metrics["bearings_power_total"].value == pytest.approx(total)


def test_plan_skips_camshaft_effects_without_section(minimal_deck):
    steps = {s.effect: s for s in resolve(ct.loads(VALVE_TRAIN).model).steps}
    assert not steps["camshaft_torque"].chosen and "[camshaft]" in steps["camshaft_torque"].reason
    assert not steps["bearings"].chosen
    r = ct.run(ct.loads(VALVE_TRAIN))
    assert "camshaft_torque" not in r.columns and "order_0" not in r.metrics


def test_plan_skips_bearings_without_bearings():
    text = camshaft_deck().split("[[camshaft.bearings]]")[0]
    steps = {s.effect: s for s in resolve(ct.loads(text).model).steps}
    assert steps["camshaft_torque"].chosen
    assert not steps["bearings"].chosen and "camshaft.bearings" in steps["bearings"].reason


def test_camshaft_without_friction_uses_normal_torque():
    text = MINIMAL_DECK + "[spring]\nrate = 38.254\npreload_compression = 6.4\n" \
        "[masses]\nvalve_side = 0.172\n[solver]\nangle_points = 360\n" \
        "[camshaft]\n[[camshaft.lobes]]\nposition = 0.0\n"
    r = ct.run(ct.loads(text))
    assert "camshaft_torque" in r.columns
    assert any("without friction" in w for w in r.warnings)


def test_v_bank_and_dampers():
    extra = ("v_angle = 90.0\n[camshaft.damper]\norders = [4, 8]\ncount = 2\nmass = 0.2\n"
             "pivot_radius = 30.0\n")
    r = ct.run(ct.loads(camshaft_deck("petroff", extra=extra)))
    np.testing.assert_allclose(r["camshaft_torque_both"],
                               r["camshaft_torque"] + r["camshaft_torque_bank_2"])
    # V = 90: order 4 of the two banks cancels, order 8 doubles (Williams Tables 9.5-9.8)
    assert r.metrics["both_order_4"].value < 1e-9 * r.metrics["order_4"].value
    assert r.metrics["both_order_8"].value == pytest.approx(2 * r.metrics["order_8"].value)
    # the damped torque has no order 4 or 8 left
    from camtrain.camshaft import harmonic_orders
    h = harmonic_orders(r["camshaft_torque_damped"])
    assert h[4] < 1e-9 and h[8] < 1e-9
    r4 = r.metrics["damper_order_4_length"].value
    assert 0.030 / r4 == pytest.approx(16 * 1.05)  # R/r = n^2 (1 + margin)
    assert r.metrics["damper_order_4_swing"].value > 0


def test_bad_camshaft_fields_named():
    from camtrain.errors import InputError
    bad = camshaft_deck().replace("position = 105.0", "position = -5.0")
    with pytest.raises(InputError) as exc:
        ct.loads(bad)
    assert "camshaft.bearings[1].position" in str(exc.value)
    bad = camshaft_deck().replace('method = "steady"', 'method = "stedy"')
    with pytest.raises(InputError) as exc:
        ct.loads(bad)
    assert "camshaft.method" in str(exc.value)


def test_camshaft_orbit_plots(tmp_path):
    from camtrain.report.bearing_plots import write_orbit_plots
    r = ct.run(ct.loads(camshaft_deck("steady")))
    files = write_orbit_plots(r, tmp_path)
    assert [f.name for f in files] == [f"orbit_bearing_{i}.png" for i in (1, 2, 3)]
    assert all(f.stat().st_size > 1000 for f in files)
