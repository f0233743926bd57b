"""Friction/load iteration of followers whose load depends on friction (pivoted followers).

Ball (1988) §4.2.3.2: the pivoted-follower load W depends on mu through the friction arm. Start
with mu = 0.08 around the whole cycle, compute W, then the traction F(W), set mu = F/W and
recompute W; repeat until the load around the cycle converges ("usually only three iterations").
A follower with no friction arm (translating followers) converges in one pass.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from camtrain.errors import ConvergenceError

__all__ = ["LoadSolution", "iterate_load"]


@dataclass(frozen=True)
class LoadSolution:
    """Converged load W [N], friction force F [N], coefficient mu = F/W [-] per angle."""

    load: np.ndarray
    friction: np.ndarray | None
    mu: np.ndarray
    iterations: int
    residual: float  # max |W_k - W_(k-1)| / max(|W_k|, 1 N) at the last iteration
    tolerance: float


def iterate_load(load_of_mu: Callable[[np.ndarray], np.ndarray],
                 friction_of_load: Callable[[np.ndarray], np.ndarray] | None, *,
                 mu0: float = 0.08, tolerance: float = 1e-6, max_iterations: int = 50,
                 depends_on_mu: bool = True) -> LoadSolution:
    """Fixed-point iteration W_k = load(mu_(k-1)), mu_k = F(W_k)/W_k.

    Args:
        load_of_mu: per-angle load for a per-angle friction coefficient.
        friction_of_load: per-angle friction force for a per-angle load; None keeps mu = mu0
            (boundary friction everywhere) and needs no iteration.
        mu0: starting coefficient (Ball: 0.08, after Zhu 1988).
        tolerance: relative tolerance on the load, max|dW| / max(max|W|, 1 N).
        max_iterations: raise :class:`ConvergenceError` beyond this.
        depends_on_mu: False when the load does not depend on mu (no friction arm): one pass.

    Where W <= 0 (no contact or loss of contact) the previous mu is kept.
    """
    load = np.asarray(load_of_mu(np.asarray(mu0, dtype=float)), dtype=float)
    mu = np.empty_like(load)   # (np.full_like is a Python-level wrapper)
    mu.fill(mu0)
    if friction_of_load is None:
        return LoadSolution(load, None, mu, 1, 0.0, tolerance)
    residual = np.inf
    for k in range(1, max_iterations + 1):
        force = np.asarray(friction_of_load(load), dtype=float)
        positive = load > 0.0
        mu = np.where(positive, force / np.where(positive, load, 1.0), mu)
        if not depends_on_mu:
            return LoadSolution(load, force, mu, k, 0.0, tolerance)
        new = np.asarray(load_of_mu(mu), dtype=float)
        scale = max(float(np.max(np.abs(new))), 1.0)
        residual = float(np.max(np.abs(new - load))) / scale
        load = new
        if residual <= tolerance:
            force = np.asarray(friction_of_load(load), dtype=float)
            return LoadSolution(load, force, mu, k, residual, tolerance)
    raise ConvergenceError(
        f"friction/load iteration did not converge: relative load change {residual:.3g} after "
        f"{max_iterations} iterations, tolerance {tolerance:g} (raise "
        f"solver.friction_max_iterations or solver.friction_tolerance)")
