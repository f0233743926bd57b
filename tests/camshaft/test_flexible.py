"""Elastic camshaft (Teodorescu et al. 2005 §2.6, §4): named bearing splits as limits of the
elastic shaft, the camstar, beam checks against closed forms, orders and torsion.

The lobe loads are a synthetic smooth valve-train load (a preload plus a lift event and an
inertia dip) on the Zeta intake layout of Yang (1992) App C.5; the identities tested do not
depend on its shape."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.camshaft import harmonic_orders, lobe_force, shift_curve, split_beam_loads
from camtrain.camshaft.flexible import ShaftSection, beam_shaft, stations, torsion_shaft
from camtrain.camshaft.flexible_response import (
    PendulumDamper,
    bearing_split,
    bending_response,
    camstar,
    drive_acceleration,
    torsion_response,
)

N = 360
THETA = np.arange(N) * 2 * np.pi / N
OMEGA = 1500.0 * np.pi / 30.0
# Yang App C.5: bearings, cams (8 intake cams, cam 8 overhanging bearing 5), phases, axis 70 deg
BEARINGS = np.array([0.0, 69.9, 161.7, 253.5, 345.3]) * 1e-3
LOBES = np.array([50.4, 89.4, 142.2, 181.2, 234.0, 273.0, 325.8, 364.8]) * 1e-3
PHASES = np.radians([0, 0, 270, 270, 90, 90, 180, 180])
AXIS = math.radians(70.0)
SECTION = ShaftSection.solid(25.0e-3)


def train_load(theta=THETA):
    """Smooth contact load [N] with maximum lift at theta = 0: preload, spring, inertia dip."""
    x = np.angle(np.exp(1j * theta)) / math.radians(60.0)
    event = np.where(np.abs(x) < 1, np.cos(0.5 * np.pi * x) ** 4, 0.0)
    dip = np.where(np.abs(x) < 1, np.cos(0.5 * np.pi * x) ** 6 * (1 - 3 * x * x), 0.0)
    return 250.0 + 300.0 * event - 150.0 * dip


def train_torque(theta=THETA):
    """Lobe torque W e with e = dlift/dtheta of the same event shape [N m]."""
    x = np.angle(np.exp(1j * theta)) / math.radians(60.0)
    de = np.where(np.abs(x) < 1, -np.sin(np.pi * x), 0.0)
    return train_load(theta) * 4e-3 * de


def lobe_forces():
    w = train_load()
    f = [lobe_force(shift_curve(w, g), 0.0, AXIS) for g in PHASES]
    return np.array([a for a, _ in f]), np.array([b for _, b in f])


def zeta_shaft(scale=1.0, nodes=1, damping=0.02):
    st = stations(BEARINGS, LOBES, nodes)
    kb = np.array([4e8, 2e8, 2e8, 2e8, 4e8]) * scale
    sec = ShaftSection(SECTION.EI * scale, SECTION.GJ * scale, SECTION.mass_per_length,
                       SECTION.polar_inertia_per_length)
    masses = np.zeros(st.positions.size)
    masses[st.force_nodes] = 0.15  # lobe mass [kg], assumed
    return beam_shaft(st, sec, kb, 200.0, damping, masses)


def test_camstar_in_line_four():
    """Teodorescu Sec. 4, Fig. 11: |sum exp(i k gamma)| = 4 if 4 | k else 0 (1e-12)."""
    k = np.arange(0, 41)
    c = camstar(np.radians([0, 90, 270, 180]), k)
    expected = np.where(k % 4 == 0, 4.0, 0.0)
    assert np.max(np.abs(c - expected)) < 1e-12


def test_rigid_shaft_summed_load_has_only_multiples_of_four():
    """R7': four identical trains on a rigid shaft, summed load: orders other than 4k below
    1e-6 of order 4 (the phases fall on whole grid steps, so the shifts are exact)."""
    w = train_load()
    total = sum(shift_curve(w, g) for g in np.radians([0, 90, 270, 180]))
    amp = harmonic_orders(total).amplitude
    off = [amp[k] for k in range(1, 60) if k % 4]
    assert max(off) < 1e-6 * amp[4]
    assert amp[4] > 1.0


@pytest.mark.parametrize("overhang", ["nearest", "lever"])
def test_determinate_split_is_todays_bearing_loads(overhang):
    """The hinged shaft on rigid supports gives the statically determinate split of the
    bearings effect (Ball 1988 §6.3; Yang Fig. 3.6) to 1e-10 of the largest load; a pulley
    load in front of bearing 1 and a force exactly on bearing 3 included."""
    fx, fy = lobe_forces()
    pos = np.concatenate([LOBES, [-0.04, BEARINGS[2]]])
    fx = np.vstack([fx, 300 * np.cos(THETA), 50 + 0 * THETA])
    fy = np.vstack([fy, 200 + 0 * THETA, -80 * np.sin(2 * THETA)])
    got = bearing_split("determinate", BEARINGS, pos, fx, fy, overhang)
    ref_x, ref_y = split_beam_loads(BEARINGS, pos, fx, fy, overhang)
    scale = np.max(np.abs(fy))
    assert np.max(np.abs(got.bearing_x - ref_x)) < 1e-10 * scale
    assert np.max(np.abs(got.bearing_y - ref_y)) < 1e-10 * scale


def test_equal_share_each_bearing_carries_a_fifth():
    """Teodorescu's rigid result (R8): each of 5 bearings carries sum(F)/5 to round-off."""
    fx, fy = lobe_forces()
    got = bearing_split("equal_share", BEARINGS, LOBES, fx, fy)
    for j in range(5):
        assert np.allclose(got.bearing_y[j], fy.sum(axis=0) / 5, rtol=1e-14, atol=1e-12)
        assert np.allclose(got.bearing_x[j], fx.sum(axis=0) / 5, rtol=1e-14, atol=1e-12)


