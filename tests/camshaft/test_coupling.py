"""The waveform shaft/train iteration (camtrain.coupled.relaxation) on problems with a known
answer: a linear interface whose plain iteration diverges, and the periodic derivatives."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.coupled.relaxation import periodic_derivatives, waveform_relaxation

RNG = np.random.default_rng(7)
N = 24
#: a linear pass x -> A x + b with spectral radius 3 (a contact three times stiffer than the
#: shaft): the plain iteration diverges, the fixed point is (I - A)^-1 b
Q, _ = np.linalg.qr(RNG.normal(size=(N, N)))
A = Q @ np.diag(np.linspace(-3.0, 0.5, N)) @ Q.T
B = RNG.normal(size=N)
EXACT = np.linalg.solve(np.eye(N) - A, B)


def linear_pass(x):
    return A @ x + B


def test_quasi_newton_converges_where_the_plain_iteration_diverges():
    state = waveform_relaxation(linear_pass, np.zeros(N), tol=1e-10, max_iterations=60)
    assert state.converged
    np.testing.assert_allclose(state.motion, EXACT, rtol=0, atol=1e-8 * np.abs(EXACT).max())
    # a linear map of dimension N: IQN-ILS needs at most about N + 1 passes
    assert state.iterations <= N + 2
    plain = waveform_relaxation(linear_pass, np.zeros(N), tol=1e-10, max_iterations=30, method="fixed",
                      relaxation=1.0)
    assert not plain.converged and plain.history[-1] > plain.history[0]


def test_aitken_converges_on_a_contraction_and_reports_its_history():
    contraction = Q @ np.diag(np.linspace(-0.6, 0.6, N)) @ Q.T
    state = waveform_relaxation(lambda x: contraction @ x + B, np.zeros(N), tol=1e-10,
                      max_iterations=200, method="aitken")
    assert state.converged
    exact = np.linalg.solve(np.eye(N) - contraction, B)
    np.testing.assert_allclose(state.motion, exact, atol=1e-8 * np.abs(exact).max())
    assert len(state.history) == state.iterations


def test_bad_method_or_relaxation_is_refused():
    with pytest.raises(ValueError):
        waveform_relaxation(linear_pass, np.zeros(N), method="newton")
    with pytest.raises(ValueError):
        waveform_relaxation(linear_pass, np.zeros(N), relaxation=1.5)


def test_periodic_derivatives_are_exact_for_a_trigonometric_curve():
    theta = np.arange(360) * 2 * np.pi / 360
    y = np.sin(3 * theta) + 0.2 * np.cos(7 * theta)
    d1, d2 = periodic_derivatives(y)
    np.testing.assert_allclose(d1, 3 * np.cos(3 * theta) - 1.4 * np.sin(7 * theta), atol=1e-12)
    np.testing.assert_allclose(d2, -9 * np.sin(3 * theta) - 9.8 * np.cos(7 * theta), atol=1e-11)
