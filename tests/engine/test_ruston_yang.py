"""Ruston 6VEB-X Mk III big-end against Yang (1992) §2.3, App. A (600 rpm, 15 cP).

Published values: h_min 4.91 um at 277 deg [Yang §2.3, stated]; Petroff power 270.2 W [derived
from App. A with eq. 1.19]; the parametric study (§2.5): b 0.04 / 0.08 m -> about 2.5 / 9.5 um,
a maximum of h_min near c = 20 um, Petroff exactly proportional to d^3, b, 1/c and eta.
Yang's program used half the printed mobility (reference notes §7): his printed films are
tested with ``mobility_scale = 0.5``; the physics as printed (1.0) is tested for the angle and
against the independent re-implementation of the reference notes (regression values [X]).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.bearings import bearing_orbit, bearing_petroff_power
from camtrain.engine import (
    YANG1992_MOBILITY_SCALE,
    crank_grid,
    cylinder_loads,
    main_loads,
    solve_engine_bearings,
)
from camtrain.engine.crank_bearings import SolverOptions

from .yang_engines import RUSTON_OMEGA, ruston_bearing, ruston_crank, ruston_engine, table
from .yang_engines import RUSTON_PRESSURE_BAR as ROWS

TH = crank_grid(4.0 * math.pi, math.radians(0.5))
PERIOD = 4.0 * math.pi


def _loads(interpolation="periodic_cubic", rod_speed="small_angle"):
    return cylinder_loads(ruston_crank(), table(ROWS), 0.0, TH, RUSTON_OMEGA,
                          interpolation=interpolation, rod_speed=rod_speed)


def _orbit(mobility="booker", scale=YANG1992_MOBILITY_SCALE, ld=None, **bearing):
    ld = ld if ld is not None else _loads()
    brg = ruston_bearing(**bearing).variants()["ungrooved"]
    return bearing_orbit(brg, ld.load_x, ld.load_y, TH, ld.omega_journal, 0.0,
                         angle_rate=RUSTON_OMEGA, period=PERIOD, film="2pi", mobility=mobility,
                         mobility_scale=scale, start="centre")


@pytest.fixture(scope="module")
def compat():
    return {m: _orbit(m) for m in ("booker", "exact")}


@pytest.fixture(scope="module")
def physical():
    return {m: _orbit(m, 1.0) for m in ("booker", "exact")}


@pytest.mark.parametrize("interpolation", ["periodic_cubic", "linear"])
def test_peak_big_end_load_207_kN_at_10_deg(interpolation):
    """207 kN at 10 deg [X, reference notes §0.4 / Yang Fig. 2.2 load diagram]: 1 %; the
    angle within 1 deg (the pressure rows are 10 deg apart; a cubic puts the peak at 10.5)."""
    ld = _loads(interpolation)
    i = int(np.argmax(ld.load))
    assert ld.load[i] == pytest.approx(207.2e3, rel=0.01)
    assert math.degrees(TH[i]) == pytest.approx(10.0, abs=1.0)


@pytest.mark.parametrize("mobility", ["booker", "exact"])
def test_min_film_4_91_um_at_277_deg_with_yang_factor(compat, mobility):
    """Yang §2.3: h_min = 4.91 um at 277 deg. With his program's factor: value 5 % (Booker
    4.99, exact 5.08 measured), angle 1 deg."""
    o = compat[mobility]
    assert o.min_film == pytest.approx(4.91e-6, rel=0.05)
    assert math.degrees(o.min_film_angle) == pytest.approx(277.0, abs=1.0)


@pytest.mark.parametrize("mobility, h_um", [("booker", 3.24), ("exact", 3.30)])
def test_min_film_physics_as_printed(physical, mobility, h_um):
    """Physics as printed: the angle of Yang's 277 deg within 3 deg [S]; the value is the
    reference notes' independent re-implementation [X: 3.24 / 3.30 um], 1 %."""
    o = physical[mobility]
    assert math.degrees(o.min_film_angle) == pytest.approx(277.0, abs=3.0)
    assert o.min_film == pytest.approx(h_um * 1e-6, rel=0.01)


def test_orbits_periodic_by_the_third_cycle(compat, physical):
    """Yang §2.2: the orbit closes within 6 pi of an 8 pi run. Here: periodic (change below
    period_tol = 1e-5) by cycle 3 from the centre, and |eps| < 1 throughout."""
    for o in (*compat.values(), *physical.values()):
        assert o.converged and o.cycles <= 3
        assert o.max_eccentricity < 1.0


