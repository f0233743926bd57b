"""Run a sensitivity study end to end: the cases through the sweep machinery, then the indices,
their convergence and the metrics' distributions, written as tables and plots.

The cases are those of a zipped sweep (:func:`camtrain.study.runner.run_cases`), so they run
as one vectorised batch where the swept fields allow it, on local processes (``jobs``) or a
Dask cluster (``scheduler``), with sweep.csv kept current and ``resume`` taking up an
interrupted study.
"""
from __future__ import annotations

import json
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from camtrain.errors import InputError, Problem
from camtrain.study import sensitivity_analysis as sa
from camtrain.study.sensitivity import MORRIS_LEVELS, Study, problem


@dataclass
class Report:
    """What a study found. The tables are lists of plain rows (one dict per row, values in
    the deck's units); :meth:`frame` gives any of them as a pandas DataFrame."""

    study: Study
    indices: list[dict] = field(default_factory=list)
    convergence: list[dict] = field(default_factory=list)
    distribution: list[dict] = field(default_factory=list)
    #: metrics whose indices could not be estimated, and why
    skipped: dict[str, str] = field(default_factory=dict)
    records: list[dict] = field(default_factory=list)
    route: object = None
    #: wall time per case of this run [s] (None when every case was reused)
    seconds_per_case: float | None = None
    reused: int = 0
    written: list[Path] = field(default_factory=list)

    def frame(self, table: str = "indices"):
        """``indices``, ``convergence``, ``distribution`` or ``samples`` (each case's inputs,
        status and metrics) as a pandas DataFrame."""
        import pandas as pd

        if table == "samples":
            return samples_frame(self.study, self.records)
        return pd.DataFrame(getattr(self, table))


def samples_frame(study: Study, records: list[dict]):
    """Each case: its inputs (deck units), status and metrics, one row per case."""
    import pandas as pd

    rows = []
    for r in sorted(records, key=lambda r: r["index"]):
        row = {"case": r["index"], **{f"{p.name}[{p.unit}]": r["values"][p.name]
                                       for p in study.sweep.params}, "status": r["status"]}
        row.update({f"{n}[{u}]": v for n, (v, u) in r["metrics"].items()})
        rows.append(row)
    return pd.DataFrame(rows).set_index("case")


def run_study(study: Study, out_dir: str | Path, *, jobs: int | None = 1, scheduler=None,
              resume: bool = False, confidence: float = 0.95, plots: bool = True,
              progress: Callable[[dict, int, int], None] | None = None) -> Report:
    """Run the study's cases (those finished in ``out_dir`` are kept with ``resume``), then
    estimate and write everything."""
    from camtrain.study.runner import run_cases

    out_dir = Path(out_dir)
    if not 0.5 <= confidence < 1.0:
        raise InputError(Problem("--confidence", "is not a confidence level", confidence,
                                 "a probability from 0.5 to below 1, e.g. 0.95"))
    start = time.perf_counter()
    outcome = run_cases(study.sweep, out_dir, jobs=jobs, scheduler=scheduler, resume=resume,
                        progress=progress)
    ran = len(outcome.records) - outcome.reused
    report = Report(study, records=outcome.records, route=outcome.route, reused=outcome.reused,
                    seconds_per_case=(time.perf_counter() - start) / ran if ran else None,
                    written=list(outcome.written))
    analyse(report, confidence)
    from camtrain.study.sensitivity_output import write_outputs

    report.written += write_outputs(report, out_dir, plots=plots)
    (out_dir / "sensitivity.json").write_text(json.dumps(
        study.as_dict() | {"confidence": confidence, "skipped": report.skipped},
        indent=2, default=str) + "\n", encoding="utf-8")
    report.written.append(out_dir / "sensitivity.json")
    return report


def analyse(report: Report, confidence: float) -> None:
    """Fill the report's tables from its records."""
    study = report.study
    metrics = list(study.metrics) or sa.varying_metrics(report.records)
    prob = problem(study.inputs)
    unit = np.asarray(study.unit)
    rows = sa.independent_rows(study.method, len(study.inputs), study.evaluations)
    seed = study.seed
    for name, (u, y) in sa.metric_values(report.records, metrics).items():
        report.distribution.append({"metric": name, "unit": u, **sa.distribution_row(y[rows])})
        why = sa.why_not(y)
        if why:
            report.skipped[name] = why
            continue
        head = {"metric": name, "unit": u}
        report.indices += [head | row for row in sa.indices(
            study.method, prob, unit, y, study.samples, confidence, seed, MORRIS_LEVELS)]
        for row in sa.convergence(study.method, prob, unit, y, study.samples, confidence, seed,
                                  MORRIS_LEVELS):
            seconds = None if report.seconds_per_case is None else \
                row["evaluations"] * report.seconds_per_case
            report.convergence.append(head | row | {"wall_time": seconds})
