"""Flat, domed (radial/offset) and tapered translating followers."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from camtrain.errors import GeometryError
from camtrain.lift.base import angle_grid
from camtrain.mechanisms import domed, flat_faced, tapered_domed
from camtrain.mechanisms.translating import (
    dyson_naylor_domed,
    offset_base_height,
    offset_cam_radius,
    offset_pressure_angle,
    offset_pressure_angle_rate,
    offset_surface_velocities,
    yang_load_factor,
)

from .envelope import Follower, Pose
from .lifts import event_lift, harrison_lift

OMEGA = 2 * np.pi * 2500 / 60
PROPS = settings(max_examples=12, deadline=None,
                 suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow,
                                        HealthCheck.data_too_large])  # older hypothesis


def _index(theta, degrees):
    return int(np.argmin(np.abs(theta - np.radians(degrees))))


def _translating_follower(lift_fn, base_radius, follower_radius, offset, sign):
    """Independent pose: body origin on the follower axis at the lift height."""
    def pose(theta):
        s = lift_fn(np.array([theta])).lift[0]
        return Pose(np.array([offset, s]), 0.0)
    if np.isinf(follower_radius):
        return Follower(pose, level=base_radius, rotation=sign)
    d = np.sqrt((base_radius + follower_radius) ** 2 - offset ** 2)
    return Follower(pose, centre=[0.0, d], radius=follower_radius, rotation=sign)


def _compare(k, follower, angles_deg):
    for a in angles_deg:
        i = _index(k.theta, a)
        m = follower.measure(k.theta[i], k.omega)
        scale = k.omega * 0.02
        assert k.contact_x[i] == pytest.approx(m["x"], abs=1e-9)
        assert k.contact_y[i] == pytest.approx(m["y"], abs=1e-9)
        assert 1 / k.cam_radius[i] == pytest.approx(1 / m["rc"], rel=2e-4, abs=1e-3)
        assert k.v_cam[i] == pytest.approx(m["vc"], abs=2e-5 * scale)
        assert k.v_follower[i] == pytest.approx(m["vf"], abs=2e-5 * scale)


# --------------------------------------------------------------- seed values (Ball 1988 §4.4)
def test_harrison_nose_radius_entrainment_and_minimum_base_radius():
    """Harrison flat follower, four-power lift (Ball §3.2). The lift coefficients have 8
    significant figures and the derivation gives R to 5: R(nose) = 6.0766 mm to 5e-5 mm. Zero
    entrainment +-39.56 deg (printed to 0.01 deg) located by linear interpolation on a 0.05 deg
    grid; min(l + l'') = -13.590 mm (printed to 0.01 mm, i.e. r_B,min = 13.59 mm)."""
    theta = angle_grid(7200)
    k = flat_faced(harrison_lift(theta), base_radius=18e-3, omega=OMEGA)
    nose = _index(theta, 0.0)
    assert k.equivalent_radius[nose] * 1e3 == pytest.approx(6.0766, abs=5e-5)
    assert k.cam_radius[nose] == k.equivalent_radius[nose]
    ue = k.entrainment
    j = np.where(np.sign(ue[:-1]) != np.sign(ue[1:]))[0]
    zeros = np.degrees(theta[j] - ue[j] * (theta[j + 1] - theta[j]) / (ue[j + 1] - ue[j]))
    assert zeros == pytest.approx([-39.56, 39.56], abs=0.01)
    r_b_min = 18e-3 - k.cam_radius.min()
    assert r_b_min * 1e3 == pytest.approx(13.59, abs=0.005)
    assert np.degrees(abs(theta[np.argmin(k.cam_radius)])) == pytest.approx(26.8, abs=0.1)
    # Ball §2.4: the face must be at least 2 max|l'| = 2 x 14.33 mm
    assert np.max(np.abs(k.eccentricity)) * 1e3 == pytest.approx(14.33, abs=0.005)


def test_flat_surface_velocities_and_arms():
    theta = angle_grid(720)
    lift = harrison_lift(theta)
    k = flat_faced(lift, base_radius=18e-3, omega=OMEGA)
    assert np.allclose(k.v_cam, OMEGA * (18e-3 + lift.lift + lift.d2))
    assert np.allclose(k.v_follower, OMEGA * lift.d2)
    assert np.allclose(k.sliding, OMEGA * (18e-3 + lift.lift))          # Ball §2.2.1
    assert np.allclose(k.friction_arm, 18e-3 + lift.lift)               # Ball §5.2.1
    assert np.allclose(k.torque_arm_normal, lift.d1)                    # W l'
    assert np.allclose(k.eccentricity, lift.d1)
    assert np.allclose(k.arm_normal, 1.0) and np.allclose(k.rocker_ratio, 1.0)
    assert np.allclose(k.pressure_angle, 0.0) and np.allclose(k.arm_friction, 0.0)


@pytest.mark.parametrize("build", ["flat", "domed", "offset", "tapered"])
def test_base_circle(build):
    """On the base circle r_c = r_B, V_c = omega r_B, V_f = 0 for every translating follower."""
    theta = angle_grid(360)
    lift = event_lift(theta, 8e-3, 1.4)
    kw = dict(base_radius=20e-3, omega=OMEGA)
    k = {"flat": lambda: flat_faced(lift, **kw),
         "domed": lambda: domed(lift, follower_radius=0.3, **kw),
         "offset": lambda: domed(lift, follower_radius=0.3, offset=4e-3, **kw),
         "tapered": lambda: tapered_domed(lift, follower_radius=0.3, taper_angle=0.01, **kw)}[build]()
    base = np.abs(theta) > 1.45
    assert np.allclose(k.cam_radius[base], 20e-3, rtol=1e-12)
    assert np.allclose(k.v_cam[base], OMEGA * 20e-3, rtol=1e-12)
    assert np.allclose(k.v_follower[base], 0.0, atol=1e-15)
    assert np.allclose(k.profile_r[base], 20e-3, rtol=1e-12)


def test_flat_limit_of_domed_formulas():
    """r_f -> inf: Ball eqs 3.1-3.3 and Williams ch. 6 tend to eqs 3.4-3.6; the difference falls
    as 1/r_f (about 2e-6 of the array scale at r_f = 100 km)."""
    theta = angle_grid(720)
    lift = harrison_lift(theta)
    flat = flat_faced(lift, base_radius=18e-3, omega=OMEGA)
    for k in (domed(lift, base_radius=18e-3, follower_radius=1e5, omega=OMEGA),
              tapered_domed(lift, base_radius=18e-3, follower_radius=1e5, taper_angle=0.0,
                            omega=OMEGA)):
        for name in ("cam_radius", "v_cam", "v_follower", "eccentricity", "contact_x",
                     "contact_y", "torque_arm_normal", "friction_arm"):
            ref = getattr(flat, name)
            scale = np.max(np.abs(ref))
            assert np.allclose(getattr(k, name), ref, rtol=0.0, atol=2e-5 * scale), name
        assert np.allclose(k.equivalent_radius, flat.equivalent_radius, rtol=1e-5)


def test_ball_and_williams_domed_formulas_agree():
    """Ball eqs 3.1-3.3 (radial) against Williams eqs 6.9-6.22 (corrected) at zero offset."""
    theta = angle_grid(720)
    lift = event_lift(theta, 9e-3, 1.3)
    rb, rf = 16e-3, 25e-3
    d = offset_base_height(rb, rf, 0.0)
    beta = offset_pressure_angle(lift.lift, lift.d1, d, 0.0)
    beta1 = offset_pressure_angle_rate(lift.lift, lift.d1, lift.d2, d, 0.0)
    rc_w = offset_cam_radius(lift.lift, beta, beta1, d, rf)
    vc_w, vf_w = offset_surface_velocities(lift.lift, beta, beta1, d, rf, OMEGA)
    rc_b, _, vc_b, vf_b = dyson_naylor_domed(lift.lift + rb + rf, lift.d1, lift.d2, rf, OMEGA)
    assert np.allclose(rc_w, rc_b, rtol=1e-10)
    assert np.allclose(vc_w, vc_b, rtol=1e-10) and np.allclose(vf_w, vf_b, atol=1e-12)


def test_tapered_principal_radii_and_load_factor():
    """Yang §3.2.3: R_x = (1/r_c + 1/r_f)^-1, R_y = r_f; eq. 3.11 load factor."""
    theta = angle_grid(720)
    lift = event_lift(theta, 9e-3, 1.5)
    taper = np.radians(1 / 60)
    k = tapered_domed(lift, base_radius=18e-3, follower_radius=2.0, taper_angle=taper,
                      omega=OMEGA)
    assert np.allclose(1 / k.radius_x, 1 / k.cam_radius + 1 / 2.0)
    assert np.all(k.radius_y == 2.0)
    beta = np.arctan2(lift.d1, lift.lift + 18e-3 + 2.0)
    assert np.allclose(k.arm_normal, yang_load_factor(beta, taper))
    assert np.allclose(k.pressure_angle, beta)
    plain = domed(lift, base_radius=18e-3, follower_radius=2.0, omega=OMEGA)
    assert np.allclose(k.cam_radius, plain.cam_radius) and np.allclose(k.v_cam, plain.v_cam)
    assert np.all(plain.radius_y == 2.0)
    assert np.all(np.isinf(domed(lift, base_radius=18e-3, follower_radius=2.0, omega=OMEGA,
                                 shape="cylindrical").radius_y))


# --------------------------------------------------------------- independent construction
@PROPS
@given(height=st.floats(4e-3, 9e-3), width=st.floats(1.3, 1.8), skew=st.floats(-0.25, 0.25),
       base=st.floats(18e-3, 35e-3), offset=st.floats(-3e-3, 3e-3),
       anticlockwise=st.booleans())
def test_flat_matches_envelope(height, width, skew, base, offset, anticlockwise):
    theta = angle_grid(360)

    def law(t):
        return event_lift(t, height, width, skew)
    try:
        k = flat_faced(law(theta), base_radius=base, omega=OMEGA, offset=offset,
                       rotation="anticlockwise" if anticlockwise else "clockwise")
    except GeometryError:
        assume(False)
    sign = -1 if anticlockwise else 1
    _compare(k, _translating_follower(law, base, np.inf, offset, sign), (-60, -35, -5, 20, 50))


@PROPS
@given(height=st.floats(4e-3, 10e-3), width=st.floats(1.1, 1.7), skew=st.floats(-0.25, 0.25),
       base=st.floats(12e-3, 30e-3), radius=st.floats(8e-3, 0.5), offset_frac=st.floats(-0.3, 0.3),
       anticlockwise=st.booleans())
def test_domed_matches_envelope(height, width, skew, base, radius, offset_frac, anticlockwise):
    theta = angle_grid(360)
    offset = offset_frac * base

    def law(t):
        return event_lift(t, height, width, skew)
    try:
        k = domed(law(theta), base_radius=base, follower_radius=radius, offset=offset,
                  omega=OMEGA, rotation="anticlockwise" if anticlockwise else "clockwise")
    except GeometryError:
        assume(False)
    sign = -1 if anticlockwise else 1
    _compare(k, _translating_follower(law, base, radius, offset, sign), (-55, -30, -3, 25, 45))
