"""Camshaft torque, harmonic orders, dampers and bearing-load split."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camtrain.camshaft import (
    bank_torque,
    bifilar_length,
    both_banks_amplitude,
    cam_grid,
    camshaft_torque,
    damper_motion,
    drive_power,
    harmonic_orders,
    idler_order,
    lobe_force,
    optimum_damper,
    pendulum_amplitude_ratio,
    pendulum_effective_inertia,
    pulley_load,
    second_bank,
    split_beam_loads,
    tuned_order,
)
from camtrain.errors import InputError

DEG = math.pi / 180.0
N = 1440  # 4 steps per camshaft degree = 1/2 crank degree timing (Williams App 7)
TH = cam_grid(N)

# Williams (2013) Tables 9.3 and 9.4: one-bank order amplitudes (N m), orders 4, 8, 12, 16.
T93 = {4: 12.57, 8: 35.53, 12: 18.74, 16: 11.04}
T94 = {4: 24.47, 8: 27.96, 12: 12.09, 16: 12.21}
# Tables 9.5-9.8: both banks.
T95 = {4: 3.50, 8: 68.30, 12: 15.24, 16: 18.73}
T96 = {8: 71.05, 16: 22.09}
T97 = {4: 6.82, 8: 53.76, 12: 9.84, 16: 20.70}
T98 = {8: 55.93, 16: 24.42}


def _bank_from_orders(amps, seed=1):
    """A bank torque with the tabulated order amplitudes and arbitrary phases (the single-valve
    torque curves of Williams ch 9 are printed only as figures)."""
    rng = np.random.default_rng(seed)
    return sum(a * np.cos(n * TH + rng.uniform(-math.pi, math.pi)) for n, a in amps.items())


@pytest.mark.parametrize("bank, v, table, small", [
    (T93, 82, T95, ()), (T93, 90, T96, (4, 12)), (T94, 82, T97, ()), (T94, 90, T98, (4, 12))])
def test_williams_tables_9_5_to_9_8_both_banks(bank, v, table, small):
    """Bank 2 = bank 1 advanced V/2 cam degrees, then FFT (Williams App 7, Tables 9.5-9.8).
    Tolerance 0.015 N m: the inputs are printed to 0.005 and doubled by 2|cos|, plus the
    output's own half digit. Orders printed '< 0.5' must come out below 0.5."""
    b1 = _bank_from_orders(bank)
    h = harmonic_orders(b1 + second_bank(b1, v * DEG))
    for n, a in table.items():
        assert h[n] == pytest.approx(a, abs=0.015)
    for n in small:
        assert h[n] < 0.5
    for n in (1, 2, 3, 5, 6, 7):
        assert h[n] < 0.5  # Table 9.1 note: orders other than multiples of 4 all < 0.5


def test_williams_table_9_10_damper_torque_extrema():
    """Table 9.10: an optimum 8th-order damper on both banks (V 90, 118/124 deg) has torque
    extrema +-71.05 N m = the Table 9.6 8th-order amplitude. The damped curve keeps only the
    other orders. (Extrema of the undamped curve need the printed-as-figure phases: not tested.)
    Tolerance: 1e-3 N m (grid sampling of a pure cosine at 1440 points)."""
    b1 = _bank_from_orders(T93)
    both = b1 + second_bank(b1, 90 * DEG)
    damper, damped = optimum_damper(both, [8])
    assert damper.max() == pytest.approx(71.05, abs=0.015)
    assert damper.min() == pytest.approx(-71.05, abs=0.015)
    assert np.max(damper) == pytest.approx(-np.min(damper), abs=1e-3)
    assert harmonic_orders(damped)[8] < 1e-9


@settings(max_examples=20, deadline=None)
@given(v=st.integers(30, 180), seed=st.integers(0, 10_000))
def test_v_bank_rule_holds_for_any_curve(v, seed):
    """Derived (docs/references/williams2013.md §2.14): |C_n, both| = 2 |cos(n V/4)| |C_n, bank| for any
    bank curve (V in whole crank degrees is a whole number of grid steps: exact to round-off)."""
    rng = np.random.default_rng(seed)
    b1 = rng.normal(size=N)
    h1 = harmonic_orders(b1)
    h2 = harmonic_orders(b1 + second_bank(b1, v * DEG))
    n = np.arange(1, 40)
    assert np.allclose(h2.amplitude[n], both_banks_amplitude(h1.amplitude[n], n, v * DEG),
                       atol=1e-9)


def test_bank_torque_timing_and_orders():
    """App 7 steps 1-3: the inlet peak moves to half its crank timing; four cylinders 90 cam
    deg apart keep only orders 4, 8, 12, ... ; two valves double the torque."""
    single = np.exp(-((np.angle(np.exp(1j * TH))) / (20 * DEG)) ** 2)  # bump at theta = 0
    single = single - single.mean()
    out = bank_torque(single, None, 4, 118 * DEG, 124 * DEG, valves_per_cylinder=2)
    one = bank_torque(single, None, 1, 118 * DEG, 124 * DEG, valves_per_cylinder=1)["inlet"]
    assert TH[np.argmax(one)] == pytest.approx(59 * DEG, abs=1e-9)
    h = harmonic_orders(out["bank"])
    non4 = [k for k in range(1, 60) if k % 4]
    assert np.max(h.amplitude[non4]) < 1e-9
    assert h[4] == pytest.approx(2 * 4 * harmonic_orders(single)[4], rel=1e-9)
    ex = bank_torque(None, single, 1, 0.0, 124 * DEG, valves_per_cylinder=1)["exhaust"]
    assert TH[np.argmax(ex)] == pytest.approx(2 * math.pi - 62 * DEG, abs=1e-9)


