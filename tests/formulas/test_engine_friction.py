"""Engine friction correlations, term by term against hand calculations from the equations in
their own units (mm, rev/min, m/s, kPa) (derived tier: the same equations, computed by hand here,
to 1e-9). Engine: B = 86, S = 90 mm, five 55 x 20 mm mains, 48 x 18 mm rod bearings, four
cylinders, 16 valves, 10 camshaft bearings, 8.5 mm lift, r_c = 10, at 3000 rev/min, oil 12 cSt.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.engine.correlations import (
    MODELS,
    ChenFlynnConstants,
    CorrelationEngine,
    OperatingPoint,
    chen_flynn_fmep,
    correlation_terms,
    fmep_to_power,
)
from camtrain.errors import InputError
from camtrain.formulas import engine_friction as ef
from camtrain.formulas.fmep import patton_nitschke_heywood_1989

pytestmark = pytest.mark.derived

RPM = 3000.0
W = RPM * 2 * math.pi / 60          # rad/s
B, S = 86.0, 90.0                   # mm
DB, LB, NB = 55.0, 20.0, 5
DR, LR = 48.0, 18.0
NC, NV, NCAM, LV, RC = 4, 16, 10, 8.5, 10.0
NU = 12.0                           # cSt
R = math.sqrt(NU / 10.6)
SP = 2 * S / 1000 * RPM / 60        # m/s
MM = 1e-3
TOL = 1e-9


def kpa(value):
    return value * 1e3


def test_crankshaft_terms_by_hand():
    assert ef.crankshaft_seals(B * MM, S * MM, DB * MM, NC) == pytest.approx(
        kpa(1.22e5 * DB / (B**2 * S * NC)), rel=TOL)
    assert ef.main_bearings(W, B * MM, S * MM, DB * MM, LB * MM, NB, NC, R) == pytest.approx(
        kpa(3.03e-4 * R * RPM * DB**3 * LB * NB / (B**2 * S * NC)), rel=TOL)
    assert ef.turbulent_dissipation(W, DB * MM, NB, NC) == pytest.approx(
        kpa(1.35e-10 * DB**2 * RPM**2 * NB / NC), rel=TOL)


def test_reciprocating_terms_by_hand():
    assert ef.mean_piston_speed(S * MM, W) == pytest.approx(9.0, rel=TOL)
    assert ef.piston_skirt(W, B * MM, S * MM, R) == pytest.approx(kpa(2.94e2 * R * SP / B),
                                                                  rel=TOL)
    for n0 in (1000.0, 500.0):
        assert ef.piston_rings(W, B * MM, n0) == pytest.approx(
            kpa(4.06e4 * (1 + n0 / RPM) / B**2), rel=TOL)
    assert ef.rod_bearings(W, B * MM, S * MM, DR * MM, LR * MM, R) == pytest.approx(
        kpa(3.03e-4 * R * RPM * DR**3 * LR / (B**2 * S)), rel=TOL)
    pi_pa = 0.6
    assert ef.ring_gas_loading(W, S * MM, pi_pa, RC, R) == pytest.approx(
        kpa(6.89 * pi_pa * (0.088 * R * RC + 0.182 * RC ** (1.33 - 2.38e-2 * SP))), rel=TOL)


@pytest.mark.parametrize("layout", sorted(ef.VALVE_TRAIN_CONSTANTS))
def test_valve_train_terms_by_hand(layout):
    c_ff, c_rf, c_oh, c_om = ef.VALVE_TRAIN_CONSTANTS[layout]
    assert ef.camshaft_bearings(W, B * MM, S * MM, NCAM, NC, R) == pytest.approx(
        kpa(244 * R * RPM * NCAM / (B**2 * S * NC)), rel=TOL)
    assert ef.valve_train_constant() == pytest.approx(kpa(4.12), rel=TOL)
    assert ef.flat_follower(W, S * MM, NV, NC, layout, 500.0) == pytest.approx(
        kpa(c_ff * (1 + 500 / RPM) * NV / (S * NC)), rel=TOL)
    if c_rf is not None:
        assert ef.roller_follower(W, S * MM, NV, NC, layout) == pytest.approx(
            kpa(c_rf * RPM * NV / (S * NC)), rel=TOL)
    assert ef.oscillating_hydrodynamic(W, B * MM, S * MM, LV * MM, NV, NC, layout, R) == \
        pytest.approx(kpa(c_oh * R * LV**1.5 * RPM**0.5 * NV / (B * S * NC)), rel=TOL)
    assert ef.oscillating_mixed(W, S * MM, LV * MM, NV, NC, layout, 1000.0) == pytest.approx(
        kpa(c_om * (1 + 1000 / RPM) * LV * NV / (S * NC)), rel=TOL)


def test_auxiliaries_and_boundary_factor_by_hand():
    assert ef.auxiliaries(W) == pytest.approx(kpa(6.23 + 5.22e-3 * RPM - 1.79e-7 * RPM**2),
                                              rel=TOL)
    assert ef.boundary_factor(W, 500.0) == pytest.approx(1 + 500 / 3000, rel=TOL)
    assert ef.viscosity_ratio(NU * 1e-6) == pytest.approx(R, rel=TOL)


def test_oil_grade_vogel_by_hand():
    k, th1, th2, hs = ef.OIL_GRADES["10W30"]
    assert ef.oil_grade_viscosity("10W30", 90.0) == pytest.approx(
        k * math.exp(th1 / (90 + th2)) * 1e-6, rel=TOL)
    assert ef.oil_grade_viscosity("10W30", 90.0, high_shear=True) == pytest.approx(
        hs * k * math.exp(th1 / (90 + th2)) * 1e-6, rel=TOL)
    # every grade thins with temperature, and a 40/100 °C pair in the range of its SAE class
    for grade in ef.OIL_GRADES:
        nu = ef.oil_grade_viscosity(grade, np.array([40.0, 100.0])) * 1e6
        assert nu[0] > nu[1] > 3.0


def test_chen_flynn_is_its_four_terms():
    c = ChenFlynnConstants(0.137e5, 0.005, 0.162e5, 0.002e5)
    eng = _engine("flat")
    p = 60e5
    assert chen_flynn_fmep(c, eng, W, p) == pytest.approx(
        0.137e5 + 0.005 * p + 0.162e5 * SP + 0.002e5 * SP**2, rel=TOL)


def _engine(follower, layout="dohc_direct"):
    return CorrelationEngine(B * MM, S * MM, NC, NB, DB * MM, LB * MM, DR * MM, LR * MM, layout,
                             follower, NV, NCAM, LV * MM, RC)


def test_model_totals_are_the_sum_of_the_hand_terms():
    """PNH: r = 1 and N_0 = 1000; Sandoval-Heywood: r = sqrt(nu/nu_0) and N_0 = 500."""
    op = OperatingPoint(W, 0.8, NU * 1e-6)
    for name, r, n0 in (("pnh1989", 1.0, 1000.0), ("sandoval_heywood2003", R, 500.0)):
        terms = correlation_terms(MODELS[name], _engine("flat"), op)
        c_ff, _, c_oh, c_om = ef.VALVE_TRAIN_CONSTANTS["dohc_direct"]
        hand = (1.22e5 * DB / (B**2 * S * NC) + 3.03e-4 * r * RPM * DB**3 * LB * NB
                / (B**2 * S * NC) + 1.35e-10 * DB**2 * RPM**2 * NB / NC
                + 2.94e2 * r * SP / B + 4.06e4 * (1 + n0 / RPM) / B**2
                + 6.89 * 0.8 * (0.088 * r * RC + 0.182 * RC ** (1.33 - 2.38e-2 * SP))
                + 3.03e-4 * r * RPM * DR**3 * LR / (B**2 * S)
                + 244 * r * RPM * NCAM / (B**2 * S * NC) + 4.12
                + c_ff * (1 + n0 / RPM) * NV / (S * NC)
                + c_oh * r * LV**1.5 * RPM**0.5 * NV / (B * S * NC)
                + c_om * (1 + n0 / RPM) * LV * NV / (S * NC)
                + 6.23 + 5.22e-3 * RPM - 1.79e-7 * RPM**2)
        assert sum(terms.values()) == pytest.approx(kpa(hand), rel=TOL)


def test_pnh_valve_train_group_equals_the_existing_valve_train_formula():
    """The valve-train terms of PNH 1989 summed are the one-function valve-train fmep."""
    op = OperatingPoint(W, 1.0, NU * 1e-6)
    for follower in ("flat", "roller"):
        terms = correlation_terms(MODELS["pnh1989"], _engine(follower), op)
        vt = sum(v for k, v in terms.items() if k in (
            "camshaft_bearings", "valve_train_constant", "follower",
            "oscillating_hydrodynamic", "oscillating_mixed"))
        assert vt == pytest.approx(patton_nitschke_heywood_1989(
            W, B * MM, S * MM, LV * MM, NC, NCAM, NV, "dohc_direct", follower), rel=TOL)


def test_power_of_an_fmep_is_fmep_times_swept_volume_per_cycle():
    eng = _engine("flat")
    vd = NC * math.pi / 4 * (B * MM) ** 2 * S * MM
    assert eng.displacement == pytest.approx(vd, rel=TOL)
    assert fmep_to_power(100e3, vd, W) == pytest.approx(100e3 * vd * RPM / 60 / 2, rel=TOL)


def test_ohv_roller_has_no_constant_and_unknown_names_are_refused():
    with pytest.raises(InputError, match="roller"):
        ef.roller_follower(W, S * MM, NV, NC, "ohv")
    with pytest.raises(InputError, match="layout"):
        ef.flat_follower(W, S * MM, NV, NC, "cvt", 500.0)
    with pytest.raises(InputError, match="grade"):
        ef.oil_grade_viscosity("0W16", 90.0)


def test_terms_vectorise_over_speed():
    speeds = np.array([1000.0, 3000.0, 6000.0]) * 2 * math.pi / 60
    terms = correlation_terms(MODELS["sandoval_heywood2003"], _engine("flat"),
                              OperatingPoint(speeds, 1.0, NU * 1e-6))
    for name, value in terms.items():
        assert np.shape(value) == (3,), name
        one = correlation_terms(MODELS["sandoval_heywood2003"], _engine("flat"),
                                OperatingPoint(speeds[1], 1.0, NU * 1e-6))[name]
        assert value[1] == pytest.approx(one, rel=TOL)


@pytest.mark.parametrize("rpm,printed", [(1000, "25.61"), (2000, "21.56"), (4000, "21.05"),
                                         (6000, "22.21")])
def test_pnh_valve_train_group_gives_the_documented_worked_engine(rpm, printed):
    """The reference notes' worked valve train (derived there from the same equations, not a
    published measurement): 4 cylinders, DOHC direct-acting, flat, B = S = 86 mm, 10 camshaft
    bearings, 16 valves, L_v = 8 mm; printed to 0.01 kPa."""
    eng = CorrelationEngine(0.086, 0.086, 4, 5, 0.05, 0.02, 0.045, 0.02, "dohc_direct", "flat",
                            16, 10, 0.008, 10.0)
    terms = correlation_terms(MODELS["pnh1989"], eng, OperatingPoint(rpm * 2 * math.pi / 60))
    vt = sum(terms[k] for k in ("camshaft_bearings", "valve_train_constant", "follower",
                                "oscillating_hydrodynamic", "oscillating_mixed"))
    assert f"{vt / 1e3:.2f}" == printed
