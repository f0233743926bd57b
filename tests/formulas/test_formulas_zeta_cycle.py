"""Formula chain over a whole cam cycle: Yang (1992) Ford Zeta intake cam and domed follower.

Reproduces Yang's printed frictional power (Fig. 4.2 header, 39.68 W per cam at 1500 rev/min
camshaft) from the formula layer alone: Hertz (``method="yang_1992"``), Chittenden et al.
central film, the closed-form Barus shear over the ellipse capped at mu = 0.08, and the cycle
mean of F (R_b + L) omega. The kinematics of a domed follower on the cam (Dyson & Naylor via
Yang eqs. 3.1-3.5) are written out here as test scaffolding only; the valve-train mechanisms
are implemented elsewhere in camtrain.
"""
from __future__ import annotations

import numpy as np
import pytest

import camtrain.formulas as cf

# Intake cam lift [mm] at 1 deg steps from -74 to +79 deg (cam angle from maximum lift); zero
# elsewhere. Yang (1992) Appendix C, as extracted (docs/references/yang1992.md §3.4).
LIFT_MM = np.array([
    0.000015, 0.000851, 0.002930, 0.006672, 0.012321, 0.019917, 0.029295, 0.040101, 0.051829,
    0.063875, 0.075922, 0.087969, 0.100015, 0.118955, 0.165468, 0.239553, 0.341211, 0.470441,
    0.626830, 0.808173, 1.010057, 1.225866, 1.446775, 1.667685, 1.888594, 2.109503, 2.330413,
    2.551322, 2.772232, 2.993142, 3.214051, 3.434961, 3.655870, 3.876780, 4.097690, 4.318525,
    4.538776, 4.757887, 4.975325, 5.190589, 5.403203, 5.612720, 5.818719, 6.020808, 6.218621,
    6.411822, 6.600101, 6.783175, 6.960788, 7.132715, 7.298756, 7.458737, 7.612514, 7.759972,
    7.901018, 8.035587, 8.163620, 8.285059, 8.399850, 8.507941, 8.609285, 8.703838, 8.791556,
    8.872401, 8.946338, 9.013331, 9.073353, 9.126377, 9.172379, 9.211337, 9.243237, 9.268063,
    9.285803, 9.296450, 9.300000, 9.296453, 9.285814, 9.268088, 9.243282, 9.211408, 9.172479,
    9.126513, 9.073530, 9.013554, 8.946611, 8.872732, 8.791949, 8.704298, 8.609818, 8.508552,
    8.400542, 8.285839, 8.164493, 8.036557, 7.902089, 7.761152, 7.613831, 7.460234, 7.300496,
    7.134778, 6.963263, 6.786163, 6.603713, 6.416173, 6.223829, 6.026991, 5.825997, 5.621207,
    5.413007, 5.201810, 4.988053, 4.772197, 4.554729, 4.336163, 4.117035, 3.897836, 3.678637,
    3.459439, 3.240240, 3.021041, 2.801842, 2.582644, 2.363445, 2.144246, 1.925048, 1.705849,
    1.486650, 1.267451, 1.053311, 0.852981, 0.673025, 0.517818, 0.389547, 0.288623, 0.215046,
    0.168816, 0.149932, 0.137886, 0.125839, 0.113792, 0.101745, 0.089699, 0.077652, 0.065605,
    0.053558, 0.041812, 0.030938, 0.021419, 0.013605, 0.007672, 0.003611, 0.001224, 0.000146,
    0.000019,
])
THETA_DEG = np.arange(-180, 180)
OMEGA = 1500 * np.pi / 30
RB, RF = 0.018, 8.0
E_R = cf.reduced_modulus(170e9, 0.28, 204e9, 0.29)
# Fig. 4.2 header values (rounded as printed there)
ETA, ALPHA, K_S, DELTA, M_EQ, W_BASE = 0.010, 22e-9, 37634.0, 5.6e-3, 0.118, 64.251


