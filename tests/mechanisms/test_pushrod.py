"""Push-rod trains (Williams 2013 ch. 11): simple train and four-bar chain."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from camtrain.errors import GeometryError
from camtrain.lift.base import angle_grid
from camtrain.mechanisms import FourBarGeometry, RockerGeometry, pushrod_four_bar, pushrod_simple
from camtrain.mechanisms.pushrod import four_bar_quadratic

from .envelope import Follower, Pose
from .lifts import event_lift

OMEGA = 2 * np.pi * 2000 / 60
MM, DEG = 1e-3, np.pi / 180
H = 1e-3


def derivatives(f, theta):
    """First and second derivatives by central differences with one Richardson step."""
    def d(h):
        return (f(theta + h) - f(theta - h)) / (2 * h), \
            (f(theta + h) - 2 * f(theta) + f(theta - h)) / h ** 2
    (a1, a2), (b1, b2) = d(H), d(2 * H)
    return (4 * a1 - b1) / 3, (4 * a2 - b2) / 3


def e(a):
    return np.array([np.cos(a), np.sin(a)])


class Train:
    """Positions of the rocker, push rod and tappet / follower from first principles."""

    def __init__(self, rocker: RockerGeometry, law, max_lift):
        self.r, self.law, self.max_lift = rocker, law, max_lift

    def rocker_angle(self, theta):
        """Rocker rotation phi - phi0 that puts the valve-arm tip at the valve lift."""
        r = self.r
        valve_dir = np.array([np.sin(r.valve_angle), -np.cos(r.valve_angle)])
        target = self.law(np.atleast_1d(theta)).lift[0] - r.perpendicular_fraction * self.max_lift
        return brentq(lambda p: r.D2 * e(r.valve_angle - p) @ valve_dir - target, -1.2, 1.2,
                      xtol=1e-15, rtol=1e-15)

    def tip(self, theta):
        r = self.r
        return r.D1 * e(np.pi + r.alpha0 + r.valve_angle - self.rocker_angle(theta))


def simple_tappet(train, x_bar):
    def end(theta):
        t = train.tip(theta)
        return np.array([-x_bar, t[1] - np.sqrt(train.r.pushrod_length ** 2 - (t[0] + x_bar) ** 2)])
    base = end(np.pi)[1]
    return end, (lambda th: end(th)[1] - base)


def four_bar_follower(train, fb: FourBarGeometry):
    F = np.array([-fb.a, -fb.b])

    def joint(theta):
        t = train.tip(theta)
        dist = np.linalg.norm(t - F)
        cosang = (fb.e ** 2 + dist ** 2 - train.r.pushrod_length ** 2) / (2 * fb.e * dist)
        ang = np.arctan2(*(t - F)[::-1]) + fb.closure * np.arccos(cosang)
        return F + fb.e * e(ang)

    def chi(theta):
        j = joint(theta)
        return np.arctan2(j[1] - F[1], j[0] - F[0])
    turn = np.sign(chi(0.0) - chi(np.pi))
    return joint, (lambda th: turn * (chi(th) - chi(np.pi)))


ROCKER = RockerGeometry(D1=35 * MM, D2=50 * MM, alpha0=10 * DEG, valve_angle=15 * DEG,
                        perpendicular_fraction=0.5, pushrod_length=200 * MM,
                        pushrod_cg_fraction=0.4)


def _x_bar(rocker, law_max, psi0=3 * DEG):
    eps0 = rocker.base_eps(law_max)
    return rocker.D1 * np.cos(eps0) + rocker.pushrod_length * np.sin(psi0)


@settings(max_examples=10, deadline=None,
          suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(d1=st.floats(25 * MM, 45 * MM), d2=st.floats(35 * MM, 60 * MM),
       alpha0=st.floats(-20 * DEG, 20 * DEG), valve_angle=st.floats(-20 * DEG, 20 * DEG),
       fraction=st.floats(0.2, 0.8), length=st.floats(0.12, 0.25),
       psi0=st.floats(-8 * DEG, 8 * DEG), cg=st.floats(0.2, 0.8),
       tappet_radius=st.sampled_from([np.inf, 0.15, 0.5, 1.0]), anticlockwise=st.booleans())
def test_simple_pushrod_against_positions(d1, d2, alpha0, valve_angle, fraction, length, psi0,
                                          cg, tappet_radius, anticlockwise):
    theta = angle_grid(720)

    def law(t):
        return event_lift(t, 9 * MM, 1.5, 0.1)
    lift = law(theta)
    rocker = RockerGeometry(D1=d1, D2=d2, alpha0=alpha0, valve_angle=valve_angle,
                            perpendicular_fraction=fraction, pushrod_length=length,
                            pushrod_cg_fraction=cg)
    x_bar = _x_bar(rocker, lift.max_lift, psi0)
    rotation = "anticlockwise" if anticlockwise else "clockwise"
    try:
        k = pushrod_simple(lift, rocker, tappet_axis_distance=x_bar, base_radius=25 * MM,
                           tappet_radius=tappet_radius, omega=OMEGA, rotation=rotation)
    except GeometryError:
        assume(False)
    train = Train(rocker, law, lift.max_lift)
    end, s_f = simple_tappet(train, x_bar)
    for a in (-70, -40, -10, 0, 25, 55):
        i = int(np.argmin(np.abs(theta - a * DEG)))
        s1, s2 = derivatives(np.vectorize(s_f), theta[i])
        assert k.cam_lift[i] == pytest.approx(s_f(theta[i]), abs=1e-12)
        assert k.cam_d1[i] == pytest.approx(s1, abs=1e-8)
        assert k.cam_d2[i] == pytest.approx(s2, abs=1e-6)
        # Williams eq. 11.27: valve velocity ratio and the inertia power identities
        phi1, phi2 = derivatives(np.vectorize(train.rocker_angle), theta[i])
        assert k.arm_valve[i] * k.q_d1[i] == pytest.approx(k.valve_d1[i], abs=1e-12)
        assert k.inertia["rocker_inertia"][i] * k.q_d1[i] == pytest.approx(phi1 * phi2, abs=1e-6)
        g = [lambda t, c=c: ((1 - cg) * end(t) + cg * train.tip(t))[c] for c in (0, 1)]
        gd = [derivatives(np.vectorize(gc), theta[i]) for gc in g]
        power = gd[0][0] * gd[0][1] + gd[1][0] * gd[1][1]
        assert k.inertia["pushrod_mass"][i] * k.q_d1[i] == pytest.approx(power, abs=1e-9)
    sign = -1 if anticlockwise else 1

    def pose(t):
        return Pose(np.array([0.0, s_f(t)]), 0.0)
    follower = (Follower(pose, level=25 * MM, rotation=sign) if np.isinf(tappet_radius) else
                Follower(pose, centre=[0.0, 25 * MM + tappet_radius], radius=tappet_radius,
                         rotation=sign))
    for a in (-45, -5, 30):
        i = int(np.argmin(np.abs(theta - a * DEG)))
        m = follower.measure(theta[i], OMEGA)
        assert (k.contact_x[i], k.contact_y[i]) == pytest.approx((m["x"], m["y"]), abs=1e-9)
        assert 1 / k.cam_radius[i] == pytest.approx(1 / m["rc"], rel=1e-4, abs=1e-2)
        assert k.v_cam[i] == pytest.approx(m["vc"], abs=1e-6 * OMEGA)
        assert k.v_follower[i] == pytest.approx(m["vf"], abs=1e-6 * OMEGA)


def _four_bar(branch, psi0=5 * DEG, chi0=10 * DEG, e_arm=40 * MM, d=120 * MM, max_lift=9 * MM):
    rocker = RockerGeometry(D1=35 * MM, D2=50 * MM, alpha0=10 * DEG, valve_angle=15 * DEG,
                            perpendicular_fraction=0.5, pushrod_length=d)
    t0 = rocker.D1 * e(np.pi - rocker.base_eps(max_lift))
    j0 = t0 - d * np.array([np.sin(psi0), np.cos(psi0)])
    F = j0 - e_arm * e(chi0)
    u, w = t0 - F, j0 - F
    closure = 1 if u[0] * w[1] - u[1] * w[0] > 0 else -1
    return rocker, FourBarGeometry(a=-F[0], b=-F[1], e=e_arm, A=35 * MM, D=45 * MM,
                                   follower_radius=20 * MM, base_radius=15 * MM, branch=branch,
                                   closure=closure)


@settings(max_examples=10, deadline=None,
          suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(branch=st.sampled_from([1, -1]), anticlockwise=st.booleans(),
       psi0=st.floats(-10 * DEG, 10 * DEG), chi0=st.floats(-30 * DEG, 30 * DEG),
       height=st.floats(6 * MM, 10 * MM), width=st.floats(1.3, 1.7))
def test_four_bar_against_positions(branch, anticlockwise, psi0, chi0, height, width):
    theta = angle_grid(360)

    def law(t):
        return event_lift(t, height, width, 0.1)
    lift = law(theta)
    rocker, fb = _four_bar(branch, psi0, chi0, max_lift=lift.max_lift)
    rotation = "anticlockwise" if anticlockwise else "clockwise"
    try:
        k = pushrod_four_bar(lift, rocker, fb, omega=OMEGA, rotation=rotation)
    except GeometryError:
        assume(False)
    train = Train(rocker, law, lift.max_lift)
    joint, q_of = four_bar_follower(train, fb)
    gamma_b = branch * np.arccos((fb.A ** 2 + fb.D ** 2 - (fb.base_radius + fb.follower_radius)
                                  ** 2) / (2 * fb.A * fb.D))
    U = np.array([fb.D, 0.0])
    follower = Follower(lambda t: Pose(U, branch * q_of(t)), centre=fb.A * e(np.pi + gamma_b),
                        radius=fb.follower_radius, rotation=-1 if anticlockwise else 1)
    for a in (-60, -20, 0, 35, 100):
        i = int(np.argmin(np.abs(theta - a * DEG)))
        q1, q2 = derivatives(np.vectorize(q_of), theta[i])
        assert k.q[i] == pytest.approx(q_of(theta[i]), abs=1e-12)
        assert (k.q_d1[i], k.q_d2[i]) == pytest.approx((q1, q2), abs=1e-6)
        assert k.arm_valve[i] * k.q_d1[i] == pytest.approx(k.valve_d1[i], abs=1e-12)
        m = follower.measure(theta[i], OMEGA)
        assert (k.contact_x[i], k.contact_y[i]) == pytest.approx((m["x"], m["y"]), abs=1e-9)
        assert 1 / k.cam_radius[i] == pytest.approx(1 / m["rc"], rel=1e-4, abs=1e-2)
        assert k.v_cam[i] == pytest.approx(m["vc"], abs=1e-6 * OMEGA)
        assert k.v_follower[i] == pytest.approx(m["vf"], abs=1e-6 * OMEGA)
        g = [lambda t, c=c: (joint(t) + rocker.pushrod_cg_fraction
                             * (train.tip(t) - joint(t)))[c] for c in (0, 1)]
        gd = [derivatives(np.vectorize(gc), theta[i]) for gc in g]
        power = gd[0][0] * gd[0][1] + gd[1][0] * gd[1][1]
        assert k.inertia["pushrod_mass"][i] * k.q_d1[i] == pytest.approx(power, abs=1e-9)


def test_williams_corrected_quadratic_matches_the_joint():
    """Both roots of the corrected eqs 11.72-11.76 lie on both circles; one is the joint."""
    theta = angle_grid(72)
    lift = event_lift(theta, 9 * MM, 1.5)
    rocker, fb = _four_bar(1)
    train = Train(rocker, lambda t: event_lift(t, 9 * MM, 1.5), lift.max_lift)
    joint, _ = four_bar_follower(train, fb)
    for th in theta[::7]:
        x1, y1 = train.tip(th)
        qa, qb, qc = four_bar_quadratic(x1, y1, fb.a, fb.b, rocker.D1, rocker.pushrod_length,
                                        fb.e)
        roots = np.roots([qa, qb, qc]).real
        F = fb.a ** 2 + fb.b ** 2 - rocker.D1 ** 2 + rocker.pushrod_length ** 2 - fb.e ** 2
        for y2 in roots:
            x2 = -(F + 2 * y2 * (y1 + fb.b)) / (2 * (x1 + fb.a))
            assert np.hypot(x2 + fb.a, y2 + fb.b) == pytest.approx(fb.e, rel=1e-9)
            assert np.hypot(x1 - x2, y1 - y2) == pytest.approx(rocker.pushrod_length, rel=1e-9)
        assert np.min(np.abs(roots - joint(th)[1])) < 1e-12


def test_base_circle_and_tappet_lift_zero():
    theta = angle_grid(360)
    lift = event_lift(theta, 9 * MM, 1.5)
    k = pushrod_simple(lift, ROCKER, tappet_axis_distance=_x_bar(ROCKER, lift.max_lift),
                       base_radius=20 * MM, omega=OMEGA)
    rocker, fb = _four_bar(1)
    k4 = pushrod_four_bar(lift, rocker, fb, omega=OMEGA)
    base = np.abs(theta) > 1.55
    for kk, rb in ((k, 20 * MM), (k4, 15 * MM)):
        assert np.allclose(kk.cam_lift[base], 0.0, atol=1e-15)
        assert np.allclose(kk.cam_radius[base], rb, rtol=1e-12)
        assert np.allclose(kk.v_cam[base], OMEGA * rb, rtol=1e-12)
        assert np.allclose(kk.v_follower[base], 0.0, atol=1e-14)
