"""Several elastic valve trains on one elastic camshaft, coupled by waveform relaxation.

Teodorescu et al. (2005) §2.6 and §4 drive the valve trains of an engine from one camshaft that
bends and twists, so each train's cam input is the rigid lift plus what the shaft's motion adds,
and the shaft's loads are the trains' dynamic contact loads. The shaft is linear and periodic;
the trains are nonlinear (unilateral contacts). The periodic state of the whole is found here by
a block Gauss-Seidel iteration between the two over whole revolutions (waveform relaxation; the
step-by-step staggered march is :mod:`._partition`):

1. the shaft's periodic response to the trains' loads gives every lobe's displacement along its
   follower axis p_j(theta) and its twist phi_j(theta) against the drive;
2. each train is marched to its periodic state with the cam input
   b_j = l(theta) + R(theta) p_j + l'(theta) phi_j  (valve-referred: R the rocker ratio, l' the
   valve lift per cam radian; a twist phi advances the lobe by phi, so it lifts l(theta + phi));
3. the trains' loads go back to the shaft, until the lobes' motion of two passes agrees (the
   motion, not the loads, is the unknown: see :func:`waveform_relaxation`).

A stiff contact on a compliant shaft makes the plain iteration diverge (its loop gain, the
contact stiffness over the shaft's, exceeds 1). Two accelerations are offered (``method``):

* ``quasi_newton`` (default): the interface quasi-Newton method with an inverse Jacobian from
  least squares (IQN-ILS, Degroote, Bathe and Vierendeels 2009), the standard of partitioned
  fluid-structure solvers: from the differences of the residuals r = H(x) - x and of the outputs
  H(x) of the passes so far, c = argmin |V c + r_k| and x_(k+1) = H(x_k) + W c.
* ``aitken``: relaxation adapted every pass by Aitken's Delta^2 rule (Irons and Tuck 1969),
  w_k = -w_(k-1) r_(k-1).(r_k - r_(k-1)) / |r_k - r_(k-1)|^2, kept in [w_min, 1]; enough for a
  loop gain near 1.

Either runs on the raw residual or on a preconditioned one (``precondition``): the interface
Newton step of the linear shaft and trains (:mod:`camtrain.coupled.interface`), without which
no acceleration holds the iteration where a contact drives a lightly damped shaft mode.

A stiff shaft makes p and phi vanish and returns every train's single-train solution (the limit
the tests hold). The functions here take callables for the two halves, so neither knows the
other's model.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

#: accelerations of the waveform iteration (module notes)
COUPLING_METHODS = ("quasi_newton", "aitken", "fixed")

__all__ = ["COUPLING_METHODS", "CoupledState", "waveform_relaxation", "periodic_derivatives",
           "lobe_input_perturbation"]


@dataclass(frozen=True)
class CoupledState:
    """The converged interface: the lobes' motion ``motion`` (what the shaft hands the trains,
    e.g. displacement along the follower axis and twist per lobe, rows scaled alike), passes
    made, the relative change of the last pass and of every pass (``history``)."""

    motion: np.ndarray
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


def waveform_relaxation(operator: Callable[[np.ndarray], np.ndarray], start: np.ndarray, *,
              tol: float = 1e-4, max_iterations: int = 30, relaxation: float = 0.5,
              method: str = "quasi_newton", min_relaxation: float = 1e-3,
              precondition: Callable[[np.ndarray], np.ndarray] | None = None,
              columns: int = 0) -> CoupledState:
    """Fixed point x = H(x) of the shaft/train pass H (module notes).

    The interface unknown is the lobes' motion, not their loads: the shaft filters it, so it is
    smooth, while a contact load carries the impacts of separations, whose timing moves a
    little between passes. ``operator`` runs the trains under the motion x and returns the
    shaft's motion under their loads; ``start`` is e.g. the shaft's motion under the
    single-train loads. The change of a pass is max|H(x) - x| / max|H(x)| per row block; the
    rows are scaled by the caller.

    Args:
        tol: relative change that counts as converged.
        max_iterations: passes at most.
        relaxation: relaxation factor in (0, 1] of the first update (of every update for
            ``method = "fixed"``).
        method: ``quasi_newton``, ``aitken`` or ``fixed`` (module notes).
        min_relaxation: smallest factor Aitken's rule may take.
        precondition: a map of the residual H(x) - x to an update, e.g. the interface Newton
            step (I - J)^-1 of :func:`camtrain.coupled.interface.interface_newton`; the
            passes then run on the preconditioned residual (the change is still the raw one).
        columns: most past passes the quasi-Newton method keeps (0: all of them).
    """
    if method not in COUPLING_METHODS:
        raise ValueError(f"unknown coupling method {method!r}")
    if not 0.0 < relaxation <= 1.0:
        raise ValueError(f"relaxation must be in (0, 1], not {relaxation}")
    x = np.asarray(start, dtype=float)
    history = []
    change = math.inf
    w = float(relaxation)
    previous = None
    residuals, outputs = [], []
    for it in range(1, int(max_iterations) + 1):
        new = np.asarray(operator(x), dtype=float)
        residual = new - x
        scale = max(float(np.max(np.abs(new))), 1e-300)
        change = float(np.max(np.abs(residual))) / scale
        history.append(change)
        if change <= tol:
            return CoupledState(new, it, change, True, tuple(history))
        if precondition is not None:
            residual = np.asarray(precondition(residual), dtype=float).reshape(x.shape)
            new = x + residual
        if method == "quasi_newton":
            residuals.append(residual.ravel())
            outputs.append(new.ravel())
            if columns and len(residuals) > columns + 1:
                del residuals[0], outputs[0]
            if len(residuals) > 1:
                V = np.column_stack([residuals[-1] - r for r in residuals[:-1]])
                W = np.column_stack([outputs[-1] - o for o in outputs[:-1]])
                c = np.linalg.lstsq(V, -residuals[-1], rcond=None)[0]
                x = (new.ravel() + W @ c).reshape(x.shape)
                continue
        elif method == "aitken" and previous is not None:
            step = (residual - previous).ravel()
            denom = float(step @ step)
            if denom > 0.0:
                w = -w * float(previous.ravel() @ step) / denom
                w = min(max(w, min_relaxation), 1.0)
        previous = residual
        x = x + w * residual
    return CoupledState(x, int(max_iterations), change, False, tuple(history))
