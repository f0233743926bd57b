"""The roller sheet of a valve-train run, an A4 page in the house style: the roller's speed
against the speed of pure rolling, slip and slide-roll ratio (skidding angles shaded), the loss
by part per angle (cam-roller sliding and rolling, pin) and the cycle-mean loss by part as bars
(the roller effect declares it). Matplotlib is imported on use."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from camtrain.result import Result

CAM_LABEL = "cam angle [deg]"
_COLORS = ("#1f4e79", "#c0504d", "#4f8a3c", "#8064a2", "#7f7f7f")
#: (column, metric, label) of the roller's losses by part
PARTS = (("power_roller_sliding", "roller_power_sliding", "cam sliding"),
         ("power_roller_rolling", "roller_power_rolling", "cam rolling"),
         ("power_pin", "roller_power_pin", "pin"))


def roller_sheet(result: Result, out_dir: Path, *, deck=None, sha: str | None = None,
                 formats=("png",)) -> list[Path]:
    """``sheet_roller.<fmt>``: speed, slip and slide-roll ratio, losses by part."""
    from camtrain.report.canvas import save_sheet
    from camtrain.report.house import LEGEND_RIGHT_IN, grid, house_page

    with house_page(deck, result, "Roller on its pin: rotation, slip and losses", sha) as fig:
        spec = grid(fig, 4, 1, hspace=0.5, left_in=1.05, right_in=LEGEND_RIGHT_IN)
        th = np.degrees(result["cam_angle"])
        _speed(fig.add_subplot(spec[0]), result, th)
        _slip(fig.add_subplot(spec[1]), result, th)
        _losses(fig.add_subplot(spec[2]), result, th)
        _means(fig.add_subplot(spec[3]), result)
        Path(out_dir).mkdir(parents=True, exist_ok=True)
        return save_sheet(fig, Path(out_dir) / "sheet_roller", formats)


def _cam_axis(ax, th) -> None:
    ax.set_xlim(float(th[0]), float(th[-1]))
    ax.set_xlabel(CAM_LABEL)


def _speed(ax, result: Result, th) -> None:
    from camtrain.report.house import legend_beside

    w = result["roller_speed"] * 60.0 / (2.0 * np.pi)
    ax.plot(th, w, color=_COLORS[0], label="roller")
    rolling = result["roller_speed_rolling"] * 60.0 / (2.0 * np.pi)
    ax.plot(th, rolling, color=_COLORS[4], ls="--", lw=0.9, label="pure rolling")
    ax.set_ylabel("roller speed [rpm]")
    ax.set_title("Roller speed on its pin")
    _cam_axis(ax, th)
    legend_beside(ax)


def _slip(ax, result: Result, th) -> None:
    from camtrain.report.house import legend_beside

    loaded = result["load"] > 0.0
    ax.plot(th, np.where(loaded, 100.0 * result["roller_slip"], np.nan), color=_COLORS[0],
            label="slip")
    ax.plot(th, np.where(loaded, 100.0 * result["slide_roll_ratio"], np.nan),
            color=_COLORS[1], lw=0.9, label="slide-roll ratio")
    skids = loaded & (result["roller_rolls"] == 0.0)
    for k, (a, b) in enumerate(_runs(th, skids)):
        ax.axvspan(a, b, color=_COLORS[1], alpha=0.12, lw=0,
                   label="skids" if k == 0 else None)
    ax.axhline(0.0, color="#404040", lw=0.5)
    ax.set_ylabel("[%]")
    ax.set_title("Slip and slide-roll ratio (loaded angles)")
    _cam_axis(ax, th)
    legend_beside(ax)


def _runs(x: np.ndarray, mask: np.ndarray) -> list[tuple[float, float]]:
    edges = np.flatnonzero(np.diff(np.concatenate(([0], mask.astype(np.int8), [0]))))
    return [(float(x[a]), float(x[b - 1])) for a, b in zip(edges[::2], edges[1::2], strict=True)]


def _losses(ax, result: Result, th) -> None:
    from camtrain.report.house import legend_beside

    for i, (column, _, label) in enumerate(PARTS):
        ax.plot(th, result[column], color=_COLORS[i], lw=0.9, label=label)
    ax.set_ylabel("power [W]")
    ax.set_title("Roller losses by part")
    _cam_axis(ax, th)
    legend_beside(ax)


def _means(ax, result: Result) -> None:
    from camtrain.report.display import fmt

    labels = [label for _, _, label in PARTS]
    values = np.array([result.metrics[m].value for _, m, _ in PARTS])
    total = float(values.sum())
    bars = ax.barh(labels, values, color=_COLORS[0])
    top = max(float(values.max()), 1e-12)
    for bar, value in zip(bars, values, strict=True):
        share = 100.0 * value / total if total else float("nan")
        ax.text(bar.get_width() + 0.01 * top, bar.get_y() + bar.get_height() / 2,
                f"{fmt(value)} W ({share:.1f} %)", va="center", fontsize=7.5)
    ax.set_xlim(0.0, 1.35 * top)
    ax.invert_yaxis()
    ax.set_xlabel("cycle-mean power [W]")
    ax.set_title(f"Cycle-mean roller loss: {fmt(total)} W")
    ax.grid(axis="y", visible=False)