def test_continuous_beam_on_three_rigid_supports():
    """Two equal spans L, load P at the middle of the first: reactions 13/32, 22/32, -3/32 P
    (standard continuous-beam result, three-moment equation)."""
    st = stations([0.0, 1.0, 2.0], [0.5])
    shaft = beam_shaft(st, SECTION, math.inf)
    r = bending_response(shaft, [[0.0]], [[32.0]], quasi_static=True)
    assert np.allclose(r.bearing_y[:, 0], [13.0, 22.0, -3.0], rtol=0, atol=1e-10)


def test_elastic_statics_balance_the_forces():
    """Quasi-static elastic shaft on springs: the bearing loads sum to the applied forces."""
    fx, fy = lobe_forces()
    r = bending_response(zeta_shaft(), fx, fy, quasi_static=True)
    assert np.allclose(r.bearing_y.sum(axis=0), fy.sum(axis=0), rtol=1e-10)
    assert np.allclose(r.bearing_x.sum(axis=0), fx.sum(axis=0), rtol=1e-10)


def test_beam_frequency_converges_at_fourth_order():
    """Simply supported shaft: f1 = (pi/L)^2 sqrt(EI/m) / (2 pi); the Hermite element with
    consistent mass converges as h^4 (observed order fitted over three refinements)."""
    L = 0.35
    exact = (math.pi / L) ** 2 * math.sqrt(SECTION.EI / SECTION.mass_per_length)
    errs, hs = [], []
    for extra in (1, 3, 7):
        shaft = beam_shaft(stations([0.0, L], [], extra), SECTION, math.inf)
        errs.append(shaft.natural_frequencies()[0] / exact - 1.0)
        hs.append(L / (extra + 1))
    order = np.polyfit(np.log(hs), np.log(np.abs(errs)), 1)[0]
    assert 3.7 < order < 4.3
    assert all(e > 0 for e in errs)  # a consistent-mass model bounds the frequency from above


def test_elastic_shaft_brings_odd_orders_to_the_centre_bearing():
    """R9: with equal share bearing 3 sees only orders 4k; on the elastic shaft (Zeta layout,
    asymmetric bays and the overhanging cam) the odd orders appear above 1e-3 of order 4."""
    fx, fy = lobe_forces()
    rigid = bearing_split("equal_share", BEARINGS, LOBES, fx, fy)
    elastic = bending_response(zeta_shaft(), fx, fy, OMEGA)
    a_rigid = harmonic_orders(rigid.bearing_y[2]).amplitude
    a_el = harmonic_orders(elastic.bearing_y[2]).amplitude
    assert max(a_rigid[k] for k in (1, 3, 5, 7)) < 1e-6 * a_rigid[4]
    assert min(a_el[k] for k in (1, 3, 5)) > 1e-3 * a_el[4]


