"""The engine load sheet: polar load diagrams of the big-end (rod axes) and of every main
(block axes), and the load magnitudes over the cycle, as Yang's (1992) Figs 2.2 and 2.5 show
them. Matplotlib is imported on use (Agg backend)."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from camtrain.catalogue import components_of
from camtrain.result import Result


def _diagrams(result: Result) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """Every bearing's load diagram: the crank-loads effect writes one for each bearing it
    declares (EffectSpec.components)."""
    out = []
    for comp in components_of(result.plan, "CrankLoads", result.components):
        part = result.component(comp)
        out.append((comp, part["load_x"], part["load_y"]))
    return out


def load_sheet(result: Result, out_dir: Path, *, deck=None, sha: str | None = None,
               formats=("png",)) -> list[Path]:
    """``sheet_engine_loads.<fmt>``, an A4 page in the house style: big-end 1 (rod axes) and
    every main (block axes) as polar load diagrams [kN], small multiples four to a row, and
    every load magnitude against crank angle (the crank-loads effect declares it). Empty when
    no bearing has a load diagram."""
    diagrams = _diagrams(result)
    if not diagrams:
        return []
    from matplotlib.ticker import MaxNLocator

    from camtrain.report.canvas import save_sheet
    from camtrain.report.house import (
        GRID_LEFT_IN,
        GRID_RIGHT_IN,
        GRID_TOP_IN,
        LEGEND_RIGHT_IN,
        grid,
        house_page,
        legend_beside,
    )
    from camtrain.report.sheet_header import HEADER_IN, PAGE_IN

    polar = [d for d in diagrams if d[0] == "big_end_1" or d[0].startswith("main_")]
    ncol = 4
    rows = math.ceil(len(polar) / ncol)
    with house_page(deck, result, "Bearing load diagrams [kN]", sha) as fig:
        # the polar rows as tall as the square plots are wide (and their titles), the
        # magnitudes below in the rest of the page
        w, h = fig.get_size_inches()
        row_in = (w - GRID_LEFT_IN - GRID_RIGHT_IN) / (ncol + 0.45 * (ncol - 1)) + 0.75
        magnitudes_in = h - PAGE_IN - HEADER_IN - GRID_TOP_IN - rows * row_in - 0.6
        heights = [row_in] * rows + [magnitudes_in]
        spec = grid(fig, rows + 1, ncol, hspace=0.3, wspace=0.45, height_ratios=heights)
        for k, (comp, lx, ly) in enumerate(polar):
            ax = fig.add_subplot(spec[k // ncol, k % ncol], projection="polar")
            ax.plot(np.arctan2(ly, lx), np.hypot(lx, ly) / 1e3, lw=0.9, color="#1f4e79")
            ax.set_title(comp.replace("_", " ").replace("big end", "big-end")
                         + (" (rod axes)" if "big" in comp else " (block axes)"), fontsize=8,
                         pad=14)
            ax.tick_params(labelsize=6, pad=1)
            ax.yaxis.set_major_locator(MaxNLocator(3))
            ax.set_rlabel_position(112.5)
        lower = grid(fig, rows + 1, 1, right_in=LEGEND_RIGHT_IN, hspace=0.3,
                     height_ratios=heights)
        ax = fig.add_subplot(lower[rows, 0])
        th = np.degrees(result["crank_angle"])
        colors = ("#1f4e79", "#c0504d", "#4f8a3c", "#8064a2", "#7f7f7f", "#d08c00", "#00838f",
                  "#ad1457")
        shown = [d for d in diagrams if not d[0].startswith("big_end_") or d[0] == "big_end_1"]
        for i, (comp, lx, ly) in enumerate(shown):
            ax.plot(th, np.hypot(lx, ly) / 1e3, lw=0.9, color=colors[i % len(colors)],
                    label=comp.replace("_", " ").replace("big end", "big-end"))
        span = 720.0 if th[-1] - th[0] > 360.0 else 360.0
        ax.set_xlim(th[0], th[0] + span)
        ax.set_xticks(np.arange(th[0], th[0] + span + 1.0, 90.0))
        ax.set_xlabel("crank angle [deg]")
        ax.set_ylabel("load magnitude [kN]")
        legend_beside(ax)
        Path(out_dir).mkdir(parents=True, exist_ok=True)
        return save_sheet(fig, Path(out_dir) / "sheet_engine_loads", formats)
