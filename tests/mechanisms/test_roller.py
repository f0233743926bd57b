"""Roller followers: roller finger follower, centre-pivot roller rocker, roller tappet; the valve
pad and the pivot of pivoted followers (camtrain.mechanisms.roller, .arm_contacts)."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.lift.base import angle_grid
from camtrain.mechanisms import PivotGeometry, domed, end_pivoted, pivoted
from camtrain.mechanisms.arm_contacts import (
    arm_contacts,
    arm_points,
    cam_to_fixed,
    fixed_to_cam,
    pad_load,
    pad_sliding_speed,
    valve_directions,
)
from camtrain.mechanisms.roller import roller

from .lifts import event_lift

MM, DEG = 1e-3, np.pi / 180
OMEGA = 2 * np.pi * 3000 / 60
# A roller finger follower of hand-checkable geometry: pivot U = (40, 0) mm, roller centre 30 mm
# from it, roller radius 9 mm, base circle 17 mm: cos(gamma_B + lambda) = (30^2 + 40^2 - 26^2) /
# (2 30 40) = 0.76, roller centre on the base circle at (17.2, +-19.4979) mm.
RFF = dict(A=30 * MM, B=45 * MM, D=40 * MM, follower_radius=9 * MM, base_radius=17 * MM,
           lam=12 * DEG, kind="end")


def rff_geometry(kappa=None) -> PivotGeometry:
    g = PivotGeometry(kappa=0.0, **RFF)
    # kappa such that the valve arm is perpendicular to the valve axis on the base circle and
    # the cam pushing the roller opens the valve (gamma_B + kappa = -90 deg)
    return PivotGeometry(kappa=-np.pi / 2 - g.gamma_b if kappa is None else kappa, **RFF)


def rff(rotation="clockwise", points=3600, kappa=None):
    theta = angle_grid(points)
    g = rff_geometry(kappa)
    lift = event_lift(theta, 8 * MM, 65 * DEG, skew=0.1)
    return lift, g, pivoted(lift, g, omega=OMEGA, rotation=rotation)


@pytest.mark.derived
def test_base_circle_points_by_hand():
    """Roller centre on the base circle from the cosine rule by hand: Q = (17.2, 19.4979) mm."""
    lift, g, k = rff()
    pts = arm_points(k, g)
    i = int(np.argmin(np.abs(k.theta - np.pi * 0.9)))       # on the base circle
    qx, qy = pts["Q"][0][i], pts["Q"][1][i]
    assert qx / MM == pytest.approx(40 - 30 * 0.76, abs=1e-9)
    assert abs(qy) / MM == pytest.approx(30 * np.sqrt(1 - 0.76 ** 2), abs=1e-9)
    assert abs(qy) / MM == pytest.approx(19.497692, abs=1e-6)
    assert np.hypot(qx, qy) / MM == pytest.approx(26.0, abs=1e-9)


def _normal_cosines(rotation, points):
    """Largest cosine between Q - P and the tangents of the profile and of the pitch curve
    (central differences) and the largest ||Q - P| - r_r|."""
    lift, g, k = rff(rotation, points=points)
    qx, qy = fixed_to_cam(k, *arm_points(k, g)["Q"])
    px, py = k.contact_x, k.contact_y
    h = k.theta[1] - k.theta[0]
    out = [np.max(np.abs(np.hypot(qx - px, qy - py) - 9 * MM))]
    for x, y in ((px, py), (qx, qy)):
        tx, ty = np.gradient(x, h), np.gradient(y, h)
        cosine = ((qx - px) * tx + (qy - py) * ty) / (9 * MM * np.hypot(tx, ty))
        out.append(np.max(np.abs(cosine[2:-2])))
    return out


@pytest.mark.derived
@pytest.mark.parametrize("rotation", ["clockwise", "anticlockwise"])
def test_roller_centre_on_offset_curve(rotation):
    """The roller centre Q (from the follower angle) is r_r from the contact point P to
    round-off, along the profile normal: Q - P is normal to the tangent of the profile and of
    the pitch curve, to the error of central differences, which falls as h^2 (observed
    ratio 4.0 per halving of the step)."""
    coarse, fine = _normal_cosines(rotation, 1800), _normal_cosines(rotation, 3600)
    assert fine[0] < 1e-12
    for c, f in zip(coarse[1:], fine[1:], strict=True):
        assert f < 1e-4
        assert c / f > 3.5


@pytest.mark.derived
def test_surface_speeds_against_position_differences():
    """omega |dP/dtheta| = |V_c| (the contact point runs along the cam profile at V_c) and
    omega d(eccentricity)/dtheta = V_f, from finite differences of positions (away from the
    event ends, where the test lift's jerk jumps and a difference is first order)."""
    lift, g, k = rff(points=7200)
    h = k.theta[1] - k.theta[0]
    speed = OMEGA * np.hypot(np.gradient(k.contact_x, h), np.gradient(k.contact_y, h))
    inner = np.abs(np.abs(k.theta) - 65 * DEG) > 3 * h
    inner[:2] = inner[-2:] = False
    assert np.allclose(speed[inner], np.abs(k.v_cam)[inner], rtol=0, atol=2e-4)
    vf = OMEGA * np.gradient(k.eccentricity, h)
    assert np.allclose(vf[inner], k.v_follower[inner], rtol=0, atol=2e-4)


@pytest.mark.derived
def test_roller_equals_curved_end_pivoted_follower():
    """A roller finger follower with the roller at the face centre is camtrain's curved
    end-pivoted follower (Dyson) to 1e-9; a crowned roller changes only R_y."""
    lift, g, k = rff()
    ref = end_pivoted(lift, g, omega=OMEGA)
    r = roller(k)
    crowned = roller(k, crown_radius=400 * MM)
    for name in ("v_cam", "v_follower", "equivalent_radius", "pressure_angle", "arm_normal",
                 "arm_valve", "contact_x", "contact_y", "cam_radius", "torque_arm_normal"):
        a, b = getattr(r, name), getattr(ref, name)
        assert np.allclose(a, b, rtol=1e-9, atol=1e-12), name
        assert np.array_equal(getattr(crowned, name), a)
    assert r.line_contact and not crowned.line_contact
    assert np.all(crowned.radius_y == 400 * MM)
    assert r.mechanism == "roller end-pivoted follower"


@pytest.mark.derived
def test_pad_sliding_speed_by_hand():
    """Valve arm perpendicular to the valve axis on the base circle (gamma_B + kappa = 90 deg):
    cos(gamma + kappa) = -l/B, gamma' = l'/sqrt(B^2 - l^2), so v_pad = omega l' (r_p + l) /
    sqrt(B^2 - l^2). B = 40 mm, r_p = 10 mm, l = 4 mm, l' = 8 mm/rad, omega = 100 rad/s:
    gamma' = 0.2010076 rad/rad, v_pad = +0.281411 m/s (along t = z x d)."""
    B, rp, lv, l1, w = 40 * MM, 10 * MM, 4 * MM, 8 * MM, 100.0
    kappa = 0.3
    gamma = np.pi / 2 + np.arcsin(lv / B) - kappa
    g1 = l1 / (B * np.sin(gamma + kappa))
    assert g1 == pytest.approx(0.2010076, abs=1e-7)
    assert pad_sliding_speed(w * g1, gamma, B, kappa, rp) == pytest.approx(0.281411, abs=1e-6)
    # a pad whose contact lies on the perpendicular from the pivot to the valve axis rolls
    assert pad_sliding_speed(w * g1, gamma, B, kappa, B * np.cos(gamma + kappa)) == 0.0


@pytest.mark.derived
@pytest.mark.parametrize("rotation", ["clockwise", "anticlockwise"])
def test_pad_sliding_speed_against_material_point(rotation):
    """The arm's material point at the pad contact, turned with the arm about the pivot over
    two grid steps centred on it: its displacement across the valve tip per time equals v_pad."""
    lift, g, k = rff(rotation, points=7200)
    pts = arm_points(k, g)
    d, t = valve_directions(g)
    rp = 11 * MM
    cx, cy = pts["V"][0] + rp * d[0], pts["V"][1] + rp * d[1]
    ux = g.D
    dg = np.roll(k.gamma, -1) - np.roll(k.gamma, 1)            # over two steps, centred
    dt = 2 * (k.theta[1] - k.theta[0]) / OMEGA
    # the material point at C turned about U by -dg/2 and +dg/2: its centred displacement
    rx, ry = cx - ux, cy
    mx = 2 * np.sin(dg / 2) * -ry
    my = 2 * np.sin(dg / 2) * rx
    fd = (mx * t[0] + my * t[1]) / dt
    v = pad_sliding_speed(OMEGA * k.gamma_d1, k.gamma, g.B, g.kappa, rp)
    assert np.max(np.abs(fd - v)[2:-2]) < 1e-4 * np.max(np.abs(v))
    assert np.max(np.abs(v)) > 0.1                          # the test exercises a real motion


@pytest.mark.derived
def test_arm_in_equilibrium():
    """With the pad load of the moment balance (no friction, no inertia) the cam force, the pad
    force and the pivot reaction have no moment about the pivot and no resultant."""
    lift, g, k = rff()
    W = np.where(lift.lift > 0, 500.0 + 1e5 * lift.lift, 100.0)
    F = pad_load(k, W, None, 0.0)
    pts = arm_points(k, g)
    px, py = cam_to_fixed(k, k.contact_x, k.contact_y)
    qx, qy = pts["Q"]
    nx, ny = (qx - px) / g.follower_radius, (qy - py) / g.follower_radius
    d, _ = valve_directions(g)
    cx, cy = pts["V"][0] + 8 * MM * d[0], pts["V"][1] + 8 * MM * d[1]
    moment = ((px - g.D) * W * ny - py * W * nx) - ((cx - g.D) * F * d[1] - cy * F * d[0])
    assert np.max(np.abs(moment)) < 1e-9 * np.max(W) * g.B
    out = arm_contacts(k, g, W, pad_radius=8 * MM, pad_width=6 * MM, pivot_radius=4 * MM,
                       pivot_friction=0.1, pad_friction=0.08, reduced_modulus=2.2e11)
    rx = -(W * nx - F * d[0])
    ry = -(W * ny - F * d[1])
    assert np.allclose(out.pivot_reaction, np.hypot(rx, ry), rtol=1e-12)
    assert np.allclose(out.pivot_friction_torque, 0.1 * 4 * MM * out.pivot_reaction)
    assert np.allclose(out.pad_friction_power, 0.08 * F * np.abs(out.pad_sliding_speed))
    # on the base circle the arm does not move: no sliding, no pivot power
    base = lift.lift == 0
    assert np.all(out.pad_sliding_speed[base] == 0) and np.all(out.pivot_friction_power[base] == 0)


@pytest.mark.derived
def test_roller_tappet_centre_on_offset_curve():
    """Translating roller tappet: the roller centre on the follower axis at height d + l is
    r_r from the contact point along the profile normal."""
    theta = angle_grid(3600)
    lift = event_lift(theta, 9 * MM, 70 * DEG)
    rr, rb = 12 * MM, 18 * MM
    k = roller(domed(lift, base_radius=rb, follower_radius=rr, omega=OMEGA, shape="cylindrical"))
    assert k.line_contact and k.mechanism == "roller domed translating"
    ax, ay = -np.sin(theta), np.cos(theta)           # follower axis in the cam frame
    qx, qy = (rb + rr + lift.lift) * ax, (rb + rr + lift.lift) * ay
    assert np.max(np.abs(np.hypot(qx - k.contact_x, qy - k.contact_y) - rr)) < 1e-12
    h = theta[1] - theta[0]
    tx, ty = np.gradient(k.contact_x, h), np.gradient(k.contact_y, h)
    cosine = ((qx - k.contact_x) * tx + (qy - k.contact_y) * ty) / (rr * np.hypot(tx, ty))
    assert np.max(np.abs(cosine[2:-2])) < 1e-4


def test_roller_refuses_bad_crown_and_a_spherical_face():
    from camtrain.errors import InputError

    lift, g, k = rff(points=720)
    with pytest.raises(InputError, match="mechanism.roller.crown_radius"):
        roller(k, crown_radius=-1.0)
    theta = angle_grid(720)
    dome = domed(event_lift(theta, 5 * MM, 60 * DEG), base_radius=18 * MM,
                 follower_radius=10 * MM, omega=OMEGA)
    with pytest.raises(ValueError, match="cylindrical"):
        roller(dome)
