"""Lift laws and bearings at their limits: a noisy lift table, exponents up to 80 and beyond, a
desmodromic closing cam, a journal bearing driven towards eps = 1."""
from __future__ import annotations

import math

import numpy as np
import pytest

from .conftest import DECKS, HARRISON, finite_columns, run_strict, variant

CHAIN = ("load", "hertz_pmax", "film_min", "friction_force", "power_loss")


def _polynomial(exponents, extra: str = "") -> str:
    start, end = HARRISON.index("[lift]"), HARRISON.index("[spring]")
    law = ('[lift]\nform = "polynomial"\n\n' + extra + "[lift.polynomial]\nhalf_period = 60.0\n"
           f"max_lift = 8.9\nexponents = {exponents}\n\n")
    return HARRISON[:start] + law + HARRISON[end:]


POLYDYNE = variant(_polynomial([2, 8, 14, 20, 26]), ("base_radius = 18.0", "base_radius = 25.0"))


def _noisy_table(noise_mm: float, seed: int = 1) -> str:
    """A polydyne lift (no ramps) sampled every degree to 4 decimals, with Gaussian noise on the
    lifted points, as a lift table."""
    base = run_strict(variant(POLYDYNE, ("angle_points = 1440", "angle_points = 360")))
    theta = np.degrees(base["cam_angle"])
    keep = np.abs(theta) <= 90
    lift = 1e3 * base["lift"][keep]
    lift = np.where(lift > 0, lift + np.random.default_rng(seed).normal(0, noise_mm, lift.size), 0)
    angles = ", ".join(f"{a:.1f}" for a in theta[keep])
    lifts = ", ".join(f"{max(x, 0.0):.4f}" for x in lift)
    start, end = POLYDYNE.index("[lift]"), POLYDYNE.index("[spring]")
    table = (f'[lift]\nform = "table"\n\n[lift.table]\nangles = [{angles}]\nlifts = [{lifts}]\n'
             f"noise = {max(noise_mm, 1e-4)}\n\n")
    return POLYDYNE[:start] + table + POLYDYNE[end:]


@pytest.mark.parametrize("noise", [0.0, 0.002])
def test_lift_table_with_measurement_noise(noise):
    """2 um noise on 9.4 mm of lift: the smoothing spline keeps the chain finite and the cycle
    loss within a few per cent of the exact law."""
    res = run_strict(_noisy_table(noise))
    finite_columns(res, CHAIN)
    exact = run_strict(POLYDYNE).metrics
    assert res.metrics["max_valve_lift"].value == pytest.approx(8.9e-3, abs=0.01e-3)
    assert res.metrics["power_loss_mean"].value == pytest.approx(
        exact["power_loss_mean"].value, rel=0.05)


@pytest.mark.parametrize("exponents", [[2, 40, 80], [2, 80, 200]])
def test_polynomial_with_high_exponents(exponents):
    """(phi/phi_T)^n for n up to 200 underflows gracefully towards the ends of the event."""
    ramps = "[lift.ramps]\nopening_height = 0.5\nopening_length = 25.0\n\n"
    res = run_strict(_polynomial(exponents, ramps))
    finite_columns(res, ("lift", "velocity", "acceleration", "jerk") + CHAIN)
    assert res.metrics["max_valve_lift"].value == pytest.approx(9.4e-3, rel=1e-9)


def test_desmodromic_closing_cam_stays_finite():
    res = run_strict((DECKS / "desmo_rig.toml").read_text(encoding="utf-8"))
    m = res.metrics
    for name in ("closing_max_valve_lift", "closing_cam_radius_min", "power_loss_mean",
                 "load_max"):
        assert math.isfinite(m[name].value), name
    assert m["closing_cam_radius_min"].value > 0


def test_journal_bearing_driven_towards_eps_1():
    """Loads up to 2000x the design load: the orbit approaches eps = 1 but never reaches it, the
    film stays positive and every output finite (numpy warnings raised as errors)."""
    from camtrain.bearings import EPS_LIMIT, JournalBearing, bearing_orbit

    brg = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
    omega = 1500 * 2 * math.pi / 60
    th = np.arange(36) * (2 * math.pi / 36)
    eps_max = []
    for load in (500.0, 5e4, 1e8):
        fx, fy = np.zeros(36), -load * (1.2 + np.cos(th))
        with np.errstate(all="raise"):
            o = bearing_orbit(brg, fx, fy, th, omega, max_cycles=60)
        assert o.converged and np.all(o.eccentricity < EPS_LIMIT)
        assert np.all(o.h_min > 0) and np.all(np.isfinite(o.power))
        eps_max.append(float(o.eccentricity.max()))
    assert eps_max[0] < eps_max[1] < eps_max[2] and eps_max[2] > 0.999


def test_bearing_orbit_converges_with_step_tolerance():
    """Peak eccentricity changes less and less as the march tolerance tightens."""
    from camtrain.bearings import JournalBearing, bearing_orbit

    brg = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
    th = np.arange(36) * (2 * math.pi / 36)
    fx, fy = np.zeros(36), -2000.0 * (1.2 + np.cos(th))
    e = [bearing_orbit(brg, fx, fy, th, 157.0, tol=tol, period_tol=1e-8, max_cycles=80)
         .eccentricity.max() for tol in (1e-4, 1e-6, 1e-8, 1e-10)]
    d = np.abs(np.diff(e))
    assert d[-1] <= d[0] and d[-1] < 1e-6
