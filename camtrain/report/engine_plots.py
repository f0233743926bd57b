"""The engine load sheet: polar load diagrams of the big-end (rod axes) and of every main
(block axes), and the load magnitudes over the cycle, as Yang's (1992) Figs 2.2 and 2.5 show
them. Matplotlib is imported on use (Agg backend)."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from camtrain.result import Result


def _diagrams(result: Result) -> list[tuple[str, np.ndarray, np.ndarray]]:
    out = []
    for comp in result.components:
        if not comp.startswith(("big_end_", "main_")):
            continue
        part = result.component(comp)
        if "load_x" in part.columns and "load_y" in part.columns:
            out.append((comp, part["load_x"], part["load_y"]))
    return out


def load_sheet(result: Result, out_dir: Path, *, title: str = "", formats=("png",)) -> list[Path]:
    """``sheet_engine_loads.<fmt>``: big-end 1 and every main as polar load diagrams (kN),
    and every load magnitude against crank angle. Empty when the run has no crank loads."""
    if "crank_angle" not in result.columns:
        return []
    diagrams = _diagrams(result)
    if not diagrams:
        return []
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure
    from matplotlib.ticker import MaxNLocator

    polar = [d for d in diagrams if d[0] == "big_end_1" or d[0].startswith("main_")]
    ncol = 4
    nrow = math.ceil(len(polar) / ncol) + 1
    fig = Figure(figsize=(8.27, 2.3 * nrow + 0.6))
    th = np.degrees(result["crank_angle"])
    for k, (comp, lx, ly) in enumerate(polar):
        ax = fig.add_subplot(nrow, ncol, k + 1, projection="polar")
        ax.plot(np.arctan2(ly, lx), np.hypot(lx, ly) / 1e3, lw=0.9)
        ax.set_title(comp.replace("_", " ") + (" (rod axes)" if "big" in comp else ""),
                     fontsize=8)
        ax.tick_params(labelsize=6)
        ax.yaxis.set_major_locator(MaxNLocator(3))
        ax.set_rlabel_position(112.5)
    ax = fig.add_subplot(nrow, 1, nrow)
    for comp, lx, ly in diagrams:
        if comp.startswith("big_end_") and comp != "big_end_1":
            continue
        ax.plot(th, np.hypot(lx, ly) / 1e3, lw=0.8, label=comp.replace("_", " "))
    ax.set_xlabel("crank angle [deg]", fontsize=8)
    ax.set_ylabel("load [kN]", fontsize=8)
    ax.tick_params(labelsize=7)
    ax.legend(fontsize=6, ncol=4, frameon=False)
    fig.suptitle((title + " — " if title else "") + "bearing loads [kN]", fontsize=10)
    fig.tight_layout()
    out_dir.mkdir(parents=True, exist_ok=True)
    written = []
    for ext in formats:
        path = out_dir / f"sheet_engine_loads.{ext}"
        fig.savefig(path, dpi=110)
        written.append(path)
    return written
