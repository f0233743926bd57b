"""Level 2: Göçmen's averaged Reynolds contact with asperities, marched implicitly."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from camtrain.formulas import greenwood_tripp_function, martin_1916
from camtrain.lubrication import (
    FilmProperties,
    FilmResolution,
    contact_solution,
    hertz_zone_half_width,
    implicit_march,
    solve_positive_root,
    transient_film,
)
from camtrain.lubrication.asperity import gt_function
from camtrain.lubrication.averaged_reynolds import contact_load
from camtrain.lubrication.flow_factors import (
    contact_factor,
    mean_gap,
    pressure_flow_factor,
    shear_flow_factor,
)

E_R, OMEGA, WIDTH = 1.8446e11, 104.72, 0.02
ROUGH = FilmProperties(viscosity=0.014, width=WIDTH, modulus=E_R, roughness=0.65e-6)
COARSE = FilmResolution(nodes=81, tolerance=1e-6)


def cam_cycle(n=120, separated=False):
    """Synthetic cam: base circle, flanks with large radius, nose with reversal at ~+-35 deg."""
    theta = np.linspace(-np.pi, np.pi, n, endpoint=False)
    bump = np.exp(-(theta / 0.9) ** 2)
    flank = np.exp(-((np.abs(theta) - 0.9) / 0.35) ** 2)
    rho = 0.018 + 0.03 * flank - 0.010 * bump
    u_e = 0.9425 * (1.0 - 2.2 * bump) + 2.0 * flank
    load = 650.0 + 300.0 * bump
    if separated:
        load = load - 1200.0 * np.exp(-(theta / 0.15) ** 2)
    u_s = 2.0 * u_e
    b2 = hertz_zone_half_width(load, WIDTH, rho, E_R)
    return theta, rho, u_e, load, b2, u_s


@pytest.fixture(scope="module")
def rough_run():
    theta, rho, u_e, load, b2, u_s = cam_cycle()
    film = transient_film(theta, OMEGA, rho, u_e, load, b2, ROUGH, COARSE, u_s=u_s)
    return (theta, rho, u_e, load, b2, u_s), film


def test_flow_factor_forms():
    """Patir-Cheng and Wu-Zheng forms: continuity at the fit ends, the Gaussian limit phi_c(0)
    ~ 1/2, and the mean gap's slope is phi_c (its defining property)."""
    assert shear_flow_factor(5.0 - 1e-9) == pytest.approx(shear_flow_factor(5.0 + 1e-9), rel=2e-3)
    assert contact_factor(3.0 - 1e-9) == pytest.approx(1.0, abs=2e-3)
    assert contact_factor(0.0) == pytest.approx(0.5, abs=2e-3)
    assert pressure_flow_factor(50.0) == pytest.approx(1.0, abs=1e-10)
    H = np.linspace(0.05, 2.95, 30)
    slope = (mean_gap(H + 1e-5) - mean_gap(H - 1e-5)) / 2e-5
    np.testing.assert_allclose(slope, contact_factor(H), rtol=1e-5)
    np.testing.assert_allclose(mean_gap([3.0, 4.0]), [3.0, 4.0], rtol=1e-12)


def test_asperity_table_matches_exact_function():
    lam = np.linspace(-3.9, 29.0, 997)
    for n in (2.0, 2.5):
        np.testing.assert_allclose(gt_function(lam, n), greenwood_tripp_function(lam, n),
                                   rtol=1e-7)


def test_load_balance_at_every_loaded_angle(rough_run):
    """S6: |W_T - W_P - W_A| / W_T <= tolerance at every loaded angle, recomputed from the
    reported film, rate and loads."""
    (theta, rho, u_e, load, b2, u_s), film = rough_run
    assert np.all(film.balance_error <= COARSE.tolerance)
    total = film.fluid_load + film.asperity_load
    np.testing.assert_allclose(total, load, rtol=COARSE.tolerance)
    assert film.period_error <= COARSE.period_tol
    assert np.all(film.film > 0.0)
    assert set(film.regime) <= {"hydrodynamic", "mixed", "boundary"}
    assert not film.unbalanced.any()


def test_film_positive_through_reversal_with_both_loads(rough_run):
    """Pure squeeze at the reversal: the fluid still carries load where u_e = 0."""
    (theta, rho, u_e, load, b2, u_s), film = rough_run
    zeros = np.flatnonzero(np.sign(u_e) != np.sign(np.roll(u_e, -1)))
    assert zeros.size >= 2
    for i in zeros:
        assert film.film[i] > 0.0 and film.fluid_load[i] > 0.0


def test_no_squeeze_is_the_per_angle_steady_solution():
    """S5: with dh/dt forced to 0 the march is the independent per-angle steady balance."""
    theta, rho, u_e, load, b2, u_s = cam_cycle(24)
    film = transient_film(theta, OMEGA, rho, u_e, load, b2, ROUGH, COARSE, u_s=u_s,
                          squeeze=False)
    xi = COARSE.grid()
    for i in range(theta.size):
        h, _, met = solve_positive_root(
            lambda v, i=i: contact_load(ROUGH, xi, b2[i], v, 0.0, rho[i], 0.0, u_e[i], u_s[i])
            / load[i] - 1.0, 1e-7)
        assert met
        assert film.film[i] == pytest.approx(h, rel=1e-8)


