"""Sensitivity and uncertainty of a deck's metrics to uncertain inputs (`camtrain sensitivity`).

An uncertain input is a deck field (addressed as a sweep addresses it: an alias such as
``viscosity`` or a dotted path) with a distribution: uniform, log-uniform or normal, in the
field's deck unit or relative to the deck's own value (a bound written with ``%``). SALib draws
the sample in the unit hypercube (Saltelli's extension of the Sobol' sequence for variance-based
indices, Morris trajectories for screening); each input's inverse distribution function maps it
to deck values, and the cases run through the sweep machinery (:func:`camtrain.study.runner.
run_cases`: the vectorised batch where the swept fields allow it, local processes or a Dask
cluster, sweep.csv kept current and ``--resume``). :mod:`camtrain.study.sensitivity_analysis`
turns the metrics into indices, their convergence and the metrics' distributions.

The sample depends only on the method, the number of samples, the number of inputs and the
seed: a study rerun with ``--resume`` finds its finished cases again, and one run with more
samples (same seed) begins with the cases of the smaller one.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

from camtrain.errors import InputError, Problem
from camtrain.study.sweep import Case, Parameter, check_values, resolve_path

#: distributions of an input: option name -> meaning of its two numbers A:B
DISTRIBUTIONS = {"uniform": "LOW:HIGH", "log-uniform": "LOW:HIGH", "normal": "MEAN:SD",
                 "relative": "-P%:+P%"}
METHODS = ("sobol", "morris")
#: a normal input must stay inside its field's range to this many standard deviations
NORMAL_REACH = 5.0
#: Morris levels reach the ends of the unit interval, where a normal's quantile is infinite:
#: its levels span the normal truncated at this many standard deviations
MORRIS_NORMAL_SPAN = 3.0
MORRIS_LEVELS = 4


@dataclass(frozen=True)
class Input:
    """One uncertain deck field: its parameter (name, path, unit, datum) and distribution.

    ``a``, ``b``: LOW and HIGH (uniform, log-uniform) or MEAN and SD (normal), in the field's
    deck unit; ``given``: the text as written (``-10%:+10%``)."""

    param: Parameter
    distribution: str
    a: float
    b: float
    given: str = ""

    @property
    def name(self) -> str:
        return self.param.name

    def quantile(self, q, morris: bool = False):
        """Deck values at probabilities ``q`` (the inverse distribution function)."""
        import numpy as np
        from scipy import stats

        q = np.asarray(q, dtype=float)
        if self.distribution == "uniform":
            return self.a + q * (self.b - self.a)
        if self.distribution == "log-uniform":
            return np.exp(math.log(self.a) + q * math.log(self.b / self.a))
        if morris:
            lo, hi = stats.norm.cdf([-MORRIS_NORMAL_SPAN, MORRIS_NORMAL_SPAN])
            q = lo + q * (hi - lo)
        return stats.norm.ppf(q, loc=self.a, scale=self.b)

    def describe(self) -> str:
        if self.distribution == "normal":
            return f"normal, mean {self.a:.6g} {self.param.unit}, sd {self.b:.6g} {self.param.unit}"
        return f"{self.distribution} {self.a:.6g} to {self.b:.6g} {self.param.unit}"

    def as_dict(self) -> dict:
        return {"name": self.name, "path": self.param.path, "unit": self.param.unit,
                "datum": self.param.datum, "distribution": self.distribution,
                "a": self.a, "b": self.b, "given": self.given}


def _number(text: str, option: str, spec: str) -> tuple[float, bool]:
    """A number and whether it was written as a percentage."""
    t = text.strip()
    try:
        x = float(t.rstrip("%"))
    except ValueError:
        raise InputError(Problem(option, f"{t!r} is not a number", spec,
                                 DISTRIBUTIONS[option[2:]])) from None
    if not math.isfinite(x):
        raise InputError(Problem(option, "values must be finite", spec))
    return x, t.endswith("%")


def parse_input(raw: dict, name: str, kind: str, text: str) -> Input:
    """``-p NAME --uniform A:B`` (or ``--log-uniform``, ``--normal MEAN:SD``, ``--relative
    -P%:+P%``) -> a checked Input; a number written with % is relative to the deck's value."""
    option = f"--{kind}"
    if kind not in DISTRIBUTIONS:
        raise InputError(Problem("--param", f"unknown distribution {kind}", name,
                                 ", ".join("--" + k for k in DISTRIBUTIONS)))
    param = resolve_path(raw, name)
    if param.integer:
        raise InputError(Problem("--param", f"{param.path} takes whole numbers: it cannot be "
                                 "an uncertain continuous input", name, "a real-valued field"))
    parts = text.split(":")
    if len(parts) != 2:
        raise InputError(Problem(option, "needs two numbers", text, DISTRIBUTIONS[kind]))
    (a, rel_a), (b, rel_b) = (_number(p, option, text) for p in parts)
    if kind == "relative":
        rel_a = rel_b = True
        kind = "uniform"
    if (rel_a or rel_b) and param.datum is None:
        raise InputError(Problem(option, f"{name} has no value in the deck to take a "
                                 "percentage of", text, "absolute values in " + param.unit))
    if rel_a:
        a = param.datum * (1.0 + a / 100.0)
    if rel_b:
        b = param.datum * (b / 100.0 if kind == "normal" else 1.0 + b / 100.0)
    return _checked(Input(param, kind, a, b, text), option)


