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
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path = Path(path)
    fig, ax = plt.subplots(figsize=(7.5, 5.0), constrained_layout=True)
    for knob, k in report["knobs"].items():
        pts = [(1e3 * r["wall_time"], max(e, ERROR_FLOOR), r["value"])
               for r, e in zip(k["rungs"], k["worst_error"], strict=False)
               if r["status"] == "ok" and e is not None]
        if not pts:
            continue
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=knob)
        for t, e, v in pts:
            text = format(v, "g") if isinstance(v, int | float) else str(v)
            ax.annotate(text, (t, e), textcoords="offset points", xytext=(4, 3), fontsize=7)
    front = pareto_front(study_points(report))
    if front:
        ax.step([1e3 * p[0] for p in front], [max(p[1], ERROR_FLOOR) for p in front],
                where="post", color="black", lw=0.8, ls="--", label="Pareto front")
    ax.axhline(report["tolerance"], color="red", lw=0.8, label=f"tolerance {report['tolerance']:g}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time per run [ms]")
    ax.set_ylabel("worst relative error over the key metrics [-]")
    ax.set_title(f"{report['title']}: accuracy against time", fontsize=9)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
