"""Tier (c): hard cases run with every floating-point warning turned into an exception.

Policies under test (documented in the modules): huge alpha p_max -> capped friction finite;
zero entrainment -> h = 0 and friction = mu W; very large R -> finite everything; zero load ->
Hertz 0, friction 0, film +inf (an unloaded contact separates); conformal or interfering
contacts -> a field error naming the offending index.
"""
from __future__ import annotations

import numpy as np
import pytest

import camtrain.formulas as cf
from camtrain.errors import InputError

E = 2.26e11
LINE_METHODS = [m for m, rec in cf.FILM_METHODS.items() if rec.kind.startswith("line")]
POINT_METHODS = [m for m, rec in cf.FILM_METHODS.items() if rec.kind.startswith("point")]


def _line_inputs(w, R, u):
    return dict(w=w, R=R, u=u, eta0=0.04, alpha=2e-8, E_r=E)


@pytest.mark.usefixtures("raise_all")
def test_huge_alpha_pmax_friction_is_capped_and_finite():
    """Ball (1988) §4.2.3.4 cap F = min(F_visc, mu W) keeps a = alpha p_max up to 1e6 finite."""
    p_max = np.array([0.0, 1e9, 5e10, 1e13, 5e16])  # a up to 1e9
    F = cf.ball_1988_friction(5.0, 1e-7, 0.04, 2e-8, p_max, 1e-4, 0.012, 500.0)
    assert np.all(np.isfinite(F)) and F[-1] == pytest.approx(40.0)
    F = cf.yang_1992_friction(5.0, 1e-7, 0.04, 2e-8, p_max, 1e-4, 3e-3, 500.0)
    assert np.all(np.isfinite(F)) and F[-1] == pytest.approx(40.0)
    # uncapped: +inf where beyond the float range, silently
    assert cf.ball_1988_shear_force(5.0, 1e-7, 0.04, 2e-8, 1e12, 1e-4, 0.012) == np.inf
    eta = cf.barus(np.array([1e9, 1e12]), 0.04, 2e-8)
    assert np.isfinite(eta[0]) and eta[1] == np.inf
    assert cf.barus(1e12, 0.04, 2e-8, eta_max=1e9) == 1e9
    assert np.isfinite(cf.barus_log(1e12, 0.04, 2e-8))


@pytest.mark.usefixtures("raise_all")
@pytest.mark.parametrize("method", LINE_METHODS)
def test_zero_entrainment_line(method):
    """Ball (1988) §4.2.3.1: film -> 0 at zero entrainment (|u| used), no warnings."""
    h = cf.film_thickness(method=method, **_line_inputs(np.array([2e5, 2e5]), 0.02,
                                                         np.array([0.0, -0.0])))
    np.testing.assert_array_equal(h, 0.0)


@pytest.mark.usefixtures("raise_all")
@pytest.mark.parametrize("method", POINT_METHODS)
def test_zero_entrainment_point(method):
    """Yang (1992) §3.2.4: where V_e = 0 the film is 0 (quasi-static artefact), no warnings."""
    kw = dict(W=50.0, u=0.0, eta0=0.01, alpha=2e-8, E_r=E)
    kw.update(dict(R_e=0.01, R_s=0.02) if "chittenden" in method else dict(Rx=0.01, Ry=0.02))
    assert cf.film_thickness(method=method, **kw) == 0.0


@pytest.mark.usefixtures("raise_all")
def test_zero_entrainment_friction_goes_to_cap():
    """h = 0 with sliding: the viscous prediction diverges and the cap mu W applies (Ball 1988;
    Yang 1992 §4.2); with no sliding either, friction is 0."""
    h = cf.dowson_toyoda_1979(2e5, 0.02, 0.0, 0.04, 2e-8, E)
    F = cf.ball_1988_friction(np.array([4.0, 0.0]), h, 0.04, 2e-8, 5e8, 1e-4, 0.012, 300.0)
    np.testing.assert_allclose(F, [24.0, 0.0])