def _checked(inp: Input, option: str) -> Input:
    """Bounds ordered and inside the field's range (a normal to NORMAL_REACH deviations)."""
    if inp.distribution == "normal":
        if not inp.b > 0.0:
            raise InputError(Problem(option, "the standard deviation must be positive",
                                     inp.given, "MEAN:SD with SD > 0"))
        ends = (inp.a - NORMAL_REACH * inp.b, inp.a + NORMAL_REACH * inp.b)
        try:
            check_values(_with_values(inp.param, ends), option)
        except InputError:
            raise InputError(Problem(option, f"a normal {inp.describe()} leaves the range of "
                                     f"{inp.param.path} within {NORMAL_REACH:g} standard "
                                     "deviations", inp.given,
                                     inp.param.info.expected_text(),
                                     "narrow it, or use --uniform or --log-uniform")) from None
        return inp
    if not inp.b > inp.a:
        raise InputError(Problem(option, "the upper bound must exceed the lower bound",
                                 inp.given, DISTRIBUTIONS[option[2:]]))
    if inp.distribution == "log-uniform" and not inp.a > 0.0:
        raise InputError(Problem(option, "a log-uniform input needs positive bounds", inp.given,
                                 "0 < LOW < HIGH"))
    check_values(_with_values(inp.param, (inp.a, inp.b)), option)
    return inp


def _with_values(p: Parameter, values: tuple[float, ...]) -> Parameter:
    return Parameter(p.name, p.path, p.unit, p.integer, p.datum, tuple(values), p.info)


# --------------------------------------------------------------------------- the sample

def check_samples(method: str, samples: int) -> int:
    """Sobol: a power of two (the balance of the Sobol' sequence, and the convergence ladder
    reads its leading powers of two); Morris: at least two trajectories."""
    if method not in METHODS:
        raise InputError(Problem("--method", "is not a method", method, " or ".join(METHODS)))
    if method == "sobol" and (samples < 4 or samples & (samples - 1)):
        low = 1 << max(2, samples.bit_length() - 1)
        raise InputError(Problem("--samples", "the Sobol' base sample must be a power of two",
                                 samples, "4, 8, ..., 1024, 2048, ...",
                                 f"e.g. {low} or {low * 2}"))
    if method == "morris" and samples < 2:
        raise InputError(Problem("--samples", "Morris needs at least two trajectories", samples,
                                 ">= 2"))
    if samples > 1 << 20:
        raise InputError(Problem("--samples", "is too many", samples, "at most 1048576"))
    return samples


