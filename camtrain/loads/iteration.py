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

__all__ = ["CaseLoads", "LoadSolution", "iterate_cases", "iterate_load"]


@dataclass(frozen=True)
class LoadSolution:
    """Converged load W [N] per angle, and the friction force F [N] and coefficient mu = F/W [-]
    it was solved with (F at the previous iterate of the load, within the tolerance of W)."""

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
    """Fixed-point iteration W_k = load(mu_(k-1)), mu_k = F(W_k)/W_k of one run
    (:func:`iterate_cases` on a single case).

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
    if friction_of_load is None:
        # one pass at mu0, as iterate_cases makes it, without forming its per-case arrays
        load = np.asarray(load_of_mu(np.asarray(mu0, dtype=float)), dtype=float)
        mu = np.empty_like(load)
        mu[...] = mu0
        return LoadSolution(load, None, mu, 1, 0.0, tolerance)
    cases = iterate_cases(load_of_mu, friction_of_load, mu0=mu0, tolerance=tolerance,
                          max_iterations=max_iterations, depends_on_mu=depends_on_mu)
    if not cases.converged:
        raise ConvergenceError(
            f"friction/load iteration did not converge: relative load change "
            f"{float(cases.residual):.3g} after {max_iterations} iterations, tolerance "
            f"{tolerance:g} (raise solver.friction_max_iterations or solver.friction_tolerance)")
    return LoadSolution(cases.load, cases.friction, cases.mu, int(cases.iterations),
                        float(cases.residual), tolerance)


@dataclass(frozen=True)
class CaseLoads:
    """:func:`iterate_cases` per case: the arrays of :class:`LoadSolution` with any leading
    case axes, and per case its iterations, last residual and whether it converged."""

    load: np.ndarray
    friction: np.ndarray | None
    mu: np.ndarray
    iterations: np.ndarray
    residual: np.ndarray
    converged: np.ndarray


def iterate_cases(load_of_mu: Callable[[np.ndarray], np.ndarray],
                  friction_of_load: Callable[[np.ndarray], np.ndarray] | None, *,
                  mu0=0.08, tolerance: float = 1e-6, max_iterations: int = 50,
                  depends_on_mu: bool = True) -> CaseLoads:
    """Ball's iteration (:func:`iterate_load`) over per-angle arrays with any leading case axes
    (the last axis is the cam angle): each case stops at its own convergence and is then held,
    so its iterates, iteration count and final friction are those of the case alone. ``mu0``
    may be one coefficient per case (shaped to broadcast against the loads)."""
    load = np.asarray(load_of_mu(np.asarray(mu0, dtype=float)), dtype=float)
    cases = load.shape[:-1]
    mu = np.empty_like(load)   # (np.full_like is a Python-level wrapper)
    mu[...] = mu0
    if friction_of_load is None:
        one = np.ones(cases, dtype=int)
        return CaseLoads(load, None, mu, one, np.zeros(cases), np.ones(cases, dtype=bool))
    done = np.zeros(cases, dtype=bool)
    iterations = np.zeros(cases, dtype=int)
    residual = np.full(cases, np.inf)
    solved_with = None
    for k in range(1, max_iterations + 1):
        force = np.asarray(friction_of_load(load), dtype=float)
        positive = load > 0.0
        step = np.where(positive, force / np.where(positive, load, 1.0), mu)
        held = done[..., None]
        mu = np.where(held, mu, step) if k > 1 else step
        solved_with = np.where(held, solved_with, force) if k > 1 else force
        if not depends_on_mu:
            return CaseLoads(load, force, mu, np.full(cases, k), np.zeros(cases),
                             np.ones(cases, dtype=bool))
        new = np.asarray(load_of_mu(mu), dtype=float)
        scale = np.maximum(np.max(np.abs(new), axis=-1), 1.0)
        change = np.max(np.abs(new - load), axis=-1) / scale
        residual = np.where(done, residual, change)
        load = np.where(done[..., None], load, new) if k > 1 else new
        now = ~done & (change <= tolerance)
        iterations[now] = k
        done |= now
        if done.all():
            break
    iterations[~done] = max_iterations
    # the friction the final load was solved with (mu = F/W of the iterate before it): no
    # further evaluation at the final load, which the chain's hertz, film and friction effects
    # (or the roller) evaluate for themselves
    return CaseLoads(load, solved_with, mu, iterations, residual, done)
