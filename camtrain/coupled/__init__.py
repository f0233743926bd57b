"""Every lobe's elastic valve train on the elastic camshaft, coupled two ways (Teodorescu et al.
2005 §2.6, §4; docs/camshaft_dynamics.md).

A :class:`~.problem.CoupledProblem` (plain data built from the deck by
:func:`camtrain.assemble.coupled.coupled_problem`) goes to the solver the deck names
(``camshaft.flexibility.coupling_solver``), which returns a :class:`~.problem.CoupledResult`.
The solvers, one module each, each owning its iteration:

* ``monolithic`` (:mod:`.monolithic`): trains and shaft in one state vector marched together
  in time (:mod:`.march`, compiled revolution :mod:`._revolution`, step :mod:`._step`);
* ``staggered`` (:mod:`.staggered`): the same march, shaft and trains in turn within every
  step (:mod:`._partition`);
* ``waveform`` (:mod:`.waveform`): trains and shaft in turn over whole revolutions
  (:mod:`.relaxation`, :mod:`.interface`).

Another solver is one module with ``solve(problem) -> CoupledResult`` registered with
:func:`register_solver`; the deck option then names it. This module imports no numpy (the
plan reads :data:`SOLVERS`); the compiled kernels take the typed records of :mod:`.records`.
"""
from __future__ import annotations

from dataclasses import dataclass
from importlib import import_module

__all__ = ["SOLVERS", "Solver", "register_solver", "solve"]


@dataclass(frozen=True)
class Solver:
    """A coupled solver: its ``module`` (with ``solve(problem)``) and how the plan says it
    works (``how``)."""

    module: str
    how: str


#: the coupled solvers by the deck's name for them
SOLVERS: dict[str, Solver] = {
    "monolithic": Solver("camtrain.coupled.monolithic", "marched together"),
    "staggered": Solver("camtrain.coupled.staggered", "marched in turn every step"),
    "waveform": Solver("camtrain.coupled.waveform", "iterated revolution by revolution"),
}


def register_solver(name: str, module: str, how: str) -> None:
    """Offer another coupled solver under ``name`` (``module`` has ``solve(problem)``)."""
    SOLVERS[name] = Solver(module, how)


def solve(problem):
    """The problem's periodic coupled state by the solver its options name."""
    return import_module(SOLVERS[problem.coupling.solver].module).solve(problem)