def problem(inputs: list[Input]) -> dict:
    """SALib's problem: every input on the unit interval (the distributions are applied by
    :meth:`Input.quantile`, so Morris' steps are in probability, comparable between inputs)."""
    return {"num_vars": len(inputs), "names": [i.name for i in inputs],
            "bounds": [[0.0, 1.0]] * len(inputs)}


def unit_sample(method: str, inputs: list[Input], samples: int, seed: int):
    """The sample in the unit hypercube: Saltelli's design from the scrambled Sobol' sequence
    (N (D + 2) rows, first-order and total indices) or N Morris trajectories (N (D + 1) rows)."""
    import warnings

    if method == "sobol":
        from SALib.sample import sobol

        return sobol.sample(problem(inputs), samples, calc_second_order=False, scramble=True,
                            seed=seed)
    from SALib.sample import morris

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        return morris.sample(problem(inputs), samples, num_levels=MORRIS_LEVELS, seed=seed)


def deck_sample(method: str, inputs: list[Input], unit):
    """The unit sample mapped to deck values, column by column."""
    import numpy as np

    return np.column_stack([inp.quantile(unit[:, j], morris=method == "morris")
                            for j, inp in enumerate(inputs)])


@dataclass
class Study:
    """A prepared study: the sweep that runs its cases and what the analysis needs."""

    sweep: object              # camtrain.study.runner.Sweep
    inputs: list[Input]
    method: str
    samples: int
    seed: int
    unit: object = field(repr=False)    # (cases, inputs) in [0, 1]
    metrics: tuple[str, ...] = ()

    @property
    def evaluations(self) -> int:
        return len(self.sweep.cases)

    def as_dict(self) -> dict:
        return {"method": self.method, "samples": self.samples, "seed": self.seed,
                "evaluations": self.evaluations, "metrics": list(self.metrics),
                "inputs": [i.as_dict() for i in self.inputs]}


def prepare(deck: str | Path, specs: list[tuple[str, str, str]], *, method: str = "sobol",
            samples: int = 1024, seed: int = 1, metrics: tuple[str, ...] = (),
            sets: list[str] = ()) -> Study:
    """Read the deck, check every input (``specs`` = [(name, distribution, 'A:B')]) and draw
    the sample. Bad arguments raise InputError naming the option and value."""
    from camtrain.study.runner import Sweep, prepare_datum

    check_samples(method, samples)
    if not specs:
        raise InputError(Problem("--param", "no uncertain input", None,
                                 "at least one --param NAME with a distribution"))
    base = prepare_datum(deck, sets)
    inputs: list[Input] = []
    for name, kind, text in specs:
        inp = parse_input(base.raw, name, kind, text)
        if any(i.param.path == inp.param.path for i in inputs):
            raise InputError(Problem("--param", f"{inp.param.path} is given twice", name))
        inputs.append(inp)
    check_metrics(base, metrics)
    unit = unit_sample(method, inputs, samples, seed)
    values = deck_sample(method, inputs, unit)
    params = [_with_values(i.param, tuple(values[:, j].tolist())) for j, i in enumerate(inputs)]
    names = [p.name for p in params]
    cases = [Case(k, tuple(zip(names, row, strict=True))) for k, row in enumerate(values.tolist())]
    sweep = Sweep(base.raw, base.name, base.base_dir, base.sha256, params, base.fixed, cases,
                  zipped=True)
    return Study(sweep, inputs, method, samples, seed, unit, tuple(metrics))



def check_metrics(datum, metrics: tuple[str, ...]) -> None:
    """The metrics asked for are metrics of the datum deck's run (checked by running it once,
    before any case runs or any file is written). A datum deck that does not run leaves the
    check to the cases, which report why."""
    if not metrics:
        return
    from camtrain.errors import CamtrainError
    from camtrain.runner import run_plan
    from camtrain.study.case_model import datum_model

    try:
        result = run_plan(datum_model(datum.raw, datum.name, datum.base_dir))
    except CamtrainError:
        return
    problems = []
    for name in metrics:
        try:
            result.metric(name, field="--metric")
        except InputError as exc:
            problems += exc.problems
    if problems:
        raise InputError(problems)
