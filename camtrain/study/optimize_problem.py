"""The optimisation problem of `camtrain optimize`: variables, objective, constraints, and the
evaluation of many points at once through the sweep machinery.

A point is a set of values of the design variables (deck units). :meth:`Problem.evaluate`
turns a list of points into sweep cases of the datum deck and runs them the way `camtrain
sweep` runs its cases (:mod:`camtrain.study.batch`, :mod:`camtrain.study.executors`): as one
vectorised batch where every variable is a scalar the chain uses elementwise, case by case
otherwise, on this process, local workers or a Dask cluster. Metrics come back in deck units.
"""
from __future__ import annotations

import dataclasses
import math
import re
from dataclasses import dataclass, field

from camtrain.errors import InputError
from camtrain.errors import Problem as DeckProblem
from camtrain.study.sweep import Case, Parameter, bounded, checked_bounds, parse_bounds, resolve_path

#: the constraint names that are not a metric compared with a number
NAMED = ("no_concave_flank", "no_separation", "min_film_parameter", "hertz_limit", "open_area")
#: smallest cam radius of curvature "no concave flank" allows [mm]: a convex flank, by a hair
CONVEX_MARGIN_MM = 0.001


def _bad(option: str, value, message: str, expected: str = "") -> InputError:
    return InputError(DeckProblem(option, message, value, expected))


@dataclass(frozen=True)
class Variable:
    """A design variable: a numeric deck field and its bounds (deck units)."""

    param: Parameter
    lower: float
    upper: float

    @property
    def name(self) -> str:
        return self.param.name

    def scaled(self, x: float) -> float:
        return (x - self.lower) / (self.upper - self.lower)

    def unscaled(self, u: float) -> float:
        return self.lower + u * (self.upper - self.lower)


@dataclass(frozen=True)
class Constraint:
    """g(metrics) >= 0 when met. ``metric`` in deck units compared with ``bound`` by ``sense``
    (">=" or "<="); ``kind``: "metric", "concave" (cam radius), "area" (valve-open area within
    ``bound`` % of the datum's), "lambda" (film / roughness)."""

    text: str
    metric: str
    sense: str
    bound: float
    unit: str = ""
    kind: str = "metric"

    def value(self, metrics: dict, datum: dict | None = None) -> float:
        """Signed, scaled margin (>= 0: met); NaN where the metric is missing."""
        if self.kind == "area":
            ref = (datum or metrics).get("open_area", (math.nan,))[0]
            got = metrics.get("open_area", (math.nan,))[0]
            return (self.bound / 100.0 - abs(got - ref) / abs(ref)) / (self.bound / 100.0)
        got = metrics.get(self.metric, (math.nan,))[0]
        scale = abs(self.bound) if self.bound else 1.0
        if self.kind == "concave":
            scale = 1.0                     # mm: the margin is a hair, the scale a millimetre
        margin = got - self.bound if self.sense == ">=" else self.bound - got
        return margin / scale


def parse_variable(raw: dict, spec) -> Variable:
    """``"base_radius=10:25"`` or ``("base_radius", 10, 25)`` (deck units) -> Variable."""
    if isinstance(spec, str):
        m = re.fullmatch(r"\s*([^=\s]+)\s*=\s*(.+?)\s*", spec)
        if not m:
            raise _bad("--var", spec, "needs NAME=LOWER:UPPER", "e.g. base_radius=12:24")
        name = m.group(1)
        lo, hi = parse_bounds("--var", m.group(2), "NAME=LOWER:UPPER")
    else:
        name = spec[0]
        lo, hi = checked_bounds("--var", float(spec[1]), float(spec[2]), spec)
    param = resolve_path(raw, name, "--var")
    if param.integer:
        raise _bad("--var", name, f"{param.path} takes whole numbers", "a continuous field")
    bounded(param, lo, hi, "--var")
    return Variable(param, lo, hi)