def test_zeta_lobe_phasing_and_drive_power():
    """Yang (1992) Appendix C.5 lobe angles 0/0/270/270/90/90/180/180 deg (firing 1-3-4-2):
    identical lobes give only orders that are multiples of 4; mean power = mean torque x omega."""
    lobe = np.sin(TH) * np.exp(-((np.angle(np.exp(1j * TH))) / (40 * DEG)) ** 2) + 0.01
    angles = np.array([0, 0, 270, 270, 90, 90, 180, 180]) * DEG
    total = camshaft_torque(lobe, angles)
    h = harmonic_orders(total)
    assert np.max(h.amplitude[[1, 2, 3, 5, 6, 7]]) < 1e-9
    p, mean = drive_power(total, 157.08)
    assert mean == pytest.approx(total.mean() * 157.08, rel=1e-12)
    assert h.mean == pytest.approx(total.mean(), rel=1e-12)


def test_pendulum_damper_formulas():
    """Williams eqs 10.52, 10.57, 10.59, 10.60, 10.64-10.66 and the derived identity
    beta = T / (N m Omega0^2 R (R + r)) (independent of detuning)."""
    R, r, m, n = 0.05, 0.05 / 66.0, 0.2, 8
    assert tuned_order(R, 0.05 / 64.0) == pytest.approx(8.0)
    ie = pendulum_effective_inertia(m, R, r, n)
    assert ie == pytest.approx(m * (R + r) ** 2 / (1 - 64 / 66), rel=1e-12)
    assert pendulum_amplitude_ratio(R, r, n) == pytest.approx((R + r) * 64 / (R - r * 64))
    lam, beta = damper_motion(71.05, 2, n, 300.0, m, R, r)
    assert beta == pytest.approx(71.05 / (2 * m * 300.0 ** 2 * R * (R + r)), rel=1e-12)
    assert pendulum_effective_inertia(m, R, 0.05 / 60.0, n) < 0  # worn: R/r < n^2
    assert bifilar_length(0.012, 0.010) == pytest.approx(0.002)
    assert idler_order(8, 30, 60) == pytest.approx(4.0)
    with pytest.raises(InputError):
        pendulum_effective_inertia(m, R, R / 64.0, 8)


ZB = np.array([0.0, 69.9, 161.7, 253.5, 345.3]) * 1e-3  # Yang C.5 bays 69.9 + 3 x 91.8 mm
ZC = np.array([50.4, 89.4, 142.2, 181.2, 234.0, 273.0, 325.8, 364.8]) * 1e-3


def test_beam_split_equilibrium_and_moments():
    """Statics: every mode keeps force balance; 'lever' also keeps moment balance about the
    shaft datum; 'nearest' puts an overhung cam (Yang's cam 8) and the pulley wholly on the end
    bearing (Ball §6.3, Yang Fig. 3.6)."""
    rng = np.random.default_rng(3)
    z = np.append(ZC, -30e-3)  # pulley ahead of bearing 1
    fx, fy = rng.normal(size=(9, 50)), rng.normal(size=(9, 50))
    for mode in ("nearest", "lever"):
        bx, by = split_beam_loads(ZB, z, fx, fy, overhang=mode)
        assert np.allclose(bx.sum(0), fx.sum(0)) and np.allclose(by.sum(0), fy.sum(0))
    bx, by = split_beam_loads(ZB, z, fx, fy, overhang="lever")
    assert np.allclose(ZB @ by, z @ fy) and np.allclose(ZB @ bx, z @ fx)
    one = np.eye(9)
    sx, _ = split_beam_loads(ZB, z, one, one, overhang="nearest")
    assert sx[4, 7] == 1.0 and sx[0, 8] == 1.0  # cam 8 -> B5, pulley -> B1
    assert sx[0, 0] == pytest.approx((69.9 - 50.4) / 69.9)
    # Ball's 3-bearing Pinto layout: centre = sum of its two bays
    s3, _ = split_beam_loads([0.0, 1.0, 2.0], [0.5, 1.5], np.eye(2), np.eye(2))
    assert np.allclose(s3, [[0.5, 0.0], [0.5, 0.5], [0.0, 0.5]])


def test_lobe_and_pulley_force():
    fx, fy = lobe_force(np.array([100.0]), np.array([8.0]), 0.5 * math.pi + 20 * DEG)
    assert math.hypot(fx[0], fy[0]) == pytest.approx(math.hypot(100.0, 8.0))
    # normal load pushes the cam away from the follower (follower above: force downwards)
    gx, gy = lobe_force(100.0, 0.0, 0.5 * math.pi)
    assert gy == pytest.approx(-100.0) and abs(gx) < 1e-12
    px, py = pulley_load(np.array([10.0, -10.0]), 0.05, math.pi, preload=0.0)
    assert np.allclose(px, -200.0) and np.allclose(py, 0.0, atol=1e-12)
