"""The friction-correlation sheet of an engine run, an A4 page in the house style: for each
correlation the run computed (Patton-Nitschke-Heywood 1989, Sandoval-Heywood 2003, Chen-Flynn)
its friction power as one bar split by group (crankshaft, reciprocating, valve train,
auxiliaries), every part with its value, the total and the fmep beside the bar; with a FLAME
total, FLAME's bar beside them. Matplotlib is imported on use."""
from __future__ import annotations

from pathlib import Path

from camtrain.report.summaries import CORRELATION_GROUPS, CORRELATION_MODELS, flame_parts
from camtrain.result import Result

_COLORS = ("#1f4e79", "#c0504d", "#4f8a3c", "#8064a2", "#7f7f7f", "#d08c00")


def _bars(result: Result) -> list[tuple[str, list[tuple[str, float]], float, float | None]]:
    """(label, [(group, power W)], total W, fmep Pa or None) per model the run computed."""
    bars = []
    for name, label in CORRELATION_MODELS:
        if name not in result.components:
            continue
        metrics = result.component(name).metrics
        parts = [(short, metrics[f"{group}_power"].value) for group, short in CORRELATION_GROUPS
                 if f"{group}_power" in metrics]
        fmep = metrics.get("fmep")
        total = metrics["power"].value
        # Chen-Flynn is one fit of the whole engine: no parts to split it into
        bars.append((label, parts or [("whole engine", total)], total,
                     None if fmep is None else fmep.value))
    if bars and _ran(result, "flame"):
        fmep = result.metrics.get("fmep")
        bars.append(("FLAME", flame_parts(result), result.metrics["flame_total"].value,
                     None if fmep is None else fmep.value))
    return bars


def _ran(result: Result, effect: str) -> bool:
    """Whether the plan ran ``effect`` (the sheet asks the plan, not the metric names)."""
    from camtrain.catalogue import declared_effects

    return any(spec.name == effect for spec in declared_effects(result.plan))


def correlation_sheet(result: Result, out_dir: Path, *, deck=None, sha: str | None = None,
                      formats=("png",)) -> list[Path]:
    """``sheet_correlations.<fmt>``: each model's friction power by group. Empty without a
    correlation run."""
    bars = _bars(result)
    if not bars:
        return []
    from camtrain.report.canvas import save_sheet
    from camtrain.report.house import LEGEND_RIGHT_IN, grid, house_page, legend_beside

    with house_page(deck, result, "Engine friction correlations", sha) as fig:
        # one short plot at the top of the page: a few bars need no more height
        spec = grid(fig, 1, 1, bottom_in=5.5, left_in=1.1, right_in=LEGEND_RIGHT_IN)
        _stacked(fig.add_subplot(spec[0]), bars)
        legend_beside(fig.axes[-1], fontsize=7.5)
        Path(out_dir).mkdir(parents=True, exist_ok=True)
        return save_sheet(fig, Path(out_dir) / "sheet_correlations", formats)


def _stacked(ax, bars) -> None:
    """One horizontal bar per model, split by part, each part's power written inside it."""
    from camtrain.report.display import fmt

    colors: dict[str, str] = {}
    largest = max(total for _, _, total, _ in bars)
    for row, (_label, parts, total, fmep) in enumerate(bars):
        left = 0.0
        for part, power in parts:
            first = part not in colors
            color = colors.setdefault(part, _COLORS[len(colors) % len(_COLORS)])
            ax.barh(row, power, left=left, color=color, label=part if first else None)
            if power > 0.08 * largest:
                ax.text(left + power / 2, row, fmt(power), ha="center", va="center",
                        fontsize=7, color="white")
            left += power
        note = f"{fmt(total)} W" + ("" if fmep is None else f", {fmt(fmep * 1e-3)} kPa")
        ax.text(left + 0.01 * largest, row, note, va="center", fontsize=7.5)
    ax.set_yticks(range(len(bars)), [label for label, *_ in bars])
    ax.set_xlim(0.0, 1.35 * largest)
    ax.set_ylim(len(bars) - 0.5, -0.5)
    ax.set_xlabel("friction power [W]")
    ax.set_title("friction power by part: total and fmep beside each bar")
    ax.grid(axis="y", visible=False)