@pytest.mark.usefixtures("raise_all")
def test_large_radius_is_finite():
    """R -> infinity (nearly conformal, 1/R -> 0+): every formula stays finite."""
    R = np.array([1.0, 1e3, 1e9, 1e12])
    for method in LINE_METHODS:
        assert np.all(np.isfinite(cf.film_thickness(method=method, **_line_inputs(2e5, R, 2.0))))
    hl = cf.hertz_line(2e5, R, E)
    assert np.all(np.isfinite(hl.half_width)) and np.all(hl.max_pressure > 0)
    hp = cf.hertz_point(100.0, R, 3 * R, E)
    assert all(np.all(np.isfinite(v)) for v in hp)
    hp = cf.hertz_point(100.0, 0.01, R * 1e3, E)  # very elongated ellipse, ratio up to 1e17
    assert all(np.all(np.isfinite(v)) for v in hp)
    for method in POINT_METHODS:
        kw = dict(W=50.0, u=1.0, eta0=0.01, alpha=2e-8, E_r=E)
        kw.update(dict(R_e=R, R_s=3 * R) if "chittenden" in method else dict(Rx=R, Ry=3 * R))
        assert np.all(np.isfinite(cf.film_thickness(method=method, **kw)))


@pytest.mark.usefixtures("raise_all")
def test_zero_load():
    """Zero load (valve clearance, base circle off contact): Hertz gives 0, friction 0 (finite);
    load-dependent films return +inf by policy, the load-free Blok film stays finite."""
    hl = cf.hertz_line(0.0, 0.02, E, L=0.012)
    assert hl.half_width == 0 and hl.max_pressure == 0
    hp = cf.hertz_point(0.0, 0.01, 0.02, E)
    assert hp.a_x == 0 and hp.max_pressure == 0 and hp.approach == 0
    for method in LINE_METHODS:
        h = cf.film_thickness(method=method, **_line_inputs(0.0, 0.02, np.array([0.0, 1.0])))
        if method == "dowson_dunn_taylor_1983":
            assert np.all(np.isfinite(h))
        else:
            np.testing.assert_array_equal(h, np.inf)
    h = cf.dowson_toyoda_1979(0.0, 0.02, 1.0, 0.04, 2e-8, E)
    F = cf.ball_1988_friction(4.0, h, 0.04, 2e-8, hl.max_pressure, hl.half_width, 0.012, 0.0)
    assert F == 0.0
    assert cf.friction_coefficient(F, 0.0) == 0.0
    r = cf.teodorescu_2005_friction(0.0, 0.0, 0.5, 2e6, 0.08, 0.12, E, 0.15e-6, 1e-4, 5e10)
    assert r.total == 0.0


@pytest.mark.usefixtures("raise_all")
def test_greenwood_tripp_far_separation_no_underflow():
    """F_n(lambda) for very thick films is exactly 0 without an underflow exception."""
    v = cf.greenwood_tripp_function(np.array([25.0, 40.0, 1e6]), 2.5)
    assert v[0] > 0 and v[1] == 0 and v[2] == 0


@pytest.mark.parametrize("R", [np.inf, -0.05, 0.0])
def test_conformal_or_interfering_contact_is_a_field_error(R):
    """1/R <= 0 (conformal or concave-dominant) or R = 0: a clear InputError naming R."""
    with pytest.raises(InputError, match="R"):
        cf.hertz_line(1e5, R, E)
    with pytest.raises(InputError, match="R"):
        cf.dowson_higginson_1977(1e5, R, 1.0, 0.04, 2e-8, E)
    with pytest.raises(InputError, match="Ry"):
        cf.hertz_point(10.0, 0.01, R, E)


def test_reduced_radius_reports_conformal_geometry():
    """reduced_radius itself only reports: inf when 1/r1 + 1/r2 = 0, negative when concave
    dominates; the first offending index is named when a formula rejects it."""
    assert cf.reduced_radius(0.02, -0.02) == np.inf
    assert cf.reduced_radius(0.01, -0.005) == pytest.approx(-0.01)
    assert cf.reduced_radius(0.02, np.inf) == pytest.approx(0.02)
    R = cf.reduced_radius(np.array([0.02, 0.02, 0.02]), np.array([np.inf, -0.02, 0.05]))
    with pytest.raises(InputError, match="index 1"):
        cf.hertz_line(1e5, R, E)


def test_bad_inputs():
    """Negative loads and unknown options are rejected clearly."""
    with pytest.raises(InputError, match="w"):
        cf.dowson_toyoda_1979(-1.0, 0.02, 1.0, 0.04, 2e-8, E)
    with pytest.raises(InputError, match="method"):
        cf.film_thickness(method="nonexistent", w=1.0, R=0.01, u=1.0, eta0=0.01)
    with pytest.raises(ValueError):
        cf.hertz_point(10.0, 0.01, 0.02, E, method="bogus")
    with pytest.raises(InputError, match="eps"):
        cf.ocvirk_load(0.01, 100.0, 0.01, 0.01, 1e-5, 1.0)
