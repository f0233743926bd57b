"""Several elastic valve trains on one elastic camshaft, coupled by staggered iteration.

Teodorescu et al. (2005) §2.6 and §4 drive the valve trains of an engine from one camshaft that
bends and twists, so each train's cam input is the rigid lift plus what the shaft's motion adds,
and the shaft's loads are the trains' dynamic contact loads. The shaft is linear and periodic;
the trains are nonlinear (unilateral contacts). The periodic state of the whole is found here by
a block Gauss-Seidel iteration between the two (a staggered, or partitioned, solution):

1. the shaft's periodic response to the trains' loads gives every lobe's displacement along its
   follower axis p_j(theta) and its twist phi_j(theta) against the drive;
2. each train is marched to its periodic state with the cam input
   b_j = l(theta) + R(theta) p_j + l'(theta) phi_j  (valve-referred: R the rocker ratio, l' the
   valve lift per cam radian; a twist phi advances the lobe by phi, so it lifts l(theta + phi));
3. the new loads, under-relaxed, go back to the shaft, until the loads of two passes agree.

A stiff shaft makes p and phi vanish and returns every train's single-train solution (the limit
the tests hold). The functions here take callables for the two halves, so neither knows the
other's model.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

__all__ = ["CoupledState", "staggered", "periodic_derivatives", "lobe_input_perturbation"]


@dataclass(frozen=True)
class CoupledState:
    """The converged coupling: each lobe's contact load in the shaft's angle frame
    (n_lobes, n) [N], the shaft's last answer (whatever ``solve_shaft`` returned), passes made,
    the relative load change of the last pass and of every pass (``history``)."""

    loads: np.ndarray
    shaft: object
    iterations: int
    change: float
    converged: bool
    history: tuple[float, ...]


def periodic_derivatives(y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """First and second derivative in theta of a curve sampled on the uniform grid of one
    revolution (spectral: exact for the band-limited periodic curve the shaft returns)."""
    y = np.asarray(y, dtype=float)
    n = y.shape[-1]
    Y = np.fft.rfft(y, axis=-1)
    k = np.arange(Y.shape[-1])
    d1 = 1j * k * Y
    d2 = -(k * k) * Y
    if n % 2 == 0:  # the Nyquist term has no odd derivative on the grid
        d1[..., -1] = 0.0
    return np.fft.irfft(d1, n=n, axis=-1), np.fft.irfft(d2, n=n, axis=-1)


def lobe_input_perturbation(displacement, twist, ratio, valve_d1):
    """The change of a train's valve-referred cam input from its lobe's motion (step 2 of the
    module notes): R p + l' phi, with its first and second theta-derivatives."""
    delta = np.asarray(ratio, dtype=float) * displacement + np.asarray(valve_d1) * twist
    d1, d2 = periodic_derivatives(delta)
    return delta, d1, d2


def staggered(solve_shaft: Callable[[np.ndarray], object],
              solve_trains: Callable[[object], np.ndarray], initial_loads: np.ndarray, *,
              tol: float = 1e-4, max_iterations: int = 30, relaxation: float = 1.0
              ) -> CoupledState:
    """Block Gauss-Seidel between the shaft and the trains (module notes).

    Args:
        solve_shaft: loads (n_lobes, n) -> the shaft's answer (passed on to ``solve_trains``).
        solve_trains: the shaft's answer -> the trains' new loads (n_lobes, n) [N].
        initial_loads: loads to start from (e.g. the single-train solution on every lobe).
        tol: relative change of the loads between passes (max norm over the largest load).
        max_iterations: passes at most.
        relaxation: under-relaxation factor in (0, 1] of the load update.
    """
    if not 0.0 < relaxation <= 1.0:
        raise ValueError(f"relaxation must be in (0, 1], not {relaxation}")
    loads = np.asarray(initial_loads, dtype=float)
    history = []
    change = math.inf
    shaft = None
    for it in range(1, int(max_iterations) + 1):
        shaft = solve_shaft(loads)
        new = np.asarray(solve_trains(shaft), dtype=float)
        scale = max(float(np.max(np.abs(new))), 1e-300)
        change = float(np.max(np.abs(new - loads))) / scale
        history.append(change)
        loads = loads + relaxation * (new - loads)
        if change <= tol:
            shaft = solve_shaft(loads)
            return CoupledState(loads, shaft, it, change, True, tuple(history))
    return CoupledState(loads, shaft, int(max_iterations), change, False, tuple(history))
