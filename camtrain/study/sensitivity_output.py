"""A sensitivity study's files: indices.csv / indices.md, convergence.csv, distribution.csv and
the plots (indices.png, convergence.png, distribution.png), metrics in the deck's units."""
from __future__ import annotations

import csv
import io
import math
from pathlib import Path

from camtrain.report.tables import atomic_write

#: metrics drawn in the plots (all of them are in the tables)
PLOT_METRICS = 9


def rows_csv(rows: list[dict]) -> str:
    """Rows of dicts as CSV: the columns in order of first appearance, floats to full
    precision, None as an empty cell."""
    columns: list[str] = []
    for row in rows:
        columns += [k for k in row if k not in columns]
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(columns)
    for row in rows:
        w.writerow(["" if row.get(c) is None else (repr(row[c]) if isinstance(row[c], float)
                                                    else row[c]) for c in columns])
    return buf.getvalue()


def markdown(report) -> str:
    """The indices as a table a person reads, inputs ranked by their total index (Sobol) or mu*
    (Morris) within each metric; the distribution of each metric below."""
    study = report.study
    sobol = study.method == "sobol"
    lines = [f"# Sensitivity: {study.sweep.name}", "",
             f"{study.method.capitalize()} study, {study.samples} "
             + ("base samples" if sobol else "trajectories")
             + f", {study.evaluations} cases, seed {study.seed}. Inputs:", ""]
    lines += [f"- {i.name} ({i.param.path}): {i.describe()}" for i in study.inputs]
    head = ("| metric | input | S1 | ± | ST | ± |" if sobol
            else "| metric | input | mu* | ± | mu | sigma |")
    lines += ["", head, "|---|---|---:|---:|---:|---:|"]
    key = "ST" if sobol else "mu_star"
    for metric in dict.fromkeys(r["metric"] for r in report.indices):
        rows = sorted((r for r in report.indices if r["metric"] == metric),
                      key=lambda r: -abs(r[key]))
        for r in rows:
            cells = ((r["S1"], r["S1_conf"], r["ST"], r["ST_conf"]) if sobol
                     else (r["mu_star"], r["mu_star_conf"], r["mu"], r["sigma"]))
            lines.append(f"| {metric} [{r['unit']}] | {r['input']} | "
                         + " | ".join(f"{c:.3g}" for c in cells) + " |")
    for metric, why in report.skipped.items():
        lines.append(f"| {metric} | (not estimated: {why}) | | | | |")
    lines += cost_lines(report)
    lines += ["", "| metric | mean | sd | 5 % | 50 % | 95 % |", "|---|---:|---:|---:|---:|---:|"]
    for d in report.distribution:
        if d.get("cases"):
            lines.append(f"| {d['metric']} [{d['unit']}] | " + " | ".join(
                f"{d[k]:.4g}" for k in ("mean", "std", "p05", "p50", "p95")) + " |")
    return "\n".join(lines) + "\n"


def cost_lines(report) -> list[str]:
    """What a narrower interval costs: the widest interval of a Sobol' study at its cases, and
    the cases (and time at this run's pace) for half its width, since the bootstrap interval
    narrows as one over the square root of the cases."""
    if report.study.method != "sobol" or not report.indices:
        return []
    widest = max(report.indices, key=lambda r: max(r["S1_conf"], r["ST_conf"]))
    width = max(widest["S1_conf"], widest["ST_conf"])
    cases = report.study.evaluations
    pace = report.seconds_per_case
    took = f" ({cases * pace:.3g} s)" if pace else ""
    more = f" (about {4 * cases * pace:.3g} s)" if pace else ""
    return ["", f"Accuracy: the widest interval is ±{width:.3g} ({widest['input']} on "
            f"{widest['metric']}) at {cases} cases{took}; half as wide takes about "
            f"{4 * cases} cases{more}."]


def write_outputs(report, out_dir: Path, plots: bool = True) -> list[Path]:
    written = []
    for name, rows in (("indices.csv", report.indices), ("convergence.csv", report.convergence),
                       ("distribution.csv", report.distribution)):
        atomic_write(out_dir / name, rows_csv(rows))
        written.append(out_dir / name)
    atomic_write(out_dir / "indices.md", markdown(report))
    written.append(out_dir / "indices.md")
    if plots and report.indices:
        (out_dir / "plots").mkdir(exist_ok=True)
        written += [indices_plot(report, out_dir / "plots" / "indices.png"),
                    convergence_plot(report, out_dir / "plots" / "convergence.png")]
    if plots and report.distribution:
        (out_dir / "plots").mkdir(exist_ok=True)
        written.append(distribution_plot(report, out_dir / "plots" / "distribution.png"))
    return written