def _cycle(hertz_method="yang_1992"):
    lift = np.zeros(THETA_DEG.size)
    lift[(THETA_DEG >= -74) & (THETA_DEG <= 79)] = LIFT_MM * 1e-3
    d = np.radians(1.0)  # periodic central differences, as the seed's data-point option
    l1 = (np.roll(lift, -1) - np.roll(lift, 1)) / (2 * d)
    l2 = (np.roll(lift, -1) - 2 * lift + np.roll(lift, 1)) / d**2
    Z, Zp, Zpp = lift + RB + RF, l1, l2
    q = Z**2 + 2 * Zp**2 - Z * Zpp
    r_cam = (Z**2 + Zp**2) ** 1.5 / q - RF  # Yang eq. 3.1
    v_c = OMEGA * (np.sqrt(Z**2 + Zp**2) - RF * q / (Z**2 + Zp**2))  # eq. 3.2
    v_f = OMEGA * RF * (Z * Zpp - Zp**2) / (Z**2 + Zp**2)  # eq. 3.3
    f_v = M_EQ * OMEGA**2 * l2 + K_S * (lift + DELTA)  # eqs. 3.6-3.8
    taper = np.tan(np.radians(1 / 60))
    W = np.where(lift > 0, f_v * np.sqrt(1 + (Zp / Z) ** 2 + taper**2), W_BASE)  # eq. 3.11
    Rx = cf.reduced_radius(r_cam, RF)
    hz = cf.hertz_point(W, Rx, RF, E_R, method=hertz_method)
    u_e = cf.entrainment_speed(v_c, v_f)
    h_c = cf.chittenden_1985_cen(W, Rx, RF, u_e, ETA, ALPHA, E_R)
    F = cf.yang_1992_friction(cf.sliding_speed(v_c, v_f), h_c, ETA, ALPHA, hz.max_pressure,
                              hz.a_x, hz.a_y, W)
    power = cf.friction_power(F, RB + lift, OMEGA)
    torque = cf.cam_torque(np.where(lift > 0, f_v, 0.0), l1, F, RB + lift)
    return dict(F=F, W=W, power=power, torque=torque, u_e=u_e, l1=l1)


def test_zeta_cam_friction_power():
    """Yang (1992) Fig. 4.2 header: frictional power loss 39.68 W per intake cam at 1500 rev/min
    camshaft. Tolerance +-2 %: the seed's exact differentiation and input rounding are unknown;
    the independent reproduction of docs/references/yang1992.md §4.6 spans 39.44-40.06 W over such variants
    (§4.6). With exact Hertz instead of Yang's k = r^(2/3) fit the same chain gives ~42.0 W, so
    the option matters and is named."""
    cyc = _cycle()
    assert cf.cycle_mean(cyc["power"]) == pytest.approx(39.68, rel=0.02)
    assert cf.cycle_mean(cyc["power"]) == pytest.approx(39.93, abs=0.01)  # docs/references/yang1992.md §4.6
    assert cf.cycle_mean(_cycle("exact")["power"]) == pytest.approx(42.0, rel=0.01)


def test_zeta_cycle_features():
    """Yang (1992) §4.2.1 as reproduced in the docs/references/yang1992.md §4.6: boundary (capped) region
    -39..+39 deg (seed: nose -40..+40); V_e = 0 between 32 and 33 deg on each side of the nose
    ("zero film points"); the total cam torque changes sign between +5 and +6 deg."""
    cyc = _cycle()
    capped = np.isclose(cyc["F"], 0.08 * cyc["W"], rtol=1e-12)
    assert THETA_DEG[capped].min() == -39 and THETA_DEG[capped].max() == 39
    for lo, hi in ((-33, -32), (32, 33)):
        i, j = np.flatnonzero(THETA_DEG == lo)[0], np.flatnonzero(THETA_DEG == hi)[0]
        assert cyc["u_e"][i] * cyc["u_e"][j] < 0
    t = cyc["torque"]
    i5, i6 = np.flatnonzero(THETA_DEG == 5)[0], np.flatnonzero(THETA_DEG == 6)[0]
    assert t[i5] > 0 > t[i6]


def test_zeta_guide_friction(printed):
    """Yang (1992) §4.2.3 full-film guide friction (eq. 3.29), intake lift at 1500 rev/min,
    eta = 0.009865 Pa s: 0.606 W per follower (d 28.4 mm, guide 22 mm, c 24 um) and 0.253 W
    per valve (stem 6.043 mm, guide 36 mm, c 20 um), docs/references/yang1992.md §4.6 (printed precision).
    Seed totals for 8 (Yang Fig. 4.7): 4.9 W and 2.0 W; the follower total comes out 4.85 W,
    1 % below the printed 4.9 W (the seed's differentiation of the lift is not known), so the
    totals are checked to 1.5 %."""
    V = OMEGA * _cycle()["l1"]
    follower = cf.cycle_mean(cf.couette_guide_power(V, 0.009865, 28.4e-3, 22e-3, 24e-6))
    valve = cf.cycle_mean(cf.couette_guide_power(V, 0.009865, 6.043e-3, 36e-3, 20e-6))
    printed(follower, "0.606")
    printed(valve, "0.253")
    assert 8 * follower == pytest.approx(4.9, rel=0.015)
    assert 8 * valve == pytest.approx(2.0, rel=0.015)
