"""GeometryError checks, the rotation rule, and the load-arm identities of every mechanism."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from camtrain.errors import EXIT_PHYSICALLY_IMPOSSIBLE, GeometryError, InputError
from camtrain.lift.base import angle_grid
from camtrain.mechanisms import (
    PivotGeometry,
    domed,
    flat_faced,
    pivoted,
    pushrod_four_bar,
    pushrod_simple,
    rescale_pivot_geometry,
    tapered_domed,
)
from camtrain.mechanisms.base import equivalent_radius, reverse_lift

from .lifts import event_lift, harrison_lift, rover_lift
from .test_pivoted import MM, PINTO, ROVER
from .test_pushrod import ROCKER, _four_bar, _x_bar

OMEGA = 200.0


def _all_mechanisms(rotation):
    theta = angle_grid(720)
    lift = event_lift(theta, 9 * MM, 1.5, 0.15)
    rocker, fb = _four_bar(1)
    return {
        "flat": flat_faced(lift, base_radius=25 * MM, omega=OMEGA, rotation=rotation,
                           offset=2 * MM),
        "domed": domed(lift, base_radius=25 * MM, follower_radius=0.2, omega=OMEGA,
                       rotation=rotation),
        "offset": domed(lift, base_radius=18 * MM, follower_radius=30 * MM, offset=-5 * MM,
                        omega=OMEGA, rotation=rotation),
        "tapered": tapered_domed(lift, base_radius=25 * MM, follower_radius=1.0,
                                 taper_angle=0.02, omega=OMEGA, rotation=rotation),
        "rover": pivoted(lift, ROVER, omega=OMEGA, rotation=rotation),
        "pinto": pivoted(lift, PINTO, omega=OMEGA, rotation=rotation),
        "pushrod": pushrod_simple(lift, ROCKER, tappet_axis_distance=_x_bar(ROCKER, 9 * MM),
                                  base_radius=20 * MM, tappet_radius=0.4, omega=OMEGA,
                                  rotation=rotation),
        "four-bar": pushrod_four_bar(lift, rocker, fb, omega=OMEGA, rotation=rotation),
    }


@pytest.mark.parametrize("rotation", ["clockwise", "anticlockwise"])
def test_load_arm_identities(rotation):
    """Virtual work and power: T_normal = W arm_normal q', l_v' = arm_valve q', and the friction
    power F |V_s| = F omega (friction_arm - arm_friction q') for every mechanism."""
    for name, k in _all_mechanisms(rotation).items():
        scale = np.max(np.abs(k.torque_arm_normal))
        assert np.allclose(k.torque_arm_normal, k.arm_normal * k.q_d1, atol=1e-12 * scale), name
        assert np.allclose(k.valve_d1, k.arm_valve * k.q_d1, atol=1e-14), name
        power = OMEGA * (k.friction_arm - k.arm_friction * k.q_d1)
        assert np.allclose(power, np.abs(k.sliding), rtol=1e-9, atol=1e-12), name
        with np.errstate(divide="ignore"):
            assert np.allclose(k.rocker_ratio, k.arm_valve / k.arm_normal), name
        assert np.all(np.isfinite(k.equivalent_radius)), name
        assert np.allclose(k.entrainment, 0.5 * (k.v_cam + k.v_follower)), name
        assert np.allclose(k.profile_r, np.hypot(k.profile_x, k.profile_y)), name


def test_equivalent_radius_singular_cases():
    """Flat spot -> r_f, conformal concave contact -> inf, cusp -> 0, flat face -> r_c; the
    RuntimeWarning filter of the test configuration would turn any warning into a failure."""
    rc = np.array([np.inf, -np.inf, -0.05, 0.0, 0.02, -0.2])
    assert np.allclose(equivalent_radius(rc, 0.05), [0.05, 0.05, np.inf, 0.0, 0.001 / 0.07, 0.2 / 3])
    assert np.array_equal(equivalent_radius(rc, np.inf), rc)
    k = flat_faced(harrison_lift(angle_grid(72)), base_radius=18 * MM, omega=OMEGA)
    with pytest.raises(ValueError):
        k.cam_radius[0] = 1.0


def test_pivoted_arms_match_ball_app_c():
    """|arm_normal| = A |sin nu| (eq. C.12) and |arm_friction| = |r_f - A cos nu| (C.13-C.14)."""
    theta = angle_grid(720)
    k = pivoted(rover_lift(theta), ROVER, omega=OMEGA)
    assert np.allclose(k.arm_normal, ROVER.A * np.abs(np.sin(k.nu)))
    assert np.allclose(k.arm_normal, ROVER.A * np.cos(k.pressure_angle))
    assert np.allclose(np.abs(k.arm_friction), np.abs(ROVER.follower_radius
                                                      - ROVER.A * np.cos(k.nu)))
    assert np.allclose(k.arm_valve, np.abs(ROVER.B * np.sin(k.gamma + ROVER.kappa)))


def test_rotation_rule_is_balls_array_reversal():
    """Anticlockwise = clockwise analysis of the reversed law, results reversed back, odd fields
    (d/dtheta, face position, pressure angle, friction arm) negated (Ball §4.2.1)."""
    theta = angle_grid(720)
    lift = rover_lift(theta)
    acw = pivoted(lift, ROVER, omega=OMEGA, rotation=-1)
    cw_rev = pivoted(reverse_lift(lift), ROVER, omega=OMEGA, rotation=1)
    assert acw.rotation == "anticlockwise"
    assert np.array_equal(acw.theta, theta)
    for name in ("cam_radius", "v_cam", "v_follower", "equivalent_radius", "contact_x", "gamma"):
        assert np.allclose(getattr(acw, name), getattr(cw_rev, name)[::-1]), name
    for name in ("valve_d1", "eccentricity", "pressure_angle", "arm_friction", "gamma_d1"):
        assert np.allclose(getattr(acw, name), -getattr(cw_rev, name)[::-1]), name
    with pytest.raises(InputError, match="mechanism.rotation"):
        pivoted(lift, ROVER, omega=OMEGA, rotation="sideways")


# --------------------------------------------------------------- GeometryError cases
def _raises(fn, *fragments):
    with pytest.raises(GeometryError) as info:
        fn()
    text = str(info.value)
    for fragment in fragments:
        assert fragment in text, text
    assert info.value.exit_code == EXIT_PHYSICALLY_IMPOSSIBLE
    return text


def test_flat_follower_on_a_concave_cam_names_the_minimum_base_radius():
    """Harrison at r_B = 13 mm: concave at +-26.8 deg; r_B must exceed 13.590 mm (Ball §5.2)."""
    lift = harrison_lift(angle_grid(3600))
    _raises(lambda: flat_faced(lift, base_radius=13 * MM, omega=OMEGA), "cam.base_radius",
            "convex", "cam angle -26.80 deg", "must exceed 13.590 mm", "got 13.000 mm")


def test_concave_flank_tighter_than_the_grinding_wheel():
    """Rover with r_f = 15 mm has concave flanks (tightest about 55.8 mm): a 100 mm wheel fails,
    a 50 mm wheel passes (Ball's minimum cam concavity)."""
    lift = rover_lift(angle_grid(1440))
    small = rescale_pivot_geometry(ROVER, follower_radius=15 * MM)
    k = pivoted(lift, small, omega=OMEGA, min_concave_radius=50 * MM)
    assert k.cam_radius.min() < 0
    _raises(lambda: pivoted(lift, small, omega=OMEGA, min_concave_radius=100 * MM),
            "mechanism.min_concave_radius", "concave with radius 55.8", "cam angle",
            "grinding wheel (100.000 mm)")


def test_cusp():
    """Large follower radii sharpen the nose until r_c passes through zero (Ball §5.3)."""
    lift = rover_lift(angle_grid(1440))
    big = rescale_pivot_geometry(ROVER, follower_radius=50 * MM)
    _raises(lambda: pivoted(lift, big, omega=OMEGA), "mechanism.follower_radius",
            "cam.base_radius", "cusp", "cam angle -20.50 deg")
    _raises(lambda: domed(harrison_lift(angle_grid(1440)), base_radius=13 * MM,
                          follower_radius=1.0, omega=OMEGA), "cusp", "cam angle -27.00 deg")


def test_contact_off_the_face():
    """Harrison needs a face of 2 x 14.33 mm (Ball §2.4)."""
    lift = harrison_lift(angle_grid(3600))
    _raises(lambda: flat_faced(lift, base_radius=18 * MM, omega=OMEGA, face_length=25 * MM),
            "mechanism.face_length", "runs off", "at least 28.65")
    flat_faced(lift, base_radius=18 * MM, omega=OMEGA, face_length=29 * MM)
    _raises(lambda: pivoted(rover_lift(angle_grid(720)), ROVER, omega=OMEGA, face_length=5 * MM),
            "mechanism.face_length")


def test_four_bar_that_cannot_assemble():
    theta = angle_grid(360)
    lift = event_lift(theta, 9 * MM, 1.5)
    rocker, fb = _four_bar(1)
    apart = replace(fb, b=fb.b + 0.2)
    _raises(lambda: pushrod_four_bar(lift, rocker, apart, omega=OMEGA),
            "mechanism.pushrod_length", "cannot assemble", "cam angle")


def test_other_impossible_geometries():
    theta = angle_grid(360)
    lift = event_lift(theta, 9 * MM, 1.5)
    _raises(lambda: pivoted(lift, replace(ROVER, B=4 * MM), omega=OMEGA),
            "mechanism.pivot_to_valve", "cam angle")
    _raises(lambda: PivotGeometry(20 * MM, 50 * MM, 80 * MM, 20 * MM, 15 * MM, 1.0, 1.0),
            "cannot touch the base circle")
    _raises(lambda: pushrod_simple(lift, ROCKER, tappet_axis_distance=0.5, base_radius=20 * MM,
                                   omega=OMEGA), "mechanism.pushrod_length", "cam angle")
    with pytest.raises(InputError, match="mechanism.offset"):
        domed(lift, base_radius=18 * MM, follower_radius=10 * MM, offset=30 * MM, omega=OMEGA)