def _grid(plt, n: int, title: str):
    cols = min(3, n)
    rows = math.ceil(n / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.6 * cols, 3.4 * rows), squeeze=False)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    fig.suptitle(title, fontsize=10)
    return fig, list(axes.flat)


def _saved(plt, fig, path: Path) -> Path:
    """Lay the figure out, write it to ``path`` and free it."""
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def _pyplot():
    from camtrain.report.plots import _pyplot as pyplot

    return pyplot()


def _metrics(rows: list[dict]) -> list[str]:
    return list(dict.fromkeys(r["metric"] for r in rows))[:PLOT_METRICS]


def indices_plot(report, path: Path) -> Path:
    """Bars of each metric's indices with their confidence intervals."""
    plt = _pyplot()
    sobol = report.study.method == "sobol"
    metrics = _metrics(report.indices)
    fig, axes = _grid(plt, len(metrics), f"{Path(report.study.sweep.name).name}: "
                      + ("Sobol' indices (bars: confidence intervals)" if sobol
                         else "Morris mu* (per unit of probability)"))
    for ax, metric in zip(axes, metrics, strict=False):
        rows = [r for r in report.indices if r["metric"] == metric]
        names = [r["input"] for r in rows]
        y = range(len(rows))
        if sobol:
            ax.barh([k + 0.2 for k in y], [r["S1"] for r in rows], 0.4,
                    xerr=[r["S1_conf"] for r in rows], label="first order S1")
            ax.barh([k - 0.2 for k in y], [r["ST"] for r in rows], 0.4,
                    xerr=[r["ST_conf"] for r in rows], label="total ST")
        else:
            ax.barh(list(y), [r["mu_star"] for r in rows], 0.6,
                    xerr=[r["mu_star_conf"] for r in rows], label="mu*")
        ax.set_yticks(list(y), names, fontsize=8)
        ax.set_title(f"{metric} [{rows[0]['unit']}]", fontsize=9)
        ax.legend(fontsize=7)
    return _saved(plt, fig, path)


def convergence_plot(report, path: Path) -> Path:
    """Each index against the model evaluations of the leading part of the sample, with its
    confidence band: what a narrower interval costs."""
    plt = _pyplot()
    sobol = report.study.method == "sobol"
    key, conf = ("ST", "ST_conf") if sobol else ("mu_star", "mu_star_conf")
    metrics = _metrics(report.convergence)
    each = f", {report.seconds_per_case * 1e3:.3g} ms per case" if report.seconds_per_case \
        else ""
    fig, axes = _grid(plt, len(metrics), f"{Path(report.study.sweep.name).name}: "
                      f"{'total index ST' if sobol else 'mu*'} against cases run{each}")
    for ax, metric in zip(axes, metrics, strict=False):
        rows = [r for r in report.convergence if r["metric"] == metric]
        for name in dict.fromkeys(r["input"] for r in rows):
            mine = [r for r in rows if r["input"] == name]
            x = [r["evaluations"] for r in mine]
            v = [r[key] for r in mine]
            c = [r[conf] for r in mine]
            line, = ax.plot(x, v, marker=".", label=name)
            ax.fill_between(x, [a - b for a, b in zip(v, c, strict=True)],
                            [a + b for a, b in zip(v, c, strict=True)],
                            color=line.get_color(), alpha=0.2)
        ax.set_xscale("log")
        ax.set_xlabel("cases run", fontsize=8)
        ax.set_title(f"{metric} [{rows[0]['unit']}]", fontsize=9)
        ax.legend(fontsize=7)
    return _saved(plt, fig, path)


def distribution_plot(report, path: Path) -> Path:
    """A histogram of each metric over the independent draws of the inputs, with its 5 %,
    50 % and 95 % quantiles."""
    import numpy as np

    from camtrain.study.sensitivity_analysis import independent_rows, metric_values

    plt = _pyplot()
    study = report.study
    names = [d["metric"] for d in report.distribution if d.get("cases")][:PLOT_METRICS]
    if not names:
        return path
    rows = independent_rows(study.method, len(study.inputs), study.evaluations)
    fig, axes = _grid(plt, len(names), f"{Path(study.sweep.name).name}: distribution of each "
                      f"metric ({rows.size} draws of the inputs)")
    for ax, (name, (unit, y)) in zip(axes, metric_values(report.records, names).items(),
                                     strict=False):
        y = y[rows]
        y = y[np.isfinite(y)]
        ax.hist(y, bins=min(50, max(10, int(np.sqrt(y.size)))), color="0.6")
        for q in np.quantile(y, (0.05, 0.5, 0.95)):
            ax.axvline(q, color="k", lw=0.8, ls="--")
        ax.set_xlabel(f"{name} [{unit}]", fontsize=8)
    return _saved(plt, fig, path)
