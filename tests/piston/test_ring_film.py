"""The film of one ring at one instant (Yang 1992 eqs. 5.15-5.31) against exact limits."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid, quad, trapezoid

from camtrain.piston.ring_film import face_integrals, ring_film


@pytest.mark.parametrize("a, c", [(0.1e-3, 1.2e-3), (0.0, 0.5e-3), (0.9e-3, 1.4e-3)])
def test_closed_form_integrals_match_quadrature(a, c):
    """Derived: the closed forms of eq. 5.22 equal adaptive quadrature to 1e-10."""
    h_m, x_c, R = 0.5e-6, 0.742e-3, 0.063
    f = face_integrals(a, c, h_m, x_c, R)
    h = lambda x: h_m + (x - x_c) ** 2 / (2 * R)  # noqa: E731
    for name, fn in [("h_1", lambda x: 1 / h(x)), ("h_2", lambda x: h(x) ** -2),
                     ("h_3", lambda x: h(x) ** -3), ("x_2", lambda x: x / h(x) ** 2),
                     ("x_3", lambda x: x / h(x) ** 3), ("xx_3", lambda x: x * x / h(x) ** 3)]:
        ref = quad(fn, a, c, epsabs=0, epsrel=1e-13, limit=400, points=[x_c])[0]
        assert getattr(f, name) == pytest.approx(ref, rel=1e-10), name


def test_martin_rigid_cylinder_limit():
    """Exact limit: a wide face with a stationary ring and the liner at u is a rigid cylinder
    rolling at the mean speed u/2; Martin (1916) with Reynolds' outlet gives
    h w / (eta (u/2) R) = 4.896 and rupture at 0.475 sqrt(2 R h) (wave2_models §2, 0.5 %)."""
    R, h, eta, u = 0.01, 1e-6, 0.01, 1.0
    s = math.sqrt(2 * R * h)
    f = ring_film(h, 0.0, u, eta, 0.0, 0.0, 2000 * s, 1000 * s, R)
    assert f.load * h / (eta * 0.5 * u * R) == pytest.approx(4.896, rel=5e-3)
    assert (f.x_rupture - 1000 * s) / s == pytest.approx(0.475, rel=5e-3)


def test_pure_squeeze_limit():
    """Exact limit: U = 0 and approach V: w = 3 sqrt(2) pi eta |V| (R/h)^(3/2) per unit length
    (wave2_models §2; 0.5 %)."""
    R, h, eta, V = 0.01, 1e-6, 0.01, -1e-4
    s = math.sqrt(2 * R * h)
    f = ring_film(h, V, 0.0, eta, 0.0, 0.0, 400 * s, 200 * s, R)
    assert f.load == pytest.approx(3 * math.sqrt(2) * math.pi * eta * abs(V) * (R / h) ** 1.5,
                                   rel=5e-3)
    assert not f.cavitated


def _numeric_load(h_m, V, u, eta, p_in, p_out, b, x_c, R, film, n=400001):
    """Rebuild the pressure of a film solution by trapezoidal integration of eq. 5.20."""
    x = np.linspace(0.0, b, n)
    h = h_m + (x - x_c) ** 2 / (2 * R)
    c1, c2 = 6 * eta * u, 12 * eta * V
    h2 = h_m + (film.x_rupture - x_c) ** 2 / (2 * R)
    c3 = -c1 * h2 - c2 * film.x_rupture
    a = x <= film.x_rupture
    p_a = p_in + cumulative_trapezoid((c1 * h[a] + c2 * x[a] + c3) / h[a] ** 3, x[a], initial=0)
    load = trapezoid(p_a, x[a])
    z = x >= film.x_reform
    if z.sum() > 1:
        p_b = cumulative_trapezoid(c1 * (h[z] - h2) / h[z] ** 3, x[z], initial=0)
        load += trapezoid(p_b, x[z])
        assert p_b[-1] == pytest.approx(p_out, rel=1e-4)
    assert p_a[-1] == pytest.approx(0.0, abs=1e-6 * max(p_in, 1e5))
    return load


@pytest.mark.parametrize("V, p_in, p_out", [(0.0, 0.0, 0.0), (0.0, 5e5, 6e6), (-1e-4, 5e5, 6e5),
                                             (1e-4, 5e5, 6e5)])
def test_cavitated_film_satisfies_its_boundary_conditions(V, p_in, p_out):
    """Derived: the rupture (p = dp/dx = 0) and reformation (p = p_out at the flank) lines of
    eqs. 5.22/5.26 rebuilt by quadrature, and the load of eq. 5.27, to 1e-5."""
    args = (0.5e-6, V, 10.0, 0.005, p_in, p_out, 1.484e-3, 0.742e-3, 0.063)
    film = ring_film(*args)
    assert film.cavitated and not film.fallback
    assert film.load == pytest.approx(_numeric_load(*args, film), rel=1e-5)


def test_a_rupture_next_to_a_zero_pressure_inlet_is_found():
    """Derived: the Zeta second ring on its downstroke just after TDC (minimum gap 0.089 mm from
    the crankcase flank at zero gauge, the gap opening): the pressure the short converging inlet
    builds falls to a rupture inside the first sixteenth of the face, where the rupture residual
    starts at p_in = 0. The rupture line is found (not the half-Sommerfeld fallback, whose
    outflow is that of a full film with negative pressures), its p = dp/dx = 0 and the load rebuilt
    by quadrature to 1e-5; and the state is continuous in h (the fallback flipped with h)."""
    b, x_c, R = 1.184e-3, 1.184e-3 - 1.0952e-3, 0.5
    for h, V, u in ((1.369e-8, 1.16e-5, 0.319), (1.693e-8, 3.52e-5, 0.956),
                    (2.286e-8, 5.95e-5, 1.590)):
        args = (h, V, u, 0.0055, 0.0, 0.0, b, x_c, R)
        film = ring_film(*args)
        assert film.cavitated and not film.fallback
        assert 0.0 < film.x_rupture < b / 16
        assert film.flow == pytest.approx(0.5 * u * (h + (film.x_rupture - x_c) ** 2 / (2 * R)))
        # the film fills 1/16 of the face: a finer quadrature grid
        assert film.load == pytest.approx(_numeric_load(*args, film, n=1600001), rel=1e-5)
        near = ring_film(h * (1 + 1e-6), *args[1:])
        assert near.flow == pytest.approx(film.flow, rel=1e-4)


def _starved_state(h, layer, p_in=2e5, p_out=6e6, u=5.0, V=0.0):
    """One starved instant of the Zeta top ring on the downstroke (the state kernel of the
    march; ``U < 0``: the inlet is the crankcase-side flank)."""
    from camtrain.piston import _ring_kernel as K

    b, R, x_min, T = 1.484e-3, 0.063, 0.742e-3, 0.2e6
    return K.state(h, V, -u, 0.005, p_out, p_in, layer, b, R, x_min, T, True), (b, x_min, T)


def _film_from_the_minimum_gap(h, p_in=2e5, p_out=6e6, u=5.0, V=0.0):
    from camtrain.piston import _ring_kernel as K

    return K.film(h, V, u, 0.005, p_in, p_out, 1.484e-3, 0.742e-3, 0.063, 0.742e-3, True, True)


def _threshold(h):
    """The layer whose flow a film with its inlet at the minimum gap draws exactly."""
    return _film_from_the_minimum_gap(h)[7] / 5.0


@pytest.mark.parametrize("h, fraction", [(1e-9, 0.5), (50e-9, 0.3), (0.5e-6, 0.9)])
def test_a_layer_too_thin_for_any_inlet_feeds_streamers_with_all_it_brings(h, fraction):
    """Derived (Yang eq. 5.34, §5.3.2.3): a layer thinner than even an inlet at the minimum gap
    draws cannot fill the conjunction; the film splits into streamers filling the fraction
    phi = supply / inflow of the circumference: the inlet draws exactly the layer's flow
    (continuity with equality), and the hydrodynamic load and shear are phi times the full
    film's, the gas past the rupture line unchanged."""
    u = 5.0
    layer = fraction * _threshold(h)
    ((load, shear, _, *_, inflow), _, _, gas), _ = _starved_state(h, layer)
    full = _film_from_the_minimum_gap(h)
    full_load, full_shear, full_gas = full[0], full[1], 6e6 * (1.484e-3 - full[3])
    assert inflow == pytest.approx(u * layer, rel=1e-12)
    assert gas == pytest.approx(full_gas, rel=1e-12)
    assert load - gas == pytest.approx(fraction * (full_load - full_gas), rel=1e-12)
    assert shear == pytest.approx(fraction * full_shear, rel=1e-12)


