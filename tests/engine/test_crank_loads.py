"""Crank-train loads: derived identities and limits (Yang 1992 §1.2, Williams 2013 App. A5).

Every test here is exact up to round-off: identities between two forms of the same equation,
equilibrium of the statically determinate bays, frame invariants.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.camshaft import split_beam_loads
from camtrain.engine import (
    CrankComponent,
    Cylinder,
    Engine,
    crank_grid,
    cylinder_loads,
    main_loads,
    unbalance_from_weight_moment,
)
from camtrain.engine import crank as ck
from camtrain.errors import InputError

from .yang_engines import RUSTON_OMEGA, ruston_crank, ruston_engine, table

TH = crank_grid(4.0 * math.pi, math.radians(0.5))


@pytest.mark.parametrize("rod_ratio", [1.5, 3.0, 4.248, 10.0])
def test_yang_eq_1_2_equals_williams_exact_slider_crank(rod_ratio):
    """Yang eq. 1.2 (Shaw & Macks) is the exact acceleration: minus Williams' A5.4 x_ddot
    (x measured away from the crank), to round-off, even for a short rod."""
    R, w = 0.05, 300.0
    L = rod_ratio * R
    a = ck.piston_acceleration_yang(TH, R, L, w)
    _, _, xdd, psi, _ = ck.slider_crank_exact(TH, R, L, w)
    assert np.max(np.abs(a + xdd)) <= 1e-12 * R * w ** 2
    assert a[0] == pytest.approx(R * w ** 2 * (1.0 + R / L), rel=1e-14)
    np.testing.assert_allclose(psi, ck.rod_obliquity(TH, R, L), atol=1e-15)


def test_williams_a5_rates_are_derivatives():
    """A5.3 and A5.8 against central differences of A5.1 and A5.7 (O(h^2), h = 1e-5 rad)."""
    R, L, w, h = 0.18415, 0.78232, 62.8, 1e-5
    x0, xd, _, psi, pd = ck.slider_crank_exact(TH, R, L, w)
    xp, _, _, pp, _ = ck.slider_crank_exact(TH + h, R, L, w)
    xm, _, _, pm, _ = ck.slider_crank_exact(TH - h, R, L, w)
    np.testing.assert_allclose((xp - xm) / (2 * h) * w, xd, atol=1e-7 * R * w)
    np.testing.assert_allclose((pp - pm) / (2 * h) * w, pd, atol=1e-7 * w)


def test_pure_gas_load_lies_along_the_rod():
    """Massless piston and rod: the big-end load is the rod force alone, along the rod axis
    (x_r = 0) at every angle; at firing TDC it is the gas force, pointing to the small end."""
    crank = ruston_crank(piston_mass=0.0, rod_mass=0.0)
    p = table([50.0] + [1.0] * 71)
    ld = cylinder_loads(crank, p, 0.0, TH, RUSTON_OMEGA)
    assert np.max(np.abs(ld.load_x)) == 0.0
    assert ld.load_y[0] == pytest.approx(0.25 * math.pi * 0.26035 ** 2 * 50e5, rel=1e-14)
    # the force on the pin in block axes points down the cylinder at TDC
    assert ld.pin_x[0] == pytest.approx(0.0, abs=1e-9)
    assert ld.pin_y[0] == pytest.approx(-ld.load_y[0], rel=1e-14)


def test_rod_frame_is_a_rotation_and_side_thrust_balances_the_piston():
    ld = cylinder_loads(ruston_crank(), table([30.0] * 36 + [1.0] * 36), 0.0, TH, RUSTON_OMEGA)
    np.testing.assert_allclose(np.hypot(ld.pin_x, ld.pin_y), ld.load, rtol=1e-13)
    # piston in x: the rod pushes it with F_rod sin psi; the liner with -F_T (Yang eq. 1.5)
    np.testing.assert_allclose(ld.side_thrust, ld.rod_force * np.sin(ld.psi), rtol=1e-12,
                               atol=1e-9)
    # pin force = -(rod force along u) + rotating mass outward (block axes)
    frot = ck.rotating_force(81.62, 0.18415, RUSTON_OMEGA)
    ux, uy = np.sin(ld.psi), np.cos(ld.psi)
    np.testing.assert_allclose(ld.pin_x, -ld.rod_force * ux - frot * np.sin(TH), atol=1e-7)
    np.testing.assert_allclose(ld.pin_y, -ld.rod_force * uy + frot * np.cos(TH), atol=1e-7)


def test_rod_speed_forms():
    """Yang eq. 2.1 (small angle) and the exact swing agree at the dead centres and differ by
    the factor 1/cos psi elsewhere."""
    R, L, w = 0.18415, 0.78232, 62.8
    s = ck.rod_frame_journal_speed(TH, R, L, w, "small_angle")
    e = ck.rod_frame_journal_speed(TH, R, L, w, "exact")
    _, _, _, psi, pd = ck.slider_crank_exact(TH, R, L, w)
    np.testing.assert_allclose(e, w + pd, rtol=1e-14)
    assert s[0] == pytest.approx(e[0], rel=1e-15) and s[360] == pytest.approx(e[360], rel=1e-15)
    np.testing.assert_allclose(e - w, (s - w) / np.cos(psi), atol=1e-12)
    with pytest.raises(InputError, match="rod_speed"):
        ck.rod_frame_journal_speed(TH, R, L, w, "other")


def test_every_bay_balances_to_round_off():
    """Yang §1.2.2: each bay is a determinate beam. Forces and moments about the front main
    balance at every angle; the mains together carry every applied force."""
    eng = ruston_engine()
    cyl = [cylinder_loads(eng.crank, c.pressure, c.firing_angle, TH, RUSTON_OMEGA)
           for c in eng.cylinders]
    ml = main_loads(eng, cyl, RUSTON_OMEGA)
    scale = np.max(ml.load)
    for k, ell in enumerate(eng.bay_lengths):
        for j, applied, mom in ((0, ml.bay_x, ml.bay_moment_x), (1, ml.bay_y, ml.bay_moment_y)):
            assert np.max(np.abs(ml.front[k, j] + ml.rear[k, j] - applied[k])) <= 1e-12 * scale
            assert np.max(np.abs(ml.rear[k, j] * ell - mom[k])) <= 1e-12 * scale * ell
    assert np.max(np.abs(ml.load_x.sum(0) - ml.bay_x.sum(0))) <= 1e-11 * scale
    assert np.max(np.abs(ml.load_y.sum(0) - ml.bay_y.sum(0))) <= 1e-11 * scale


def test_bay_split_equals_the_camshaft_beam_splitter():
    """The crank bays and the camshaft's determinate-beam split (Ball §6.3) are the same rule."""
    eng = ruston_engine()
    cyl = [cylinder_loads(eng.crank, c.pressure, c.firing_angle, TH, RUSTON_OMEGA)
           for c in eng.cylinders]
    ml = main_loads(eng, cyl, RUSTON_OMEGA)
    zb = np.concatenate([[0.0], np.cumsum(eng.bay_lengths)])
    zf, fx, fy = [], [], []
    for c, ld in zip(eng.cylinders, cyl, strict=True):
        zf.append(zb[c.bay] + c.position)
        fx.append(ld.pin_x)
        fy.append(ld.pin_y)
    for comp in eng.components:
        zf.append(zb[comp.bay] + comp.position)
        f = comp.unbalance * RUSTON_OMEGA ** 2
        fx.append(-f * np.sin(TH + comp.angle))
        fy.append(f * np.cos(TH + comp.angle))
    bx, by = split_beam_loads(zb, zf, np.array(fx), np.array(fy))
    np.testing.assert_allclose(ml.load_x, bx, atol=1e-9 * np.max(ml.load))
    np.testing.assert_allclose(ml.load_y, by, atol=1e-9 * np.max(ml.load))


