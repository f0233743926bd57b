"""`camtrain optimize`: the deck that loses least under the constraints a valve train must meet.

The variables are scaled to [0, 1] between their bounds; the objective (any metric, the mean
friction power by default) is divided by its datum value and every constraint margin by its
bound (:mod:`camtrain.study.optimize_problem`), so the solvers see numbers of order one.

Methods (scipy.optimize):

* ``slsqp`` (default): sequential least squares programming (Kraft 1988, DFVLR-FB 88-28).
  Gradients by forward differences of ``step`` (in the scaled variables, backward at the upper
  bound); the point and its n neighbours are one batch of n + 1 cases when the variables allow
  the batch route, so an iteration costs about one vectorised chain.
* ``trust-constr``: the trust-region interior-point method (Byrd, Hribar & Nocedal 1999, SIAM
  J. Optim. 9:877-900) with the same differences and BFGS Hessians.
* ``differential_evolution``: the global search of Storn & Price (1997, J. Global Optim.
  11:341-359). Each generation is one set of cases (the population, deferred updating);
  constraints by Deb's (2000, Comput. Methods Appl. Mech. Eng. 186:311-338) feasibility rules
  (a feasible point beats an infeasible one, infeasible points rank by their violation); the
  best point is then polished by ``slsqp``.

A point whose case fails (a concave flank under a flat follower, an invalid value) has no
objective: the solvers see the worst objective met so far there, and its constraint margins
from what can still be computed (the cam radius from the lift law and the kinematics kernel),
else -1. The optimum is the best feasible point evaluated. Ctrl-C stops the search and keeps it.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from camtrain.errors import InputError
from camtrain.errors import Problem as DeckProblem
from camtrain.metric_rows import case_metric
from camtrain.study.optimize_problem import (
    Point,
    Problem,
    parse_constraint,
    parse_variable,
)

METHODS = ("slsqp", "trust-constr", "differential_evolution")
#: scaled margin within which a constraint counts as active at the optimum
ACTIVE = 1e-3


@dataclass
class OptimizeOutcome:
    """What a search found: the datum, the optimum, how, and every point on the way."""

    problem: Problem
    datum: Point
    optimum: Point
    method: str
    status: str         # converged | stopped | interrupted | infeasible
    message: str

    @property
    def evaluations(self) -> int:
        """Chain evaluations (cases run), the datum included."""
        return len(self.problem.path)

    def active(self) -> list[str]:
        """Constraints (and bounds) active at the optimum."""
        out = [c.text for c, g in zip(self.problem.constraints, self.optimum.margins,
                                      strict=True) if abs(g) <= ACTIVE]
        for v, x in zip(self.problem.variables, self.optimum.x, strict=True):
            u = v.scaled(x)
            if u <= 1e-6 or u >= 1 - 1e-6:
                out.append(f"{v.name} at its {'lower' if u <= 0.5 else 'upper'} bound")
        return out

    def gains(self) -> list[tuple[str, str, float, float, float, float]]:
        """(metric, unit, datum, optimum, change, change %) of the objective and every power
        [W] of the run: the gain by part."""
        names = [self.problem.objective] + [
            n for n, (_, u) in self.datum.metrics.items()
            if u == "W" and n != self.problem.objective
            and case_metric(self.optimum.metrics, n) is not None]
        rows = []
        for n in names:
            d = self.datum.metrics.get(n, (math.nan, ""))
            o = self.optimum.metrics.get(n, (math.nan, ""))
            change = o[0] - d[0]
            rows.append((n, d[1], d[0], o[0], change, 100.0 * change / d[0] if d[0] else
                         math.nan))
        return rows


def optimize(deck: str | Path, variables: Sequence, objective: str = "power_loss_mean",
             constraints: Sequence[str] = (), *, method: str = "slsqp", step: float = 1e-3,
             maxiter: int = 100, jobs: int | None = 1, scheduler=None, sets: Sequence[str] = (),
             popsize: int = 8, seed: int = 1,
             progress: Callable[[Problem], None] | None = None) -> OptimizeOutcome:
    """Minimise ``objective`` over ``variables`` (``"path=lo:hi"`` or ``(path, lo, hi)``, deck
    units) subject to ``constraints`` (docs/design.md), starting from the deck's values.

    ``progress(problem)`` is called after each set of cases (``problem.path`` holds them).
    """
    problem = _problem(deck, variables, objective, constraints, method, jobs, scheduler, sets)
    problem.progress = progress
    own = problem.executor
    try:
        return _solve(problem, method, step, maxiter, popsize, seed)
    finally:
        own.close()


def _problem(deck, variables, objective, constraints, method, jobs, scheduler, sets) -> Problem:
    from camtrain.study.batch import route
    from camtrain.study.case_model import datum_key
    from camtrain.study.executors import make_executor

    if method not in METHODS:
        raise InputError(DeckProblem("--method", "is not a method", method, ", ".join(METHODS)))
    if not variables:
        raise InputError(DeckProblem("--var", "no design variable given", None,
                                     "at least one NAME=LOWER:UPPER"))
    raw, name, base_dir = _datum_deck(deck, sets)
    vars_ = [parse_variable(raw, v) for v in variables]
    names = [v.param.path for v in vars_]
    if len(set(names)) != len(names):
        raise InputError(DeckProblem("--var", "a field is given twice", names, "distinct"))
    cons = [parse_constraint(c) for c in constraints]
    key = datum_key(raw, name, base_dir)
    problem = Problem(raw, name, base_dir, vars_, objective, cons, key=key)
    problem.route = route(raw, [v.param for v in vars_], name, base_dir, key)
    problem.executor = make_executor(jobs, scheduler)
    return problem


def _datum_deck(deck, sets) -> tuple[dict, str, str]:
    """The raw datum deck (``--set`` values written in, then validated), its name and folder."""
    from camtrain.deck.load import load_deck, parse_toml, validate
    from camtrain.study.assign import apply_fixed, parse_assignment

    loaded = load_deck(str(deck))
    raw = parse_toml(loaded.text, loaded.path)
    base_dir = str(Path(deck).resolve().parent) if str(deck) != "-" else str(Path.cwd())
    fixed = [parse_assignment(raw, s) for s in sets]
    raw = apply_fixed(raw, fixed)
    if fixed:
        validate(raw, loaded.path, Path(base_dir))
    return raw, loaded.path, base_dir


def _datum(problem: Problem) -> Point:
    x0 = tuple(v.param.datum if v.param.datum is not None else 0.5 * (v.lower + v.upper)
               for v in problem.variables)
    x0 = tuple(min(max(x, v.lower), v.upper) for x, v in zip(x0, problem.variables,
                                                              strict=True))
    point = problem.evaluate([x0], "datum")[0]
    if not math.isfinite(point.objective):
        raise InputError(DeckProblem("--objective", f"the datum deck gives no {problem.objective!r}"
                                     f" ({point.status}: {point.message})", problem.objective,
                                     "a metric of the run, e.g. power_loss_mean, hertz_max"))
    problem.datum = point
    point.margins = tuple(c.value(point.metrics, point.metrics) for c in problem.constraints)
    return point


def _solve(problem: Problem, method: str, step: float, maxiter: int, popsize: int,
           seed: int) -> OptimizeOutcome:
    datum = _datum(problem)
    fn = _Functions(problem, step)
    status, message = "stopped", ""
    try:
        if method == "differential_evolution":
            status, message = _global(fn, maxiter, popsize, seed)
        else:
            status, message = _local(fn, method, np.array([v.scaled(x) for v, x in
                                                           zip(problem.variables, datum.x,
                                                               strict=True)]), maxiter)
    except KeyboardInterrupt:
        status, message = "interrupted", "stopped by the user; the best point so far is kept"
    feasible = [p for p in problem.path if p.feasible]
    if feasible:
        optimum = min(feasible, key=lambda p: p.objective)
    else:
        optimum = min(problem.path, key=lambda p: -sum(min(g, 0.0) for g in p.margins
                                                       if math.isfinite(g)))
        status, message = "infeasible", "no evaluated point meets every constraint"
    return OptimizeOutcome(problem, datum, optimum, method, status, message)


class _Functions:
    """Objective, constraints and their forward differences on the scaled variables."""

    def __init__(self, problem: Problem, step: float):
        self.p, self.step = problem, step
        self.f0 = abs(problem.datum.objective) or 1.0
        self.n = len(problem.variables)

    def x_of(self, u) -> tuple[float, ...]:
        return tuple(float(v.unscaled(min(max(ui, 0.0), 1.0)))
                     for v, ui in zip(self.p.variables, u, strict=True))

    def neighbours(self, u) -> list[np.ndarray]:
        out = []
        for i in range(self.n):
            e = np.array(u, dtype=float)
            e[i] += self.step if e[i] + self.step <= 1.0 else -self.step
            out.append(e)
        return out

    def points(self, u, with_gradient: bool) -> list[Point]:
        us = [np.asarray(u, dtype=float)]
        if with_gradient or self.p.route.batch:   # in a batch the neighbours cost ~nothing
            us += self.neighbours(u)
        return self.p.evaluate([self.x_of(v) for v in us],
                               "iterate" if not with_gradient else "gradient")

    def objective(self, point: Point) -> float:
        if math.isfinite(point.objective):
            return point.objective / self.f0
        seen = [q.objective for q in self.p.path if math.isfinite(q.objective)]
        return max(seen) / self.f0

    @staticmethod
    def margins(point: Point) -> np.ndarray:
        return np.array([g if math.isfinite(g) else -1.0 for g in point.margins])

    def f(self, u) -> float:
        return self.objective(self.points(u, False)[0])

    def g(self, u) -> np.ndarray:
        return self.margins(self.points(u, False)[0])

    def _jac(self, u, of) -> np.ndarray:
        pts = self.points(u, True)
        base, rows = of(pts[0]), []
        for i, q in enumerate(pts[1:]):
            h = self.neighbours(u)[i][i] - u[i]
            rows.append((np.asarray(of(q)) - np.asarray(base)) / h)
        return np.array(rows).T

    def df(self, u) -> np.ndarray:
        return self._jac(u, self.objective).ravel()

    def dg(self, u) -> np.ndarray:
        return self._jac(u, self.margins).reshape(len(self.p.constraints), self.n)


def _local(fn: _Functions, method: str, u0: np.ndarray, maxiter: int) -> tuple[str, str]:
    from scipy.optimize import Bounds, minimize

    def counted(u):
        fn.p.iteration += 1
        return False

    bounds = Bounds(np.zeros(fn.n), np.ones(fn.n))
    if method == "trust-constr":
        from scipy.optimize import BFGS, NonlinearConstraint

        cons = ([NonlinearConstraint(fn.g, 0.0, np.inf, jac=fn.dg, hess=BFGS())]
                if fn.p.constraints else [])
        res = minimize(fn.f, u0, jac=fn.df, hess=BFGS(), method="trust-constr",
                       bounds=bounds, constraints=cons,
                       options={"maxiter": maxiter, "xtol": 1e-2 * fn.step, "gtol": 1e-6},
                       callback=lambda *a: counted(a[0]))
    else:
        cons = ([{"type": "ineq", "fun": fn.g, "jac": fn.dg}] if fn.p.constraints else [])
        res = minimize(fn.f, u0, jac=fn.df, method="SLSQP", bounds=bounds, constraints=cons,
                       options={"maxiter": maxiter, "ftol": 1e-7}, callback=counted)
    return ("converged" if res.success else "stopped"), str(res.message)


def _global(fn: _Functions, maxiter: int, popsize: int, seed: int) -> tuple[str, str]:
    from scipy.optimize import differential_evolution

    def ranked(point: Point) -> float:
        violation = float(np.sum(np.maximum(-fn.margins(point), 0.0)))
        if violation > 1e-9 or not math.isfinite(point.objective):
            return 1e3 * (1.0 + violation)         # Deb: every feasible point ranks above
        return point.objective / fn.f0

    def population(func, us):
        us = [np.asarray(u, dtype=float) for u in us]
        fn.p.iteration += 1
        pts = fn.p.evaluate([fn.x_of(u) for u in us], "population")
        return [ranked(q) for q in pts]

    res = differential_evolution(lambda u: 0.0, [(0.0, 1.0)] * fn.n, maxiter=maxiter,
                                 popsize=popsize, seed=seed, workers=population,
                                 updating="deferred", polish=False, tol=1e-6)
    feasible = [q for q in fn.p.path if q.feasible]
    if not feasible:
        return "stopped", f"differential evolution: {res.message}; no feasible point"
    best = min(feasible, key=lambda q: q.objective)
    status, message = _local(fn, "slsqp", np.array([v.scaled(x) for v, x in
                                                   zip(fn.p.variables, best.x, strict=True)]),
                             maxiter)
    return status, f"differential evolution: {res.message}; polished by SLSQP: {message}"
