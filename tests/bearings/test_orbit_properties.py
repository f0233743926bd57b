"""Mobility orbit kernel: analytic limits and properties (no published data needed)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camtrain.bearings import EPS_LIMIT, JournalBearing, bearing_orbit, journal_orbit, steady_orbit
from camtrain.errors import ConvergenceError, InputError
from camtrain.formulas.bearings import martin_1985_shear_power, ocvirk_attitude_angle, ocvirk_eccentricity

RPM = 2.0 * math.pi / 60.0
# formulas_and_anchors §4.3 example bearing: D 25 mm, L 18 mm, c 25 um, 0.01 Pa s, 1500 rev/min.
BRG = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
W = 1500 * RPM
N = 36
TH = np.arange(N) * (2 * math.pi / N)


def _const(load, angle=-0.5 * math.pi):
    return load * math.cos(angle) * np.ones(N), load * math.sin(angle) * np.ones(N)


@pytest.mark.parametrize("load", [50.0, 500.0, 5000.0])
def test_constant_load_converges_to_ocvirk(load):
    """Constant load from the centre: the orbit must settle on the Ocvirk steady solution
    (formulas_and_anchors §4.3; exact pi-film mobility, so only the march tolerance remains:
    1e-5 in eps, 1e-4 rad in attitude)."""
    fx, fy = _const(load)
    o = bearing_orbit(BRG, fx, fy, TH, W, start="centre", max_cycles=60)
    e = ocvirk_eccentricity(load, BRG.viscosity, W, BRG.radius, BRG.length, BRG.clearance)
    assert o.converged and o.periodicity_error <= 1e-5
    assert np.allclose(o.eccentricity, e, atol=1e-5)
    assert np.allclose(o.attitude, ocvirk_attitude_angle(e), atol=1e-4)
    if load == 500.0:  # anchor: eps 0.7165, h_min 7.09 um, attitude 37.40 deg (4 figures)
        assert o.eccentricity[0] == pytest.approx(0.7165, abs=5e-5)
        assert o.h_min[0] == pytest.approx(7.09e-6, abs=5e-9)
        assert math.degrees(o.attitude[0]) == pytest.approx(37.40, abs=5e-3)


def test_booker_closed_form_close_to_ocvirk():
    """Yang §2.1.5: Booker's approximate mobility (eqs 1.15/1.16) reproduces Ocvirk's eps to
    within 0.4 % over eps 0.66-0.94 at steady load; we allow 0.5 %."""
    for load in (300.0, 500.0, 2000.0, 8000.0):
        fx, fy = _const(load)
        o = bearing_orbit(BRG, fx, fy, TH, W, mobility="booker", max_cycles=60)
        e = ocvirk_eccentricity(load, BRG.viscosity, W, BRG.radius, BRG.length, BRG.clearance)
        assert 0.6 < e < 0.95
        assert o.eccentricity[0] == pytest.approx(e, rel=5e-3)


def test_steady_orbit_is_ocvirk_and_powers():
    """Steady method = Ocvirk at each angle; 2 pi shear power = Martin (1985) (Yang eq. 1.18);
    pi film over the loaded half = half of it; the 'all' extra term = wbar W e sin(attitude)
    (Yang eq. 1.20 with V = 0). Identities: 1e-12 relative."""
    fx, fy = _const(500.0)
    s2 = steady_orbit(BRG, fx, fy, TH, W, film="2pi", terms="all")
    e = s2.eccentricity[0]
    h = martin_1985_shear_power(BRG.viscosity, W, BRG.radius, BRG.length, BRG.clearance, e)
    assert np.allclose(s2.power_shear, h, rtol=1e-12)
    s1 = steady_orbit(BRG, fx, fy, TH, W, film="pi")
    assert np.allclose(s1.power_shear, 0.5 * h, rtol=1e-12)
    press = 0.5 * W * 500.0 * e * BRG.clearance * math.sin(ocvirk_attitude_angle(e))
    assert np.allclose(s2.power_squeeze, press, rtol=1e-9)
    assert s2.mean_power == pytest.approx(h + press, rel=1e-9)


def test_grooved_bearing_is_two_lands():
    """A central groove: each land a short bearing carrying half the load (Yang §2.4)."""
    g = JournalBearing(25e-3, 20e-3, 25e-6, 0.01, groove_width=2e-3)
    fx, fy = _const(800.0)
    o = steady_orbit(g, fx, fy, TH, W)
    e = ocvirk_eccentricity(400.0, 0.01, W, 12.5e-3, 9e-3, 25e-6)
    assert o.eccentricity[0] == pytest.approx(e, rel=1e-12)
    d = bearing_orbit(g, fx, fy, TH, W)
    assert d.eccentricity[0] == pytest.approx(e, abs=1e-5)


def _wobble(load, phase=0.0, k=2):
    a = phase + 0.3 * np.sin(k * TH)
    mag = load * (1.0 + 0.8 * np.cos(TH))
    return mag * np.cos(a - 0.5 * math.pi), mag * np.sin(a - 0.5 * math.pi)


@settings(max_examples=6, deadline=None)
@given(rot=st.floats(-math.pi, math.pi))
def test_rotation_invariance(rot):
    """Rotating every load vector rotates the orbit by the same angle (isotropic bush)."""
    fx, fy = _wobble(400.0)
    c, s = math.cos(rot), math.sin(rot)
    a = bearing_orbit(BRG, fx, fy, TH, W, tol=1e-9, period_tol=1e-7)
    b = bearing_orbit(BRG, c * fx - s * fy, s * fx + c * fy, TH, W, tol=1e-9, period_tol=1e-7)
    assert np.allclose(b.eccentricity, a.eccentricity, atol=1e-6)
    assert np.allclose(b.eps_x, c * a.eps_x - s * a.eps_y, atol=1e-6)
    assert np.allclose(b.power, a.power, rtol=1e-5)


def test_periodic_and_resolution_converges():
    """A varying load gives a periodic orbit; tightening tol changes h_min by < 1 %."""
    fx, fy = _wobble(600.0)
    a = bearing_orbit(BRG, fx, fy, TH, W, tol=1e-6)
    b = bearing_orbit(BRG, fx, fy, TH, W, tol=1e-10, period_tol=1e-7)
    assert a.converged and a.periodicity_error <= 1e-5 and a.cycles >= 2
    assert a.min_film == pytest.approx(b.min_film, rel=1e-2)
    # the same orbit from a different start (periodic attractor)
    c = bearing_orbit(BRG, fx, fy, TH, W, start="centre", tol=1e-10, period_tol=1e-7)
    assert np.allclose(b.eccentricity, c.eccentricity, atol=1e-5)


@pytest.mark.parametrize("scale", [1e3, 1e6, 1e9])
def test_eps_stays_below_one_for_huge_loads(scale):
    """Loads far beyond capacity: the march never lets eps reach 1 and h_min stays > 0."""
    fx, fy = _wobble(scale)
    o = journal_orbit(fx, fy, TH, W, 0.0, 25e-3, 18e-3, 25e-6, 0.01, max_cycles=30)
    assert np.all(o.eccentricity < 1.0) and np.all(o.eccentricity <= EPS_LIMIT)
    assert np.all(o.h_min > 0.0) and np.all(np.isfinite(o.power))


def test_quasi_static_limit_matches_steady():
    """A load diagram spread over k journal revolutions makes squeeze ~ 1/k: the mobility orbit
    approaches the steady-load locus at first order (error ratio 4 +- 10 % for k 200 -> 800)."""
    fx, fy = _wobble(500.0)
    err = []
    for k in (200.0, 800.0):
        rate = W / k
        d = bearing_orbit(BRG, fx, fy, TH, W, angle_rate=rate, tol=1e-9, period_tol=1e-7)
        s = steady_orbit(BRG, fx, fy, TH, W, angle_rate=rate)
        err.append(np.max(np.abs(d.eccentricity - s.eccentricity)))
    assert err[1] < 1e-3
    assert err[0] / err[1] == pytest.approx(4.0, rel=0.1)


def test_half_speed_whirl_is_reported_not_periodic():
    """A load turning with wbar (half-speed whirl) leaves only squeeze: eps creeps towards 1
    without settling. The kernel keeps eps < 1 and reports non-convergence."""
    rate = 0.5 * W
    ang = TH  # one turn per load cycle, load cycle time 2 pi / rate: load turns at wbar
    fx, fy = 500.0 * np.cos(ang), 500.0 * np.sin(ang)
    with pytest.raises(ConvergenceError):
        bearing_orbit(BRG, fx, fy, TH, W, angle_rate=rate, max_cycles=6)


def test_input_errors():
    fx, fy = _const(100.0)
    with pytest.raises(InputError):
        bearing_orbit(BRG, fx, fy, TH[::-1], W)
    with pytest.raises(InputError):
        bearing_orbit(BRG, fx[:-1], fy, TH, W)
    with pytest.raises(InputError):
        bearing_orbit(BRG, fx, fy, TH, W, film="3pi")
    with pytest.raises(InputError):
        JournalBearing(25e-3, 18e-3, -1e-6, 0.01)
    with pytest.raises(InputError):
        steady_orbit(BRG, fx, fy, TH, W, -W)  # wbar = 0: steady method undefined