def test_out_of_balance_and_flywheel():
    """One crank component alone: C = (M_o/g) omega^2 turning with the crank (Yang §1.2.2),
    shared by the lever rule; a flywheel adds its weight to the last main only."""
    crank = ruston_crank(piston_mass=0.0, rod_mass=0.0)
    zero = table([0.0] * 72)
    mr = unbalance_from_weight_moment(100.0)
    eng = Engine(crank, (0.4, 0.4), (Cylinder(0, 0.2, 0.0, zero),),
                 (CrankComponent(1, 0.1, mr, math.radians(90.0)),), flywheel_mass=50.0)
    cyl = [cylinder_loads(crank, zero, 0.0, TH, 100.0)]
    ml = main_loads(eng, cyl, 100.0)
    c = 100.0 / 9.81 * 100.0 ** 2
    np.testing.assert_allclose(ml.load[0], 0.0, atol=1e-9)
    np.testing.assert_allclose(ml.load[1], 0.75 * c, rtol=1e-13)
    np.testing.assert_allclose(ml.load_x[2], 0.25 * c * -np.sin(TH + 0.5 * math.pi),
                               atol=1e-9 * c)
    np.testing.assert_allclose(ml.load_y[2], 0.25 * c * np.cos(TH + 0.5 * math.pi) - 50 * 9.81,
                               atol=1e-9 * c)


def test_pressure_tables_interpolate_through_the_rows_and_wrap():
    p = table([float(v) for v in np.sin(np.arange(72) / 5.0) + 2.0])
    rows = np.radians(np.arange(72) * 10.0)
    for how in ("periodic_cubic", "linear"):
        np.testing.assert_allclose(p(rows, how), np.asarray(p.pressure), rtol=1e-13)
        np.testing.assert_allclose(p(rows + 4 * math.pi, how), p(rows, how), rtol=1e-12)
    with pytest.raises(InputError, match="pressure_interpolation"):
        p(rows, "spline")


def test_two_stroke_fires_every_revolution():
    crank = ruston_crank(strokes=2)
    th = crank_grid(crank.cycle, math.radians(1.0))
    p = table([40.0] + [1.0] * 35)
    ld = cylinder_loads(crank, p, 0.0, th, RUSTON_OMEGA)
    assert th.size == 360 and ld.pressure[0] == pytest.approx(40e5)


@pytest.mark.parametrize("change, field", [(dict(rod_length=0.1), "engine.rod_length"),
                                           (dict(strokes=3), "engine.strokes"),
                                           (dict(bore=-1.0), "engine.bore")])
def test_bad_crank_data_name_the_field(change, field):
    with pytest.raises(InputError, match=field.replace(".", r"\.")):
        ruston_crank(**change)


def test_crank_step_must_divide_the_cycle():
    with pytest.raises(InputError, match="crank_step"):
        crank_grid(4.0 * math.pi, math.radians(0.7))