@pytest.mark.parametrize("march", ["implicit_euler", "bdf2"])
def test_constant_conditions_converge_to_steady(march):
    """At constant load, speed and radius the transient film is the steady one (1e-8)."""
    n = 24
    args = (np.linspace(-np.pi, np.pi, n, endpoint=False), OMEGA, np.full(n, 0.018),
            np.full(n, 0.9425), np.full(n, 650.0), np.full(n, 3.6e-4))
    res = FilmResolution(nodes=81, march=march, period_tol=1e-12, cycles_max=4)
    steady = transient_film(*args, ROUGH, res, squeeze=False)
    moving = transient_film(*args, ROUGH, res, h_start=3e-7)
    np.testing.assert_allclose(moving.film, steady.film, rtol=1e-8)


def test_smooth_rigid_steady_limit_is_martin():
    """S4 + S2: smooth (sigma = 0) rigid steady level 2 on a wide zone reproduces the existing
    martin_1916 film (0.5 %)."""
    smooth = FilmProperties(viscosity=0.014, width=WIDTH, modulus=E_R)
    n, R, u, W = 8, 0.018, 0.9425, 650.0
    h_martin = martin_1916(w=W / WIDTH, R=R, u=u, eta0=0.014)
    zone = 200.0 * math.sqrt(2.0 * R * h_martin)
    film = transient_film(np.linspace(-np.pi, np.pi, n, endpoint=False), OMEGA, R, u, W, zone,
                          smooth, FilmResolution(nodes=1601, clustering=5.0), squeeze=False)
    np.testing.assert_allclose(film.film, h_martin, rtol=5e-3)
    assert np.all(film.regime == "hydrodynamic")


def test_mirrored_cycle_gives_the_same_film():
    """Reversing every speed (the mirrored contact) leaves the symmetric-gap film unchanged."""
    theta, rho, u_e, load, b2, u_s = cam_cycle(36)
    a = transient_film(theta, OMEGA, rho, u_e, load, b2, ROUGH, COARSE, u_s=u_s)
    b = transient_film(theta, OMEGA, rho, -u_e, load, b2, ROUGH, COARSE, u_s=-u_s)
    np.testing.assert_allclose(b.film, a.film, rtol=1e-9)


def test_separated_angles_are_labelled_and_held():
    theta, rho, u_e, load, b2, u_s = cam_cycle(72, separated=True)
    film = transient_film(theta, OMEGA, rho, u_e, load, b2, ROUGH, COARSE, u_s=u_s)
    off = load <= 0.0
    assert off.any()
    assert np.all(film.regime[off] == "separated")
    assert np.all(np.isnan(film.balance_error[off]))
    assert np.all(film.film_rate[off] == 0.0)


def test_opening_edges_near_reversal_give_several_pressure_zones():
    """Where the radius shrinks fast the zone edges open while the centre approaches: a
    cavitated stretch lies between two pressurised zones (complementarity branch), and the
    pressures still carry load."""
    xi = np.linspace(-1, 1, 201)
    props = dataclasses.replace(ROUGH, shear_weight=1.0)
    s = contact_solution(props, xi, 3.6e-4, 5e-8, -5e-4, 0.0138, -7.5, 0.03, 2.4)
    wet = s.pressure > 0.0
    starts = np.flatnonzero(wet[1:] & ~wet[:-1])
    assert starts.size >= 2                  # a second zone re-forms downstream
    assert s.fluid_load > 0.0


def quadratic_balance(t_nodes):
    """Cheap film-like balance: W(y, ydot) = a/y - b ydot / y^1.5 (wedge + squeeze) = W_T(t)."""
    load = 1.0 + 0.5 * np.sin(2.0 * np.pi * t_nodes) + 0.2 * np.cos(4.0 * np.pi * t_nodes)
    return lambda i, y, yd: (1.0 / y - 0.05 * yd / y**1.5) / load[i] - 1.0


@pytest.mark.parametrize("scheme, order", [("implicit_euler", 1.0), ("bdf2", 2.0)])
def test_march_orders_in_the_step(scheme, order):
    """S7: the march kernel is first order (implicit Euler) and second order (BDF2) in the
    step; fitted slope +- 0.2 against a 64x finer march of the same scheme."""
    def run(n):
        t = np.arange(n) / n
        return implicit_march(quadratic_balance(t), t, 1.0, scheme, period=1.0,
                              cycles_max=30, period_tol=1e-13).y
    ns = np.array([40, 80, 160, 320])
    ref = run(20480)
    errs = [np.max(np.abs(run(n) - ref[:: 20480 // n])) for n in ns]
    slope = -np.polyfit(np.log(ns), np.log(errs), 1)[0]
    assert slope == pytest.approx(order, abs=0.2)


def test_level2_marches_agree_as_the_step_falls():
    """Euler and BDF2 level-2 films approach each other about linearly in the angle step on a
    cycle without reversal (their difference is the Euler error)."""
    diffs = []
    for n in (90, 180):
        theta, rho, u_e, load, b2, u_s = cam_cycle(n)
        u_e = np.abs(u_e) + 0.3
        films = [transient_film(theta, OMEGA, rho, u_e, load, b2, ROUGH,
                                FilmResolution(nodes=61, march=m), u_s=u_s).film
                 for m in ("implicit_euler", "bdf2")]
        diffs.append(np.max(np.abs(films[0] - films[1]) / films[1]))
    assert 1.6 < diffs[0] / diffs[1] < 2.6


def test_bad_options_are_named():
    with pytest.raises(ValueError, match="cavitation"):
        FilmProperties(viscosity=0.01, width=0.01, modulus=2e11, cavitation="elrod")
    with pytest.raises(ValueError, match="march"):
        FilmResolution(march="rk4")
    with pytest.raises(ValueError, match="nodes across the contact"):
        FilmResolution(nodes=3).grid()
