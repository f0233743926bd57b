"""The waveform coupling's interface Jacobian (camtrain.coupled.interface): the shaft's lobe
receptance against its periodic harmonic solve, the train's dynamic contact stiffness against
its static limit, and the preconditioned iteration on linear passes with a known answer."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.camshaft.elastic import elastic_shaft
from camtrain.camshaft.flexible import ShaftSection
from camtrain.camshaft.flexible_response import bending_response, lobe_receptance
from camtrain.coupled.interface import contact_stiffness, interface_newton
from camtrain.coupled.relaxation import waveform_relaxation
from camtrain.dynamics.train import CAM, SEAT, TrainModel, series

OMEGA = 2 * math.pi * 25.0  # 1500 rpm camshaft


def zeta_like_shaft():
    section = ShaftSection.hollow(24.0e-3, 0.0, 170e9, 66e9, 7300.0)
    return elastic_shaft([0.0, 0.0699, 0.1617], [0.0504, 0.0894, 0.1422], -0.04, section,
                         bearing_stiffness=1e9, damping_ratio=2.0, lobe_mass=0.12,
                         lobe_inertia=2e-5, drive_stiffness=4e4, drive_inertia=2e-3,
                         nodes_per_span=2)


@pytest.mark.derived
def test_lobe_receptance_is_the_shaft_periodic_answer_to_a_unit_harmonic_force():
    shaft = zeta_like_shaft()
    n = 720
    theta = np.arange(n) * 2 * math.pi / n
    orders = np.array([0, 3, 57, 304])
    H = lobe_receptance(shaft.beam, shaft.lobe_nodes, OMEGA, orders)
    for j in range(len(shaft.lobe_nodes)):
        force = np.zeros((len(shaft.lobe_nodes) + 1, n))
        force[j] = sum(np.cos(k * theta) for k in orders)
        bend = bending_response(shaft.beam, force, np.zeros_like(force), OMEGA)
        X = np.fft.rfft(bend.deflection_x[shaft.lobe_nodes], axis=-1)[:, orders]
        X[:, 1:] /= n / 2
        X[:, 0] /= n
        scale = np.abs(H[:, :, j]).max()
        np.testing.assert_allclose(X.T, H[:, :, j], rtol=0, atol=1e-10 * scale)


def two_mass_train(k_contact=2e8, k_stem=2e7, k_spring=4e4):
    """Follower (0.05 kg) on the cam contact, stem to the valve (0.06 kg) on its spring and
    seat; 2 % damping of the stem."""
    m = np.array([0.05, 0.06])
    K = np.array([[k_stem, -k_stem], [-k_stem, k_stem + k_spring]])
    c = 2 * 0.02 * math.sqrt(k_stem * 0.05)
    C = np.array([[c, -c], [-c, c]])
    return TrainModel(mass=m, stiffness=K, damping=C, preload=np.zeros(2),
                      uni_node=np.array([0, 1]), uni_k=np.array([k_contact, 2e8]),
                      uni_c=np.array([0.0, 0.0]), uni_offset=np.zeros(2), follower=0, valve=1,
                      elements=(), spring_rate=k_spring, spring_preload=300.0)


@pytest.mark.derived
def test_contact_stiffness_limits():
    """Order 0: the contact, stem and valve spring in series (the seat open); far above the
    train's modes the follower stands still and the contact stiffness alone remains."""
    model = two_mass_train()
    g = contact_stiffness(model, OMEGA, [0, 200000])
    assert g[0].real == pytest.approx(series(2e8, 2e7, 4e4), rel=1e-9)
    assert abs(g[0].imag) < 1e-9 * abs(g[0])
    assert g[1] == pytest.approx(model.uni_k[CAM], rel=2e-3)
    assert model.uni_node[SEAT] == model.valve


def test_interface_newton_with_the_exact_jacobian_converges_in_one_pass():
    """A linear periodic pass x -> J * x + b (J applied order by order, gain up to 40 at a
    'resonance'): the plain passes diverge, one preconditioned step lands on the fixed point."""
    n, m = 64, 3
    rng = np.random.default_rng(3)
    orders = np.arange(n // 2 + 1)
    J = rng.normal(size=(orders.size, m, m)) * 0.3 + 0j
    J[20] *= 40.0 / np.abs(np.linalg.eigvals(J[20])).max()
    J[0] = J[0].real
    J[-1] = J[-1].real
    b = rng.normal(size=(m, n))

    def linear_pass(x):
        return np.fft.irfft(np.einsum("kij,jk->ik", J, np.fft.rfft(x, axis=-1)), n=n) + b

    P = interface_newton(J, slice(0, m))
    state = waveform_relaxation(linear_pass, np.zeros((m, n)), tol=1e-10, max_iterations=5,
                      relaxation=1.0, precondition=P)
    assert state.converged and state.iterations <= 2, state.history
    plain = waveform_relaxation(linear_pass, np.zeros((m, n)), tol=1e-10, max_iterations=10,
                      method="fixed", relaxation=1.0)
    assert not plain.converged