def parse_constraint(spec: str) -> Constraint:
    """A constraint from its text (docs/design.md):

    ``no_concave_flank``; ``no_separation=RPM`` (bounce speed >= the over-speed);
    ``min_film_parameter=X``; ``hertz_limit=MPA``; ``open_area=PCT``; or ``METRIC>=X`` /
    ``METRIC<=X`` with any metric of a run, in its deck unit (as summary.json gives it).
    """
    text = spec.strip()
    if text == "no_concave_flank":
        return Constraint(text, "cam_radius_min", ">=", CONVEX_MARGIN_MM, "mm", "concave")
    m = re.fullmatch(r"([A-Za-z_][A-Za-z0-9_]*)\s*(>=|<=|=)\s*([-+0-9.eE]+)", text)
    if not m:
        raise _bad("--constraint", spec, "is not a constraint",
                   "no_concave_flank, no_separation=RPM, min_film_parameter=X, hertz_limit=MPA,"
                   " open_area=PCT, or METRIC>=X / METRIC<=X")
    name, op, number = m.group(1), m.group(2), m.group(3)
    try:
        bound = float(number)
    except ValueError:
        raise _bad("--constraint", spec, f"{number!r} is not a number") from None
    named = {"no_separation": ("bounce_speed", ">=", "rpm", "metric"),
             "min_film_parameter": ("film_parameter_min", ">=", "-", "lambda"),
             "hertz_limit": ("hertz_max", "<=", "MPa", "metric"),
             "open_area": ("open_area", "<=", "%", "area")}
    if name in named:
        if op != "=":
            raise _bad("--constraint", spec, f"{name} takes NAME=VALUE")
        metric, sense, unit, kind = named[name]
        if kind == "area" and not bound > 0:
            raise _bad("--constraint", spec, "the tolerance must be positive", "a percentage")
        return Constraint(text, metric, sense, bound, unit, kind)
    if op == "=":
        raise _bad("--constraint", spec, "a metric needs >= or <=", "e.g. film_min>=0.1")
    return Constraint(text, name, op, bound)


@dataclass
class Point:
    """One evaluated point: variable values (deck units), status, metrics (deck units)."""

    x: tuple[float, ...]
    status: str
    message: str
    metrics: dict
    objective: float = math.nan
    margins: tuple[float, ...] = ()
    role: str = "iterate"
    iteration: int = 0
    #: the case's [lift.spline] (deck units) when its lift was designed from [design] fields
    designed_lift: dict | None = None

    @property
    def feasible(self) -> bool:
        return (self.status in ("ok", "lost_contact") and math.isfinite(self.objective)
                and all(g >= -1e-9 for g in self.margins))


