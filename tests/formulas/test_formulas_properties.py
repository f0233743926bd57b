"""Tier (c): mathematical properties, limits and closed forms checked against quadrature."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad
from scipy.special import ellipe, ellipk, i0

import camtrain.formulas as cf

STEEL = 2.3077e11


# ---------------------------------------------------------------- Hertz
def test_exact_point_hertz_reduces_to_circular():
    """Hertz (1881) circle, sphere of radius R on a flat: a^3 = 3 W R / (2 E'),
    p_max = 3 W / (2 pi a^2), delta = a^2 / R (Johnson 1985 eqs. 4.22-4.23 with E' = 2 E*)."""
    W, R = np.array([1.0, 50.0, 2000.0]), 0.012
    h = cf.hertz_point(W, R, R, STEEL)
    a = np.cbrt(3 * W * R / (2 * STEEL))
    np.testing.assert_allclose(h.a_x, a, rtol=1e-13)
    np.testing.assert_allclose(h.a_y, a, rtol=1e-13)
    np.testing.assert_allclose(h.max_pressure, 3 * W / (2 * np.pi * a**2), rtol=1e-13)
    np.testing.assert_allclose(h.approach, a**2 / R, rtol=1e-13)
    np.testing.assert_allclose(h.ellipticity, 1.0, rtol=1e-13)


@pytest.mark.parametrize("ratio", [1.01, 1.5, 10.0, 445.0, 1e5])
def test_exact_point_hertz_satisfies_surface_compatibility(ratio):
    """Independent check of the exact ellipse: the Hertz pressure on the computed ellipse must
    reproduce the prescribed relative curvatures through Johnson (1985) eq. 4.38 (A and B from
    the displacement integrals), to 1e-10."""
    Rx, W, E = 0.01, 120.0, 2.2e11
    h = cf.hertz_point(W, Rx, Rx * ratio, E)
    a, b, p0, Es = h.a_y, h.a_x, h.max_pressure, E / 2  # a major (along y), b minor
    e2 = 1 - (b / a) ** 2
    K, Ee = ellipk(e2), ellipe(e2)
    A = p0 / Es * b / (e2 * a**2) * (K - Ee)  # half curvature along the major axis
    B = p0 / Es * b / (e2 * a**2) * ((a / b) ** 2 * Ee - K)
    assert A * 2 * Rx * ratio == pytest.approx(1.0, rel=1e-10)
    assert B * 2 * Rx == pytest.approx(1.0, rel=1e-10)


def test_exact_point_hertz_tends_to_line_contact():
    """As R_y/R_x grows the central section of the ellipse approaches the line-contact Hertz
    solution for its own load per unit length w0 = 3W/(4 a_y): the ratios of half-width and
    peak pressure converge monotonically to 1."""
    W, Rx = 100.0, 0.01
    r = np.array([1.0, 10.0, 1e2, 1e3, 1e4, 1e6, 1e8])
    h = cf.hertz_point(W, Rx, Rx * r, STEEL)
    line = cf.hertz_line(3 * W / (4 * h.a_y), Rx, STEEL)
    dev = np.abs(h.a_x / line.half_width - 1)
    assert np.all(np.diff(dev) < 0) and dev[-1] < 1e-8
    assert np.all(np.diff(np.abs(h.max_pressure / line.max_pressure - 1)) < 0)


def test_point_hertz_axis_swap():
    """Swapping R_x and R_y swaps the semi-axes and inverts k (all methods)."""
    for method in cf.HERTZ_POINT_METHODS:
        h1 = cf.hertz_point(80.0, 0.01, 0.07, STEEL, method)
        h2 = cf.hertz_point(80.0, 0.07, 0.01, STEEL, method)
        assert (h1.a_x, h1.a_y) == pytest.approx((h2.a_y, h2.a_x), rel=1e-13)
        assert h1.ellipticity * h2.ellipticity == pytest.approx(1.0, rel=1e-13)
        assert h1.max_pressure == pytest.approx(h2.max_pressure, rel=1e-13)


@settings(max_examples=40, deadline=None)
@given(st.floats(1e-3, 1e4), st.floats(1e-4, 1.0), st.floats(1.0, 1e6))
def test_line_hertz_load_balance(w, R, scale):
    """Ball (1988) eqs. 3.8-3.10: the semi-elliptical pressure integrates to the load,
    (pi/2) p_max b = w, for any load and radius."""
    h = cf.hertz_line(w * scale, R, STEEL)
    assert np.pi / 2 * h.max_pressure * h.half_width == pytest.approx(w * scale, rel=1e-12)


# ---------------------------------------------------------------- friction integrals
@pytest.mark.parametrize("a", np.linspace(0.0, 30.0, 31))
def test_line_barus_integral_matches_quadrature(a):
    """Ball (1988) eq. 4.7 corrected: the closed form pi [I1(a) + L1(a)] + 2 equals the
    integral of exp(a sqrt(1 - s^2)) over [-1, 1] to 1e-10 (adaptive quadrature, docs/references/ball1988.md
    §2.6)."""
    q, _ = quad(lambda s: np.exp(a * np.sqrt(1 - s * s)), -1, 1, epsabs=0, epsrel=1e-13,
                limit=200)
    assert cf.barus_line_integral(a) == pytest.approx(q, rel=1e-10)


@pytest.mark.parametrize("A", [0.0, 1e-4, 0.009, 0.011, 0.5, 1.0, 5.0, 13.5, 30.0])
def test_ellipse_barus_integral_matches_quadrature(A):
    """Yang (1992) eq. 3.24 closed form 2 pi [e^A (A - 1) + 1] / A^2 (per unit a b) against
    quadrature in polar coordinates, to 1e-10, including the small-A series branch."""
    q, _ = quad(lambda r: 2 * np.pi * r * np.exp(A * np.sqrt(1 - r * r)), 0, 1, epsabs=0,
                epsrel=1e-13, limit=200)
    assert cf.barus_ellipse_integral(A) == pytest.approx(q, rel=1e-10)


def test_log_integrals_continuous_and_finite():
    """The overflow-safe branches join smoothly (a = 40 switch) and stay finite at a = 1e6,
    where ln J ~ a."""
    a = np.array([40 - 1e-9, 40 + 1e-9])
    assert np.ptp(cf.log_barus_line_integral(a)) < 1e-8
    big = cf.log_barus_line_integral(1e6)
    assert np.isfinite(big) and big == pytest.approx(1e6, rel=1e-4)
    assert np.isfinite(cf.log_barus_ellipse_integral(1e6))


def test_viscous_friction_uncapped_small_a_limit():
    """With alpha = 0 the Barus factor is 1: F = L eta0 |V_s| 2b / h (line) and
    eta0 |V_s| pi a b / h (ellipse) exactly."""
    F = cf.ball_1988_shear_force(-3.0, 2e-7, 0.02, 0.0, 5e8, 1e-4, 0.01)
    assert F == pytest.approx(0.01 * 0.02 * 3.0 * 2e-4 / 2e-7, rel=1e-14)
    F = cf.yang_1992_shear_force(3.0, 2e-7, 0.02, 0.0, 5e8, 1e-4, 3e-3)
    assert F == pytest.approx(0.02 * 3.0 * np.pi * 1e-4 * 3e-3 / 2e-7, rel=1e-14)


def test_cap_and_lambda_switch():
    """Ball (1988) §4.2.3.4: F = min(F_visc, mu W); lambda = h/sigma < 1 (sigma = 0.2 um)
    switches to boundary friction mu W."""
    W = 400.0
    args = (4.0, np.array([0.1e-6, 0.5e-6]), 0.05, 22e-9, 5e8, 5e-5, 0.012)
    visc = cf.ball_1988_shear_force(*args)
    capped = cf.ball_1988_friction(*args, W)
    np.testing.assert_allclose(capped, np.minimum(visc, 0.08 * W), rtol=1e-14)
    lam = cf.ball_1988_friction(*args, W, model="lambda")
    assert lam[0] == pytest.approx(0.08 * W) and lam[1] == pytest.approx(visc[1], rel=1e-14)


# ---------------------------------------------------------------- Greenwood-Tripp
@pytest.mark.parametrize("n", [2.0, 2.5])
@pytest.mark.parametrize("lam", [-1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0, 6.0])
def test_greenwood_tripp_function_matches_quadrature(n, lam):
    """Greenwood & Tripp F_n(lambda) via parabolic-cylinder functions against its defining
    integral (Teodorescu et al. 2005 notation list), to 1e-8."""
    q, _ = quad(lambda s: (s - lam) ** n * np.exp(-s * s / 2), lam, np.inf, epsabs=0,
                epsrel=1e-12)
    assert cf.greenwood_tripp_function(lam, n) == pytest.approx(q / np.sqrt(2 * np.pi), rel=1e-8)


@pytest.mark.derived
@pytest.mark.parametrize("n", [2.0, 2.5])
def test_greenwood_tripp_tabulated_is_the_exact_function(n):
    """The tabulated F_n (cubic Hermite pieces in ln F_n, 0.002 apart on [0, 3]) against the
    exact parabolic-cylinder evaluation at 20,000 points off the nodes, to 3e-13 relative; the
    exact function outside the table (negative and large lambda)."""
    lam = np.random.default_rng(7).uniform(0.0, 3.0, 20000)
    np.testing.assert_allclose(cf.greenwood_tripp_tabulated(lam, n),
                               cf.greenwood_tripp_function(lam, n), rtol=3e-13, atol=0.0)
    off = np.array([-0.7, 3.5, 31.0])
    np.testing.assert_array_equal(cf.greenwood_tripp_tabulated(off, n),
                                  cf.greenwood_tripp_function(off, n))


def test_greenwood_tripp_tabulated_needs_a_positive_order():
    with pytest.raises(ValueError, match="n > 0"):
        cf.greenwood_tripp_tabulated(1.0, 0.0)


def test_greenwood_tripp_fit_range():
    """The common fit 4.4086e-5 (4 - lambda)^6.804 is within 10 % for 0.5 <= lambda <= 2."""
    lam = np.linspace(0.5, 2.0, 16)
    ratio = cf.greenwood_tripp_f52_fit(lam) / cf.greenwood_tripp_function(lam, 2.5)
    assert np.all(np.abs(ratio - 1) < 0.1)


def test_teodorescu_split_identity():
    """Teodorescu et al. (2005) eq. 15: F_f = tau0 A + gamma W + (m - gamma) W_a, and the
    boundary term vanishes for lambda >= 3."""
    W, A, E = 800.0, 2e-6, 2.2e11
    lam = np.array([0.8, 1.5, 2.9, 3.0, 5.0])
    r = cf.teodorescu_2005_friction(W, A, lam, 2e6, 0.08, 0.12, E, 0.15e-6, 1e-4, 5e10)
    np.testing.assert_allclose(r.total, 2e6 * A + 0.08 * W + (0.12 - 0.08) * r.asperity_load,
                               rtol=1e-13)
    assert np.all(r.boundary[3:] == 0) and np.all(r.asperity_load[:3] > 0)


# ---------------------------------------------------------------- films
@settings(max_examples=30, deadline=None)
@given(st.floats(0.05, 20.0), st.floats(1e3, 1e6), st.floats(1e-3, 0.1))
def test_film_exponents(u, w, R):
    """Dowson & Higginson (1977) h ~ u^0.70 w^-0.13; Dowson & Toyoda h ~ u^0.69 w^-0.10;
    the sign of the entrainment speed does not matter."""
    kw = dict(eta0=0.01, alpha=2e-8, E_r=STEEL)
    dh = cf.dowson_higginson_1977
    assert dh(w, R, 2 * u, **kw) / dh(w, R, u, **kw) == pytest.approx(2**0.7, rel=1e-12)
    assert dh(2 * w, R, u, **kw) / dh(w, R, u, **kw) == pytest.approx(2**-0.13, rel=1e-12)
    assert dh(w, R, -u, **kw) == dh(w, R, u, **kw)
    dt = cf.dowson_toyoda_1979
    assert dt(w, R, 2 * u, **kw) / dt(w, R, u, **kw) == pytest.approx(2**0.69, rel=1e-12)


def test_film_dispatcher_and_methods():
    """Registry: aliases, default method by geometry, applicability by inputs and ranges."""
    case_a = dict(w=2e5, R=0.02, u=1.0, eta0=0.04, alpha=2e-8, E_r=2.26e11)
    assert cf.film_thickness(**case_a) == cf.dowson_higginson_1977(**case_a)
    assert cf.film_thickness(method="blok", **case_a) == cf.dowson_dunn_taylor_1983(
        0.02, 1.0, 0.04, 2e-8)
    names = cf.film_thickness_methods(**case_a)
    assert "dowson_higginson_1977" in names and "moes_1992" in names
    assert "martin_1916" not in names  # M = 10.5: far from rigid-isoviscous
    assert "martin_1916" in cf.film_thickness_methods(check_ranges=False, **case_a)
    assert cf.film_thickness_methods(kind="line/central", **case_a)[0] == "dowson_toyoda_1979"
    no_load = dict(R=0.02, u=1.0, eta0=0.04, alpha=2e-8, E_r=2.26e11)
    assert cf.film_thickness_methods(**no_load) == ["dowson_dunn_taylor_1983"]
    assert cf.film_thickness(**no_load) == cf.dowson_dunn_taylor_1983(0.02, 1.0, 0.04, 2e-8)
    point = dict(W=50.0, Rx=0.01, Ry=0.01, u=1.0, eta0=0.01, alpha=2e-8, E_r=STEEL)
    assert cf.film_thickness(**point) == cf.hamrock_dowson_1977_min(**point)


def test_entrainment_conventions():
    """Ball (1988) nomenclature V_e = (V_c + V_f)/2 vs the sum used in his Ch. 3 and 5."""
    assert cf.entrainment_speed(0.955, -3.349) == pytest.approx(-1.197)
    assert cf.entrainment_speed(0.955, -3.349, "sum") == pytest.approx(-2.394)
    assert cf.sliding_speed(0.955, -3.349) == pytest.approx(4.304)


# ---------------------------------------------------------------- viscosity
def test_roelands_matches_barus_slope_and_limits():
    """Roelands (1966) with z from alpha (Houpert identification) has the Barus slope at p = 0
    and lies below Barus at high pressure."""
    eta0, alpha = 0.04, 2e-8
    dp = 1e3
    slope = np.log(cf.roelands(dp, eta0, alpha) / cf.roelands(-dp, eta0, alpha)) / (2 * dp)
    assert slope == pytest.approx(alpha, rel=1e-6)
    assert cf.roelands(1e9, eta0, alpha) < cf.barus(1e9, eta0, alpha)
    assert cf.roelands(0.0, eta0, z=0.68) == pytest.approx(eta0, rel=1e-15)


def test_temperature_fits_roundtrip():
    """Reynolds and Walther two-point fits and the Vogel three-point fit pass through their
    data; the Vogel least-squares fit recovers exact parameters."""
    T1, T2 = 313.15, 373.15
    assert cf.reynolds_two_point(T2, T1, 0.05, T2, 0.008) == pytest.approx(0.008, rel=1e-13)
    nu = cf.walther_two_point(np.array([T1, T2]), T1, 68e-6, T2, 10e-6)
    np.testing.assert_allclose(nu, [68e-6, 10e-6], rtol=1e-12)
    A, B, Tinf = 7e-5, 900.0, 170.0
    T = np.array([300.0, 340.0, 380.0, 420.0])
    eta = cf.vogel(T, A, B, Tinf)
    for pts in (slice(0, 3), slice(0, 4)):
        fit = cf.vogel_fit(T[pts], eta[pts])
        assert fit == pytest.approx((A, B, Tinf), rel=1e-6)


# ---------------------------------------------------------------- cycle means, guides, bearings
def test_trapezoid_is_spectral_on_periodic_grid():
    """Periodic trapezoid (the sample mean) integrates exp(cos phi) to machine precision with
    16 points; Simpson (Ball 1988 eq. 4.9) on the same grid is far less accurate."""
    exact = i0(1.0)  # (1/2pi) int exp(cos phi) dphi
    phi = np.linspace(0, 2 * np.pi, 16, endpoint=False)
    f = np.exp(np.cos(phi))
    assert cf.cycle_mean(f) == pytest.approx(exact, rel=1e-15)
    assert abs(cf.cycle_mean(f, method="simpson") / exact - 1) > 1e-8
    closed = np.append(f, f[0])
    assert cf.cycle_mean(closed, closed=True) == pytest.approx(exact, rel=1e-15)


def test_guide_boundary_identities():
    """Yang (1992) eqs. 3.26-3.28: F_f1 + F_f2 = F_v - F_z and F_f2 - F_f1 = mu F_c."""
    r = cf.yang_1992_guide_boundary(500.0, 40.0, 0.004, 0.0284, 0.0265, mu=0.08)
    assert r.friction_1 + r.friction_2 == pytest.approx(500.0 - r.axial_reaction, rel=1e-14)
    assert r.friction_2 - r.friction_1 == pytest.approx(0.08 * 40.0, rel=1e-13)


@settings(max_examples=30, deadline=None)
@given(st.floats(0.0, 0.99))
def test_ocvirk_inverse_roundtrip(eps):
    """ocvirk_eccentricity inverts ocvirk_load (Ocvirk 1952)."""
    args = (0.01, 157.08, 0.0125, 0.018, 25e-6)
    W = cf.ocvirk_load(*args, eps)
    assert cf.ocvirk_eccentricity(W, *args) == pytest.approx(eps, abs=1e-12)


def test_registry_records_and_doctests():
    """Every registered film formula names its source; the dispatcher's doctest (case A,
    Dowson & Higginson 1977, 336.5 nm) runs."""
    import doctest

    from camtrain.formulas import film

    for name, rec in cf.FILM_METHODS.items():
        assert rec.reference and "Reference" in (rec.func.__doc__ or ""), name
        assert rec.func.__name__ == name
    assert doctest.testmod(film).failed == 0


def test_fast_barus_line_integral_matches_closed_form():
    """The Gauss-Legendre evaluation of J(a) equals Ball's corrected closed form
    pi [I_1(a) + L_1(a)] + 2 to 1e-12 relative over the whole range where it is used (a < 40)."""
    a = np.linspace(0.0, 39.999, 2001)
    fast = np.exp(cf.log_barus_line_integral(a))
    assert np.max(np.abs(fast / cf.barus_line_integral_closed_form(a) - 1.0)) < 1e-12


@pytest.mark.parametrize("p_max", [1e6, 1e8, 5e8, 2e9])
def test_roelands_zone_integrals_against_quadrature(p_max):
    """Roelands (1966) integrated over a Hertz line and ellipse zone: the Gauss-Legendre
    evaluation equals adaptive quadrature of the same integrand to 1e-10."""
    eta0, alpha = 0.05, 22e-9

    def ratio(p):
        return float(cf.roelands(p, eta0, alpha=alpha) / eta0)

    line = quad(lambda s: ratio(p_max * np.sqrt(1.0 - s * s)), -1.0, 1.0, epsabs=0,
                epsrel=1e-12, limit=200)[0]
    disc = 2 * np.pi * quad(lambda c: ratio(p_max * c) * c, 0.0, 1.0, epsabs=0,
                            epsrel=1e-12, limit=200)[0]
    assert np.exp(cf.log_roelands_line_integral(p_max, eta0, alpha)) == pytest.approx(line,
                                                                                      rel=1e-10)
    assert np.exp(cf.log_roelands_ellipse_integral(p_max, eta0, alpha)) == pytest.approx(disc,
                                                                                         rel=1e-10)


def test_roelands_matches_barus_at_low_pressure_and_falls_below_at_hertz_pressure():
    """z is matched to alpha at p = 0, so the two laws agree as p_max -> 0; at cam-nose Hertz
    pressures Roelands gives the lower viscosity (the reason it is offered)."""
    eta0, alpha = 0.05, 22e-9
    low, high = 1e4, 6e8
    assert cf.log_roelands_line_integral(low, eta0, alpha) == pytest.approx(
        cf.log_barus_line_integral(alpha * low), rel=1e-6)
    assert cf.log_roelands_line_integral(high, eta0, alpha) < \
        cf.log_barus_line_integral(alpha * high)