def test_periodic_solution_satisfies_the_equation_of_motion():
    """The order-by-order solution is the periodic solution: M x'' + C x' + K x = F."""
    from camtrain.camshaft.flexible_response import _derivative, _harmonic_solve

    shaft = zeta_shaft()
    fx, fy = lobe_forces()
    F = np.zeros((shaft.K_full.shape[0], N))
    np.add.at(F, shaft.v_index[shaft.stations.force_nodes], fy)
    x, _ = _harmonic_solve(shaft.K, shaft.M, shaft.C, F[shaft.free], OMEGA)
    v = _derivative(x, OMEGA)
    a = _derivative(v, OMEGA)
    res = shaft.M @ a + shaft.C @ v + shaft.K @ x - F[shaft.free]
    # the Nyquist order is dropped by the spectral derivative: compare with the load band-limited
    assert np.max(np.abs(res)) < 1e-6 * np.max(np.abs(fy))


def _torsion(scale=1.0, dampers=(), drive_stiffness=math.inf):
    st = stations(BEARINGS, LOBES, 1)
    sec = ShaftSection(SECTION.EI, SECTION.GJ * scale, SECTION.mass_per_length,
                       SECTION.polar_inertia_per_length)
    inertia = np.zeros(st.positions.size)
    inertia[st.force_nodes] = 3e-5  # lobe polar inertia [kg m^2], assumed
    shaft = torsion_shaft(st, sec, int(st.bearing_nodes[0]), inertia, 0.02, drive_stiffness)
    torques = -np.array([shift_curve(train_torque(), g) for g in PHASES])
    return st, torsion_response(shaft, torques, OMEGA, dampers)


def test_twist_grows_monotonically_from_the_drive():
    """R12: max over the cycle of |psi_k - theta| grows station by station from the gear."""
    st, phi = _torsion()
    amp = np.max(np.abs(phi), axis=1)
    assert amp[st.bearing_nodes[0]] == 0.0
    assert np.all(np.diff(amp[st.bearing_nodes[0]:]) > 0)


def test_pendulum_damper_lowers_its_order():
    """Williams ch 10: on a belt-driven shaft (drive stiffness 2000 N m/rad, assumed) four
    pendulums tuned to order 4 (R/r = 16 x 1.05, eq. 10.59) on the pulley lower the order-4
    twist at every station, by more than half; other orders are not the target."""
    kd = 2000.0
    st, phi = _torsion(drive_stiffness=kd)
    R = 0.03
    damper = PendulumDamper(int(st.bearing_nodes[0]), 0.2, R, R / (16 * 1.05), count=4)
    _, phi_d = _torsion(dampers=[damper], drive_stiffness=kd)
    for i in range(st.positions.size):
        a = harmonic_orders(phi[i]).amplitude[4]
        b = harmonic_orders(phi_d[i]).amplitude[4]
        assert b < 0.5 * a


def test_drive_oscillation_on_one_segment_matches_closed_form():
    """Williams A6.5: base acceleration a = w_hat q w cos(q theta) on a single inertia J on a
    segment of stiffness k: phi = -J a / (k - (q w)^2 J) (undamped)."""
    st = stations([0.0, 0.1], [])
    sec = SECTION
    shaft = torsion_shaft(st, sec, 0, [0.0, 2e-3])
    acc = drive_acceleration(THETA, OMEGA, 5.0, 2)
    phi = torsion_response(shaft, np.zeros((0, N)), OMEGA, drive_accel=acc)
    J = shaft.J[0, 0]
    k = shaft.K[0, 0]
    expected = -J * acc / (k - (2 * OMEGA) ** 2 * J)
    assert np.allclose(phi[1], expected, rtol=1e-10, atol=1e-18)
