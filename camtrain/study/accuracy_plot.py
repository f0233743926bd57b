"""Error against wall time for an accuracy study, with its Pareto front (accuracy.png).

matplotlib is imported only here, and only when a plot is written (Agg backend, no display).
"""
from __future__ import annotations

from pathlib import Path

#: Errors below this are drawn at this level (the finest rung's error against itself is 0).
ERROR_FLOOR = 1e-12


def pareto_front(points: list[tuple[float, float, object]]) -> list[tuple[float, float, object]]:
    """Points (time, error, label) not beaten on both time and error by another, fastest first."""
    front = []
    best = float("inf")
    for t, e, label in sorted(points, key=lambda p: (p[0], p[1])):
        if e < best:
            front.append((t, e, label))
            best = e
    return front


def study_points(report: dict) -> list[tuple[float, float, object]]:
    """(wall time, worst relative error, (knob, value)) of every successful rung."""
    out = []
    for knob, k in report["knobs"].items():
        for rung, err in zip(k["rungs"], k["worst_error"], strict=False):
            if rung["status"] == "ok" and err is not None:
                out.append((rung["wall_time"], err, (knob, rung["value"])))
    return out


def pareto_plot(report: dict, path: str | Path) -> Path:
    """Write the error-against-time plot of every knob, the front and the tolerance line."""
    path = Path(path)
    fig = pareto_figure(report)
    fig.savefig(path, dpi=120)
    return path


def zero_level(report: dict) -> float:
    """Where an error of exactly 0 is drawn on the log axis: a decade under the smallest
    non-zero error (or the tolerance), never below ERROR_FLOOR."""
    errors = [e for k in report["knobs"].values() for e in k["worst_error"] if e]
    return max(ERROR_FLOOR, 0.1 * min(errors + [report["tolerance"]]))


def pareto_figure(report: dict):
    """The figure of ``pareto_plot``: errors of exactly 0 (a rung against itself as the
    reference) drawn as open triangles at ``zero_level`` and named so in the legend; tick
    labels in plain numbers; rung labels moved apart where points crowd."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.ticker import FuncFormatter

    fig = Figure(figsize=(7.5, 5.0), constrained_layout=True)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    zero = zero_level(report)
    zeros, labels = [], []
    for knob, k in report["knobs"].items():
        pts = [(1e3 * r["wall_time"], e if e > 0 else zero, r["value"], e == 0)
               for r, e in zip(k["rungs"], k["worst_error"], strict=False)
               if r["status"] == "ok" and e is not None]
        if not pts:
            continue
        line, = ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=knob)
        zeros += [(p[0], p[1], line.get_color()) for p in pts if p[3]]
        labels += [(t, e, format(v, "g") if isinstance(v, int | float) else str(v))
                   for t, e, v, _ in pts]
    for i, (t, e, color) in enumerate(zeros):
        ax.plot([t], [e], "v", ms=9, mfc="white", mec=color, mew=1.5, zorder=5,
                label=f"error exactly 0 (drawn at {zero:.0e})" if i == 0 else None)
    front = pareto_front(study_points(report))
    if front:
        ax.step([1e3 * p[0] for p in front], [max(p[1], zero) for p in front],
                where="post", color="black", lw=0.8, ls="--", label="Pareto front")
    ax.axhline(report["tolerance"], color="red", lw=0.8, label=f"tolerance {report['tolerance']:g}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    ax.xaxis.set_minor_formatter(FuncFormatter(_minor_label))
    ax.set_xlabel("wall time per run [ms]")
    ax.set_ylabel("worst relative error over the key metrics [-]")
    ax.set_title(f"{report['title']}: accuracy against time", fontsize=9)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    _place_labels(fig, ax, labels)
    return fig


def _minor_label(v: float, _pos=None) -> str:
    """Label the minor ticks 2 and 5 of each decade only: more would run into each other."""
    import math

    if v <= 0:
        return ""
    mantissa = round(v / 10 ** math.floor(math.log10(v) + 1e-9))
    return f"{v:g}" if mantissa in (2, 5) else ""


def _place_labels(fig, ax, labels, min_px: float = 14.0) -> None:
    """Annotate each point with its rung value, stacking a label upwards while it would
    land on one already placed."""
    fig.canvas.draw()
    placed: list[tuple[float, float]] = []
    for t, e, text in labels:
        x, y = ax.transData.transform((t, e))
        dy = 3.0
        while any(abs(x - px) < 3 * min_px and abs(y + dy - py) < min_px for px, py in placed):
            dy += min_px * 0.8
        placed.append((x, y + dy))
        ax.annotate(text, (t, e), textcoords="offset points", xytext=(4, dy * 72 / fig.dpi),
                    fontsize=7)
