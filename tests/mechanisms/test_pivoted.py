"""Pivoted followers by Dyson's method (Ball 1988 App A, corrected), geometry rules, conversion."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from camtrain.errors import GeometryError
from camtrain.lift.base import angle_grid
from camtrain.lift.table import TableLift
from camtrain.mechanisms import (
    PivotGeometry,
    centrally_pivoted,
    end_pivoted,
    pivoted,
    rescale_pivot_geometry,
    valve_lift_from_cam_lift,
)
from camtrain.mechanisms.pivoted import dyson_cam_radius, dyson_l2, dyson_m2

from .envelope import Follower, Pose
from .lifts import event_lift, pinto_cam_lift, pinto_nose_reference, rover_lift

OMEGA = 2 * np.pi * 2500 / 60
MM, DEG = 1e-3, np.pi / 180
ROVER = PivotGeometry(50.06 * MM, 54.00 * MM, 74.27 * MM, 35.56 * MM, 14.30 * MM,
                      107.5 * DEG, 140.0 * DEG, kind="central")
PINTO = PivotGeometry(51.80 * MM, 61.80 * MM, 46.20 * MM, 44.00 * MM, 15.00 * MM,
                      39.7 * DEG, 31.9 * DEG, kind="end")


def _nose(theta):
    return int(np.argmin(np.abs(theta)))


def _zeros(theta, y):
    j = np.where(np.sign(y[:-1]) != np.sign(y[1:]))[0]
    return np.degrees(theta[j] - y[j] * (theta[j + 1] - theta[j]) / (y[j + 1] - y[j]))


@pytest.fixture(scope="module")
def pinto():
    theta = angle_grid(1440)
    valve = valve_lift_from_cam_lift(pinto_cam_lift(theta), PINTO, 44 * MM,
                                     rotation="anticlockwise")
    return valve, end_pivoted(valve, PINTO, omega=OMEGA, rotation="anticlockwise")


# --------------------------------------------------------------- seed values
def test_rover_nose_and_base_circle():
    """Rover centrally pivoted (Ball §3.3, Lim's clockwise frame). The exp fit has 7 significant
    figures, Ball's reference values are quoted to 0.01 mm and 0.1 deg."""
    theta = angle_grid(3600)
    k = centrally_pivoted(rover_lift(theta), ROVER, omega=OMEGA, rotation="clockwise")
    assert np.degrees(ROVER.gamma_b) % 360 == pytest.approx(178.116, abs=1e-3)
    i = _nose(theta)
    assert k.cam_radius[i] / MM == pytest.approx(4.50, abs=0.005)
    assert k.equivalent_radius[i] / MM == pytest.approx(3.99, abs=0.005)
    assert k.entrainment_sum[i] / OMEGA / MM == pytest.approx(-10.5, abs=0.05)
    assert _zeros(theta, k.entrainment) == pytest.approx([-33.1, 25.4], abs=0.1)
    assert k.cam_radius.min() / MM == pytest.approx(2.31, abs=0.01)
    assert k.rocker_ratio[0] == pytest.approx(1.0447, abs=1e-4)
    assert k.arm_normal[0] / MM == pytest.approx(49.78, abs=0.005)


def test_pinto_valve_lift_from_app_e_cam_lift(pinto):
    """Ball App E cam lift (44 mm inspection roller = r_f) -> valve lift. The data have four
    decimals (0.1 um), so the maximum 10.3498 mm is checked to 0.1 um; with the anticlockwise
    pairing the valve lift is symmetric to ~0.01 mm (reference §4.6)."""
    valve, _ = pinto
    theta = valve.theta
    assert valve.lift.max() / MM == pytest.approx(10.3498, abs=1e-4)
    assert valve.lift[_nose(theta)] == pytest.approx(valve.lift.max(), abs=1e-12)
    # round trip: with r_i = r_f the pad centre runs on the inspection pitch curve, so the largest
    # pad-centre lift is App E's 6.3323 mm (to the 0.25 deg grid, ~3e-5 mm)
    k = end_pivoted(valve, PINTO, omega=OMEGA, rotation="anticlockwise")
    assert k.cam_lift.max() / MM == pytest.approx(6.3323, abs=1e-4)
    for a, ref in ((10, 10.016), (20, 9.015), (30, 7.34), (40, 5.01)):
        left, right = (np.interp(s * a * DEG, theta, valve.lift) / MM for s in (-1, 1))
        assert left == pytest.approx(ref, abs=0.012) and right == pytest.approx(ref, abs=0.012)


def test_pinto_nose_kinematics():
    """Pinto datum nose r_c, R, V_c/omega, V_f/omega against the values derived from the App E
    data alone (least-squares nose fits and pitch-curve geometry, see
    :func:`lifts.pinto_nose_reference`: r_c = 10.57, R = 8.52, V_c/omega = 12.65,
    V_f/omega = -8.68 mm), to the spread of that fit family (0.05 / 0.033 / 0.05 / 0.05 mm).
    camtrain's default table treatment (smoothing spline at the data's print precision) is
    used; an interpolating cubic spline follows the 4-decimal rounding into l'' and gives
    r_c = 10.11, R = 8.22 mm, outside the fit family."""
    theta = angle_grid(1440)
    cam = TableLift.dataset("pinto_inlet_cam").evaluate(theta)
    valve = valve_lift_from_cam_lift(cam, PINTO, 44 * MM, rotation="anticlockwise")
    k = end_pivoted(valve, PINTO, omega=OMEGA, rotation="anticlockwise")
    i = _nose(k.theta)
    ref = pinto_nose_reference()
    for name, value in (("cam_radius", k.cam_radius[i]), ("equivalent_radius",
                                                          k.equivalent_radius[i]),
                        ("v_cam", k.v_cam[i] / OMEGA), ("v_follower", k.v_follower[i] / OMEGA)):
        expected, tol = ref[name]
        assert value / MM == pytest.approx(expected, abs=tol), name
    # zero entrainment near -43 and -11 deg (docs/references/ball1988.md §4.6), both on the rising side
    assert _zeros(k.theta, k.entrainment) == pytest.approx([-43, -11], abs=0.5)
    assert k.rocker_ratio[0] == pytest.approx(1.5696, abs=1e-4)        # base circle
    assert k.rocker_ratio[i] == pytest.approx(1.698, abs=1e-3)         # nose
    assert np.all(k.cam_radius > 0)                                    # no concavity


def test_pinto_improved_geometry_rules():
    """Ball §5.5: r_f +20 % and r_B +12 % with pivot and valve fixed gives A = 57.98 mm,
    D = 47.19 mm, kappa = 37.86 deg, lambda = 38.45 deg (printed to 0.01)."""
    new = rescale_pivot_geometry(PINTO, base_radius=16.8 * MM, follower_radius=52.8 * MM)
    assert new.A / MM == pytest.approx(57.98, abs=0.005)
    assert new.D / MM == pytest.approx(47.193, abs=5e-4)
    assert np.degrees(new.lam) == pytest.approx(38.453, abs=5e-4)
    assert np.degrees(new.kappa) == pytest.approx(37.857, abs=5e-4)
    assert new.B == PINTO.B
    assert new.gamma_b + new.kappa == pytest.approx(PINTO.gamma_b + PINTO.kappa, abs=1e-12)
    only_rf = rescale_pivot_geometry(PINTO, follower_radius=52.8 * MM)
    assert (only_rf.D, only_rf.kappa) == pytest.approx((PINTO.D, PINTO.kappa), abs=1e-12)
    only_rb = rescale_pivot_geometry(PINTO, base_radius=16.8 * MM)
    assert (only_rb.A, only_rb.lam) == pytest.approx((PINTO.A, PINTO.lam), abs=1e-12)
    # pivot, valve and base-circle contact stay where they were
    old, moved = PINTO.points(), new.points()
    shift = old["Q"] / np.linalg.norm(old["Q"]) * (16.8 - 15.0) * MM
    assert np.linalg.norm(moved["U"] - moved["Q"]) == pytest.approx(new.A)
    assert np.linalg.norm(old["U"] - old["V"]) == pytest.approx(np.linalg.norm(
        moved["U"] - moved["V"]))
    assert np.linalg.norm(shift) == pytest.approx(1.8 * MM)


@pytest.mark.parametrize("geometry,rotation", [(ROVER, "clockwise"), (PINTO, "anticlockwise")])
def test_base_circle(geometry, rotation):
    theta = angle_grid(360)
    k = pivoted(event_lift(theta, 9 * MM, 1.5), geometry, omega=OMEGA, rotation=rotation)
    base = np.abs(theta) > 1.55
    rb = geometry.base_radius
    assert np.allclose(k.cam_radius[base], rb, rtol=1e-12)
    assert np.allclose(k.v_cam[base], OMEGA * rb, rtol=1e-12)
    assert np.allclose(k.v_follower[base], 0.0, atol=1e-14)
    assert np.allclose(k.profile_r[base], rb, rtol=1e-12)
    assert np.allclose(k.eccentricity[base], 0.0, atol=1e-15)


def test_printed_l2_sign_is_wrong_on_the_base_circle():
    """Ball's printed eq. A.11 is the negative of dQ/dphi' x d2Q/dphi'2: on the base circle it
    would give r_c = -(M + r_f) instead of r_B (reference §2.2.3)."""
    g = PINTO
    m2 = dyson_m2(g.A, g.D, g.lam, g.gamma_b, 0.0)
    l2 = dyson_l2(g.A, g.D, g.lam, g.gamma_b, 0.0, 0.0)
    assert m2 == pytest.approx((g.base_radius + g.follower_radius) ** 2)
    assert l2 == pytest.approx(m2)
    assert dyson_cam_radius(m2, l2, g.follower_radius) == pytest.approx(g.base_radius)
    printed = -l2
    assert dyson_cam_radius(m2, printed, g.follower_radius) == pytest.approx(
        -(np.sqrt(m2) + g.follower_radius))


# --------------------------------------------------------------- independent construction
def pivot_follower(geometry: PivotGeometry, law, sign):
    """Pose from the geometric definition: the follower angle that puts the valve point at the
    required lift is found by root finding (no use of eqs A.19-A.21)."""
    g = geometry
    gb, ev = g.gamma_b, np.array([np.cos(g.kappa), -np.sin(g.kappa)])
    U = np.array([g.D, 0.0])

    def valve_position(gamma):
        return (U + g.B * np.array([np.cos(np.pi + gamma), np.sin(np.pi + gamma)])) @ ev

    psi = np.angle(np.exp(1j * (gb + g.kappa)))
    lo, hi = (-psi, np.pi - psi) if psi > 0 else (psi, psi + np.pi)
    step = 1.0 if psi > 0 else -1.0

    def pose(theta):
        target = law(np.array([theta])).lift[0] + valve_position(gb)
        x = brentq(lambda x: valve_position(gb + step * x) - target, lo + 1e-9, hi - 1e-9,
                   xtol=1e-15, rtol=1e-15)
        return Pose(U, step * x)
    centre = g.A * np.array([np.cos(np.pi + g.lam + gb), np.sin(np.pi + g.lam + gb)])
    return Follower(pose, centre=centre, radius=g.follower_radius, rotation=sign)


@st.composite
def pivot_geometries(draw):
    A, D = draw(st.floats(35 * MM, 60 * MM)), draw(st.floats(35 * MM, 75 * MM))
    reach = draw(st.floats(0.15, 0.85))
    oq = abs(D - A) + 5 * MM + reach * (D + A - abs(D - A) - 10 * MM)
    rb = draw(st.floats(12 * MM, 18 * MM))
    assume(oq - rb > 10 * MM)
    lam, branch = draw(st.floats(-2.6, 2.6)), draw(st.sampled_from([1, -1]))
    base = branch * np.arccos((A * A + D * D - oq * oq) / (2 * A * D))
    side = draw(st.sampled_from([1, -1]))
    kappa = side * draw(st.floats(60 * DEG, 100 * DEG)) - (base - lam)
    return PivotGeometry(A, draw(st.floats(35 * MM, 65 * MM)), D, oq - rb, rb, kappa, lam,
                         branch=branch, kind=draw(st.sampled_from(["end", "central"])))


@settings(max_examples=15, deadline=None,
          suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(geometry=pivot_geometries(), height=st.floats(5 * MM, 10 * MM), width=st.floats(1.1, 1.6),
       skew=st.floats(-0.2, 0.2), anticlockwise=st.booleans())
def test_pivoted_matches_envelope(geometry, height, width, skew, anticlockwise):
    theta = angle_grid(360)

    def law(t):
        return event_lift(t, height, width, skew)
    rotation = "anticlockwise" if anticlockwise else "clockwise"
    try:
        k = pivoted(law(theta), geometry, omega=OMEGA, rotation=rotation)
    except GeometryError:
        assume(False)
    follower = pivot_follower(geometry, law, -1 if anticlockwise else 1)
    for a in (-60, -30, -4, 18, 40, 150):
        i = int(np.argmin(np.abs(theta - a * DEG)))
        m = follower.measure(theta[i], OMEGA)
        assert k.contact_x[i] == pytest.approx(m["x"], abs=1e-9)
        assert k.contact_y[i] == pytest.approx(m["y"], abs=1e-9)
        assert 1 / k.cam_radius[i] == pytest.approx(1 / m["rc"], rel=1e-4, abs=1e-2)
        assert k.v_cam[i] == pytest.approx(m["vc"], abs=1e-6 * OMEGA)
        assert k.v_follower[i] == pytest.approx(m["vf"], abs=1e-6 * OMEGA)