def test_petroff_270_2_W():
    """App. A with Yang eq. 1.19 at the engine speed: 270.2 W (printed to 0.1 W)."""
    brg = ruston_bearing().variants()["ungrooved"]
    assert bearing_petroff_power(brg, RUSTON_OMEGA) == pytest.approx(270.2, rel=1e-3)


def test_petroff_exactly_proportional_to_d3_b_eta_and_inverse_c():
    """Yang §2.5: power is exactly cubic in d, linear in b and eta, hyperbolic in c (Petroff)."""
    base = bearing_petroff_power(ruston_bearing().variants()["ungrooved"], RUSTON_OMEGA)
    for field, k, power in (("diameter", 1.7, 3), ("length", 0.6, 1), ("viscosity", 2.3, 1),
                            ("clearance", 1.9, -1)):
        b0 = ruston_bearing()
        brg = ruston_bearing(**{field: getattr(b0, field) * k}).variants()["ungrooved"]
        assert bearing_petroff_power(brg, RUSTON_OMEGA) == pytest.approx(base * k ** power,
                                                                         rel=1e-13)


@pytest.mark.parametrize("length, h_um", [(0.04, 2.5), (0.08, 9.5)])
def test_length_study_with_yang_factor(length, h_um):
    """Yang §2.5: b = 0.04 m gives about 2.5 um and 0.08 m about 9.5 um ("+280 %"). Printed
    to 2 figures as "about": 10 % (X measured 2.57 / 9.37 um)."""
    assert _orbit(length=length).min_film == pytest.approx(h_um * 1e-6, rel=0.10)


def test_clearance_study_has_a_maximum_near_20_um():
    """Yang §2.5: h_min has a local maximum near c = 20 um (with his factor); the film rises
    from 12.4 to 20 um and falls from 20 to 40 um and on to the datum 82.55 um."""
    h = [_orbit(clearance=c * 1e-6).min_film for c in (12.4, 20.0, 40.0)]
    datum = _orbit().min_film
    assert h[1] > h[0] and h[1] > h[2] > datum


def test_yang_factor_is_the_doubled_viscosity():
    """Half the mobility is exactly twice the viscosity for the orbit (the mobility velocity
    is proportional to 1/eta): the compatibility option changes nothing else."""
    a = _orbit("booker", 0.5)
    b = _orbit("booker", 1.0, viscosity=0.030)
    np.testing.assert_allclose(a.eccentricity, b.eccentricity, atol=1e-6)


def test_whole_ruston_engine(tmp_path):
    """Six big-ends and seven mains at 600 rpm: the big-ends are one orbit shifted by the
    firing angles; big-end 2 pi / Petroff power between 1.5 and 2.6 (Yang §2.5 says 1.5-2.0
    with his factor; the physics as printed gives 2.5, reference notes E6); a main's 2 pi shear
    power exceeds Petroff (same speed, 1/sqrt(1 - eps^2) > 1)."""
    res = solve_engine_bearings(ruston_engine(), RUSTON_OMEGA, ruston_bearing(),
                                ruston_bearing(name="main"),
                                SolverOptions(mobility="booker", crank_step=math.radians(1.0)))
    assert len(res.big_ends) == 6 and len(res.mains) == 7
    h, ang = res.big_ends[1].min_film_dynamic
    h0, ang0 = res.big_ends[0].min_film_dynamic
    assert h == h0 and math.degrees(ang - ang0) % 720 == pytest.approx(120.0, abs=1e-9)
    for b in res.big_ends:
        assert 1.5 < b.power_dynamic / b.power_petroff < 2.6
    for b in res.mains:
        assert b.power_dynamic > b.power_petroff
    for b in res.bearings:
        assert b.variants["ungrooved"].dynamic.max_eccentricity < 1.0
    assert res.total("petroff") == pytest.approx(13 * 270.2, rel=1e-3)
    # mains 3 and 5 (and 2/6, 1/7) see the same loads half a cycle apart: one orbit each
    assert res.mains[4].variants["ungrooved"].dynamic.eccentricity[360] == \
        res.mains[2].variants["ungrooved"].dynamic.eccentricity[0]
    ml = main_loads(ruston_engine(), res.cylinders, RUSTON_OMEGA)
    np.testing.assert_array_equal(ml.load_x, res.mains_loads.load_x)