@pytest.mark.parametrize("h", [1e-9, 50e-9, 0.5e-6])
def test_the_starved_film_is_continuous_where_the_inlet_reaches_the_minimum_gap(h):
    """Derived: at the layer that an inlet at the minimum gap draws exactly, the streamers
    (phi -> 1) and the full film (inlet -> minimum gap) carry the same load and radial force, so
    the film march meets no jump there."""
    below, _ = _starved_state(h, _threshold(h) * (1 - 1e-7))
    above, _ = _starved_state(h, _threshold(h) * (1 + 1e-7))
    assert below[0][0] == pytest.approx(above[0][0], rel=1e-5)
    assert below[1] == pytest.approx(above[1], rel=1e-5)
def test_a_layer_thick_enough_forms_a_film_that_draws_no_more_than_it_brings():
    """Derived (Yang eq. 5.34): where an inlet position exists the starved film forms and its
    inlet draws no more than the layer brings; the film carries load."""
    h, u = 50e-9, 5.0
    for layer in (1.2 * _threshold(h), 2.0 * h, 10.0 * h):
        ((load, _, _, *_, inflow), _, _, gas), _ = _starved_state(h, layer)
        assert 0.0 < inflow <= u * layer * (1 + 1e-9)
        assert load - gas > 0.0
