"""camtrain's prediction of measured data sets for given deck constants (`camtrain fit`).

A prediction for one set of constants is a list of runs: one per data set against angle (the
run's column read at the data's angles) and one per row of a data set against speed (the run's
metric). Every run is a sweep case (the validated datum deck with the constants, and the speed,
replaced: :func:`camtrain.study.case_model.build_case_model`), and the runs of several sets of
constants (the columns of a finite-difference Jacobian) go to the executor together, so that
local processes or a Dask cluster share them.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.errors import CamtrainError, InputError, Problem
from camtrain.study.fit_data import DataSet
from camtrain.study.sweep import Case, Parameter, bounded, parse_bounds, resolve_path
from camtrain.units import UNITS


@dataclass(frozen=True)
class Constant:
    """A deck constant to calibrate: its parameter (datum: the start) and bounds (deck unit)."""

    param: Parameter
    low: float
    high: float

    @property
    def name(self) -> str:
        return self.param.name


def parse_constant(raw: dict, name: str, text: str) -> Constant:
    """``-p NAME --bounds LOW:HIGH``: a constant, its start the deck's value (exit 2 if the
    field is not a real number, the bounds are not ordered or the start lies outside them)."""
    param = resolve_path(raw, name)
    if param.integer:
        raise InputError(Problem("--param", f"{param.path} takes whole numbers and cannot be "
                                 "fitted", name, "a real-valued field"))
    low, high = parse_bounds("--bounds", text)
    bounded(param, low, high, "--bounds")
    if param.datum is None or not low <= param.datum <= high:
        raise InputError(Problem("--bounds", f"the deck's {param.path} = {param.datum} "
                                 f"{param.unit} (the start of the fit) is outside the bounds",
                                 text, "bounds around the deck's value"))
    return Constant(param, low, high)


@dataclass(frozen=True)
class FitJob:
    """One run of a prediction, picklable: the data set's datum deck, the values of the
    constants (and speed), and what to read from the run."""

    raw: dict
    params: tuple[Parameter, ...]
    case: Case
    name: str
    base_dir: str
    key: str
    #: names of the columns (against angle) or metrics (against speed) to read
    wanted: tuple[str, ...]
    axis: str


def run_fit_case(job: FitJob) -> dict:
    """The wanted columns (with their axis) or metrics of one run, in SI, or the failure."""
    from camtrain.runner import run_plan
    from camtrain.study.case_model import build_case_model

    try:
        result = run_plan(build_case_model(job.raw, list(job.params), job.case, job.name,
                                           job.base_dir, job.key))
    except CamtrainError as exc:
        return {"error": f"{type(exc).__name__}: {exc}"}
    try:    # the data file names the quantities: the run is asked for them by name
        if job.axis == "speed":
            metrics = [result.metric(n, field="--data") for n in job.wanted]
            return {"metrics": {n: (m.value, m.unit)
                                for n, m in zip(job.wanted, metrics, strict=True)}}
        columns = [result.column(n, field="--data", axis=job.axis) for n in job.wanted]
    except InputError as exc:
        return {"invalid": exc.problems}
    return {"axis": np.asarray(result[job.axis]), "columns": {
        n: (np.asarray(c.values), c.unit) for n, c in zip(job.wanted, columns, strict=True)}}


@dataclass
class Source:
    """A data set with the datum deck it runs (its own ``sets`` applied) and its speed field."""

    data: DataSet
    raw: dict
    key: str
    speed: Parameter | None = None


class Predictor:
    """camtrain's values of every data point for sets of constants (SI units)."""

    def __init__(self, datum, constants: list[Constant], datasets: list[DataSet], executor):
        from camtrain.study.assign import apply_fixed, parse_assignment
        from camtrain.study.case_model import datum_key, datum_model

        self.datum, self.constants, self.executor = datum, constants, executor
        self.sources = []
        for data in datasets:
            raw = apply_fixed(datum.raw, [parse_assignment(datum.raw, s) for s in data.sets])
            key = datum_key(raw, datum.name, datum.base_dir)
            datum_model(raw, datum.name, datum.base_dir, key)   # an invalid set stops here
            speed = resolve_path(raw, "speed") if data.by_speed else None
            self.sources.append(Source(data, raw, key, speed))

    def _jobs(self, theta: np.ndarray) -> list[FitJob]:
        params = tuple(c.param for c in self.constants)
        values = tuple((c.name, float(t)) for c, t in zip(self.constants, theta, strict=True))
        jobs = []
        for s in self.sources:
            wanted = tuple(q.name for q in s.data.series)
            common = (self.datum.name, self.datum.base_dir, s.key, wanted, s.data.axis)
            if s.speed is None:
                jobs.append(FitJob(s.raw, params, Case(0, values), *common))
                continue
            factor = UNITS[s.speed.unit][0]
            for x in s.data.x_si():
                jobs.append(FitJob(s.raw, params + (s.speed,),
                                   Case(0, values + ((s.speed.name, float(x / factor)),)),
                                   *common))
        return jobs

    def predict(self, thetas: list[np.ndarray]) -> list[list[np.ndarray]]:
        """For each set of constants: one array per (data set, quantity), in SI."""
        per = len(self._jobs(thetas[0]))
        jobs = [j for t in thetas for j in self._jobs(t)]
        out = list(self.executor.map(run_fit_case, jobs))
        return [self._read(out[k * per:(k + 1) * per], t) for k, t in enumerate(thetas)]

    def _read(self, runs: list[dict], theta: np.ndarray) -> list[np.ndarray]:
        failed = next((r["error"] for r in runs if "error" in r), None)
        if failed:
            at = ", ".join(f"{c.name} = {t:.6g} {c.param.unit}"
                           for c, t in zip(self.constants, theta, strict=True))
            raise CamtrainError(f"the deck does not run with {at}: {failed}")
        out, k = [], 0
        for s in self.sources:
            size = 1 if s.speed is None else len(s.data.x)
            invalid = next((r["invalid"] for r in runs[k:k + size] if "invalid" in r), None)
            if invalid:
                raise InputError(invalid, source=s.data.path)
            if s.speed is None:
                run = runs[k]
                k += 1
                out += [self._at_angles(s, q, run) for q in s.data.series]
                continue
            mine = runs[k:k + len(s.data.x)]
            k += len(s.data.x)
            out += [np.array([self._metric(s, q, r) for r in mine]) for q in s.data.series]
        return out

    @staticmethod
    def _at_angles(source: Source, quantity, run: dict) -> np.ndarray:
        values, unit = run["columns"][quantity.name]
        _same_unit(source, quantity, unit)
        x = source.data.x_si()
        axis = run["axis"]
        if x.min() < axis.min() - 1e-9 or x.max() > axis.max() + 1e-9:
            raise InputError(Problem("--data", f"angles outside the run's grid "
                                     f"({np.degrees(axis.min()):.6g} to "
                                     f"{np.degrees(axis.max()):.6g} deg)",
                                     f"{np.degrees(x.min()):.6g} to {np.degrees(x.max()):.6g}"),
                             source=source.data.path)
        return np.interp(x, axis, values)

    @staticmethod
    def _metric(source: Source, quantity, run: dict) -> float:
        value, unit = run["metrics"][quantity.name]
        _same_unit(source, quantity, unit)
        return value


def _same_unit(source: Source, quantity, si_unit: str) -> None:
    if UNITS[quantity.unit][1] != si_unit:
        raise InputError(Problem("--data", f"the unit of {quantity.name} does not measure what "
                                 f"camtrain computes ({si_unit} in SI)", quantity.unit,
                                 f"a unit of {si_unit}"), source=source.data.path)