@dataclass
class Problem:
    """The datum deck, the variables, the objective metric, the constraints, where cases run."""

    raw: dict
    name: str
    base_dir: str
    variables: list[Variable]
    objective: str
    constraints: list[Constraint]
    executor: object = None
    route: object = None
    key: str = ""
    datum: Point | None = None
    path: list[Point] = field(default_factory=list)
    cache: dict = field(default_factory=dict)
    iteration: int = 0
    progress: object = None
    _index: int = 0

    def evaluate(self, points: list[tuple[float, ...]], role: str = "iterate") -> list[Point]:
        """Every point (deck units) run as one set of sweep cases; cached by value."""
        todo = [p for p in dict.fromkeys(points) if p not in self.cache]
        if todo:
            for x, rec in zip(todo, self._run(todo), strict=True):
                self.cache[x] = self._point(x, rec, role)
                self.path.append(self.cache[x])
            if self.progress is not None:
                self.progress(self)
        return [self.cache[p] for p in points]

    def _run(self, points: list[tuple[float, ...]]) -> list[dict]:
        from camtrain.study.batch import BatchJob, run_batch
        from camtrain.study.executors import Job, run_case
        from camtrain.study.sweep_output import in_units

        params = tuple(v.param for v in self.variables)
        cases = []
        for x in points:
            cases.append(Case(self._index, tuple((v.name, float(xi)) for v, xi in
                                                 zip(self.variables, x, strict=True))))
            self._index += 1
        jobs = getattr(self.executor, "jobs", None) or 1
        if self.route.batch:
            size = max(1, -(-len(cases) // jobs))
            work = [BatchJob(self.raw, params, tuple(cases[i:i + size]), self.name,
                             self.base_dir, frozenset(), self.key)
                    for i in range(0, len(cases), size)]
            records = [r for out in self.executor.map(run_batch, work) for r in out]
        else:
            work = [Job(self.raw, params, c, self.name, self.base_dir, False, self.key)
                    for c in cases]
            designed = any(v.param.path.startswith("design.") for v in self.variables)
            records = list(self.executor.map(run_designed_case if designed else run_case,
                                             work))
        by_index = {r["index"]: in_units(r, "deck") for r in records}
        return [by_index[c.index] for c in cases]

    def _point(self, x: tuple[float, ...], rec: dict, role: str) -> Point:
        metrics = dict(rec["metrics"])
        if any(c.kind in ("area", "concave", "lambda") for c in self.constraints):
            metrics.update(_derived(self, x, metrics, rec.get("designed_lift")))
        point = Point(x, rec["status"], rec["message"], metrics, role=role,
                      iteration=self.iteration, designed_lift=rec.get("designed_lift"))
        value = metrics.get(self.objective, (math.nan,))[0]
        point.objective = float(value) if rec["status"] in ("ok", "lost_contact") else math.nan
        datum = self.datum.metrics if self.datum is not None else None
        point.margins = tuple(c.value(metrics, datum) for c in self.constraints)
        return point


def _derived(problem: Problem, x: tuple[float, ...], metrics: dict,
             designed: dict | None = None) -> dict:
    """Metrics a constraint needs that a run does not give (or a failed case lacks): the
    valve-open area, the film parameter, and the smallest cam radius of curvature from the
    lift law and the kinematics kernel without the geometry checks (a case whose concave
    flank stopped it still has a margin, negative, for the optimiser to step back by)."""
    import numpy as np

    from camtrain.study.case_model import build_case_model
    from camtrain.units import from_si

    out = {}
    case = Case(-1, tuple((v.name, float(xi)) for v, xi in zip(problem.variables, x,
                                                                 strict=True)))
    try:
        model = build_case_model(problem.raw, [v.param for v in problem.variables], case,
                                 problem.name, problem.base_dir, problem.key)
    except Exception:  # noqa: BLE001 - an invalid case has no derived metrics either
        return out
    from camtrain.tabulate.lift import lift_curve

    if designed is not None:      # the case's own lift, designed from its events
        from camtrain.deck.schema_lift import Lift
        from camtrain.deck.schema_lift_spline import Spline
        from camtrain.units import to_si

        spline = Spline(degree=designed["degree"],
                        knots=tuple(to_si(v, "deg") for v in designed["knots"]),
                        coefficients=tuple(to_si(v, "mm") for v in designed["coefficients"]))
        model = dataclasses.replace(model, lift=Lift(form="spline", spline=spline))
    curve = lift_curve(model.lift, model.solver.angle_points)
    step = 2.0 * np.pi / curve.theta.size
    out["open_area"] = (float(from_si(np.sum(curve.lift) * step, "mm·deg")), "mm·deg")
    if "film_min" in metrics and model.lubricant is not None:
        out["film_parameter_min"] = (_film_parameter(metrics, model), "-")
    if "cam_radius_min" not in metrics:
        rc = _cam_radius_min(model, curve)
        if rc is not None:
            out["cam_radius_min"] = (float(from_si(rc, "mm")), "mm")
    return out


def run_designed_case(job) -> dict:
    """A case whose variables include [design] fields: its lift is designed from its events
    (:mod:`camtrain.design`), then it runs as an ordinary case; the record also carries the
    designed ``[lift.spline]`` (deck units). Events no lift can meet make a failed case."""
    from camtrain.design.command import design_raw
    from camtrain.errors import CamtrainError
    from camtrain.study.executors import Job, run_case
    from camtrain.study.sweep import case_raw

    try:
        raw = design_raw(case_raw(job.raw, list(job.params), job.case), job.name,
                         job.base_dir).raw
    except CamtrainError as exc:
        return {"index": job.case.index, "values": job.case.as_dict(), "status": "failed",
                "message": f"{type(exc).__name__}: {exc}", "metrics": {}, "curves": None}
    record = run_case(Job(raw, (), Case(job.case.index, ()), job.name, job.base_dir))
    record.update(values=job.case.as_dict(), designed_lift=raw["lift"]["spline"])
    return record


def _film_parameter(metrics: dict, model) -> float:
    from camtrain.units import UNITS

    value, unit = metrics["film_min"]
    return float(value * UNITS[unit][0] / model.lubricant.roughness)


def _cam_radius_min(model, curve) -> float | None:
    """min r_c [m] of a translating flat or domed follower, without the geometry checks."""
    import numpy as np

    from camtrain.mechanisms.translating import translating_contact

    mech = model.mechanism
    if mech.type not in ("flat", "domed"):
        return None
    flat = mech.type == "flat"
    fields = translating_contact(curve.theta, curve.lift, curve.d1, curve.d2,
                                 base_radius=model.cam.base_radius,
                                 follower_radius=np.inf if flat else mech.follower_radius,
                                 offset=0.0 if flat else mech.offset, omega=model.speed.omega)
    return float(np.min(fields["cam_radius"]))
