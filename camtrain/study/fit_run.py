"""`camtrain fit` end to end: read the data and constants, fit, write the tables, the
calibrated deck and the plots of data against prediction before and after."""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from camtrain.errors import InputError, Problem
from camtrain.report.tables import atomic_write
from camtrain.study.fit import Fit, fit
from camtrain.study.fit_data import read_data
from camtrain.study.fit_model import Predictor, parse_constant


@dataclass
class FitReport:
    """A fit and the files written; :meth:`frame` gives its tables as pandas DataFrames."""

    fit: Fit
    deck: str
    written: list[Path] = field(default_factory=list)

    def frame(self, table: str = "constants"):
        """``constants`` (values and intervals), ``correlation``, ``singular`` (relative
        singular values and their directions) or ``residuals``."""
        import pandas as pd

        f = self.fit
        names = [c.name for c in f.constants]
        if table == "constants":
            return pd.DataFrame(f.rows()).set_index("constant")
        if table == "correlation":
            return pd.DataFrame(f.correlation, index=names, columns=names)
        if table == "singular":
            return pd.DataFrame(f.directions, columns=names).assign(relative=f.singular)
        return pd.DataFrame(residual_rows(f))


def run_fit(deck: str | Path, data: list[str | Path], specs: list[tuple[str, str]], out_dir,
            *, sets: list[str] = (), jobs: int | None = 1, scheduler=None,
            confidence: float = 0.95, plots: bool = True, progress=None) -> FitReport:
    """Fit the constants ``specs`` = [(name, 'LOW:HIGH')] of ``deck`` to the data files."""
    from camtrain.study.executors import make_executor
    from camtrain.study.runner import prepare_datum

    if not specs:
        raise InputError(Problem("--param", "nothing to fit", None,
                                 "at least one --param NAME --bounds LOW:HIGH"))
    if not data:
        raise InputError(Problem("--data", "no measured data", None, "one or more CSV files"))
    if not 0.5 <= confidence < 1.0:
        raise InputError(Problem("--confidence", "is not a confidence level", confidence,
                                 "a probability from 0.5 to below 1"))
    datum = prepare_datum(deck, sets)
    constants = [parse_constant(datum.raw, name, text) for name, text in specs]
    if len({c.param.path for c in constants}) != len(constants):
        raise InputError(Problem("--param", "a constant is given twice",
                                 ", ".join(n for n, _ in specs)))
    datasets = [read_data(p) for p in data]
    points = sum(d.points for d in datasets)
    if points <= len(constants):
        raise InputError(Problem("--data", f"{points} data points cannot fix "
                                 f"{len(constants)} constants", points, "more points than constants"))
    executor = make_executor(jobs, scheduler)
    try:
        result = fit(Predictor(datum, constants, datasets, executor), confidence, progress)
    finally:
        executor.close()
    report = FitReport(result, datum.name)
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    report.written += write_tables(result, out_dir)
    report.written.append(write_deck(datum, result, out_dir / "calibrated.toml"))
    if plots:
        report.written.append(fit_plot(result, out_dir / "fit.png", Path(datum.name).name))
    return report


def residual_rows(f: Fit) -> list[dict]:
    """Every data point: data, prediction before and after, residual, in the data's units."""
    from camtrain.units import UNITS

    rows, k = [], 0
    for d in f.datasets:
        for q in d.series:
            factor = UNITS[q.unit][0]
            for x, y, b, a in zip(d.x, q.values, f.before[k] / factor, f.after[k] / factor,
                                  strict=True):
                rows.append({"data": d.label, "quantity": q.name, "unit": q.unit,
                             f"{d.axis}[{d.axis_unit}]": x, "measured": y, "before": float(b),
                             "after": float(a), "residual": float(a - y)})
            k += 1
    return rows


def write_tables(f: Fit, out_dir: Path) -> list[Path]:
    from camtrain.study.sensitivity_output import rows_csv as text

    names = [c.name for c in f.constants]
    singular = [{"relative_singular_value": float(s), **{n: float(v) for n, v in zip(
        names, row, strict=True)}} for s, row in zip(f.singular, f.directions, strict=True)]
    files = {"fit.csv": text(f.rows()), "residuals.csv": text(residual_rows(f)),
             "singular_values.csv": text(singular),
             "fit.json": json.dumps({
                 "confidence": f.confidence, "points": f.points, "evaluations": f.evaluations,
                 "rss": f.rss, "status": f.status, "constants": f.rows(),
                 "correlation": {a: {b: float(f.correlation[i, j]) for j, b in enumerate(names)}
                                 for i, a in enumerate(names)},
                 "not_identifiable": f.unidentifiable, "determined_combinations": f.combinations,
                 "poorly_determined": f.poorly_determined(),
                 "correlated": [{"constants": [a, b], "correlation": r}
                                for a, b, r in f.correlated()],
                 "at_bound": f.at_bound}, indent=2, allow_nan=True) + "\n"}
    for name, body in files.items():
        atomic_write(out_dir / name, body)
    return [out_dir / n for n in files]


def write_deck(datum, f: Fit, path: Path) -> Path:
    """The datum deck with the fitted constants written in (deck units), as the deck writer
    writes any deck, with a header saying what was fitted to what."""
    from camtrain.deck.load import validate
    from camtrain.deck.writer import save
    from camtrain.study.sweep import set_path

    raw = json.loads(json.dumps(datum.raw))
    for c, v in zip(f.constants, f.value, strict=True):
        set_path(raw, c.param.path, float(v))
    model = validate(raw, datum.name, Path(datum.base_dir))
    head = "\n".join([f"calibrated from {datum.name} by camtrain fit to "
                      + ", ".join(d.label for d in f.datasets) + ":"]
                     + [f"  {r['path']} = {r['value']:.6g} {r['unit']} "
                        + (f"± {r['half_width']:.3g} ({100 * f.confidence:g} %)"
                           if r["identifiable"] else "(not identifiable from these data)")
                        for r in f.rows()])
    return save(model, path, header=head)


def fit_plot(f: Fit, path: Path, title: str) -> Path:
    """Each measured quantity against its abscissa with camtrain's prediction before and
    after the fit."""
    from camtrain.report.plots import _pyplot
    from camtrain.units import UNITS

    plt = _pyplot()
    panels = [(d, q) for d in f.datasets for q in d.series]
    cols = min(2, len(panels))
    rows = -(-len(panels) // cols)
    fig, axes = plt.subplots(rows, cols, figsize=(5.5 * cols, 3.6 * rows), squeeze=False)
    for ax in axes.flat[len(panels):]:
        ax.set_visible(False)
    for k, (ax, (d, q)) in enumerate(zip(axes.flat, panels, strict=False)):
        factor = UNITS[q.unit][0]
        order = np.argsort(d.x)
        x = np.asarray(d.x)[order]
        ax.plot(x, np.asarray(q.values)[order], "k.", ms=3, label="measured")
        ax.plot(x, (f.before[k] / factor)[order], "--", color="0.5", label="before")
        ax.plot(x, (f.after[k] / factor)[order], "-", color="C3", label="after")
        ax.set_xlabel(f"{d.axis} [{d.axis_unit}]", fontsize=8)
        ax.set_ylabel(f"{q.name} [{q.unit}]", fontsize=8)
        ax.set_title(d.label, fontsize=9)
        ax.legend(fontsize=7)
    fig.suptitle(f"{title}: " + ", ".join(f"{r['constant']} {r['start']:.4g} → {r['value']:.4g} "
                                          f"{r['unit']}" for r in f.rows()), fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
