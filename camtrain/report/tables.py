"""Machine-readable outputs: summary.json and cycle.csv, written atomically.

Everything is computed before anything is written; each file is written to a temporary name in the
output directory and renamed into place, so a failed run never leaves a half-written result.
"""
from __future__ import annotations

import math
import os
import tempfile
from pathlib import Path

import numpy as np

from camtrain import __version__
from camtrain.deck.load import LoadedDeck
from camtrain.result import Result

#: Columns whose SI unit is shown in engineering units in cycle.csv.
_DISPLAY = {"rad": ("deg", 180.0 / math.pi)}


def summary_dict(result: Result, deck: LoadedDeck, wall_time: float, checks=None) -> dict:
    """The summary of a run as plain data (what summary.json holds).

    ``checks`` are the evaluated design limits (camtrain.report.limits), if any.
    """
    from camtrain.report.findings import find
    metrics = {}
    for name, m in result.metrics.items():
        entry = {"value": _finite_or_none(m.value), "unit": m.unit, "description": m.description}
        if m.angle is not None:
            entry["angle_deg"] = round(math.degrees(m.angle), 6)
        metrics[name] = entry
    return {
        "camtrain_version": __version__,
        "deck": {"path": deck.path, "sha256": deck.sha256, "title": deck.model.title},
        "plan": result.plan.as_dict() if result.plan is not None else None,
        "metrics": metrics,
        "warnings": list(result.warnings),
        "findings": find(result).as_dict(),
        "limits": [c.as_dict() for c in checks or []],
        "timings_s": {k: round(v, 6) for k, v in result.timings.items()},
        "wall_time_s": round(wall_time, 6),
        "columns": {name: {"unit": c.unit, "description": c.description}
                    for name, c in result.columns.items()},
    }


def _finite_or_none(x: float):
    return x if math.isfinite(x) else None


def cycle_table(result: Result, axis: str | None = None) -> tuple[list[str], np.ndarray]:
    """Column headers with units (e.g. ``cam_angle[deg]``) and the data matrix of the columns
    on ``axis`` (default: the first axis; columns on other grids go to tables of their own)."""
    headers, cols = [], []
    axis = axis or (result.axes[0] if result.axes else None)
    for name, col in result.columns.items():
        if axis is not None and col.axis != axis:
            continue
        unit, factor = _DISPLAY.get(col.unit, (col.unit, 1.0)) if name == "cam_angle" \
            else (col.unit, 1.0)
        headers.append(f"{name}[{unit}]")
        cols.append(col.values * factor)
    data = np.column_stack(cols) if cols else np.empty((0, 0))
    return headers, data


def atomic_write(path: Path, text: str) -> None:
    """Write text to a temporary name beside ``path`` and rename it into place."""
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as fh:
            fh.write(text)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def csv_text(result: Result, axis: str | None = None) -> str:
    headers, data = cycle_table(result, axis)
    lines = [",".join(headers)]
    lines += [",".join(f"{v:.10g}" for v in row) for row in data]
    return "\n".join(lines) + "\n"


def write_table(result: Result, path: Path) -> Path:
    """Write the per-angle columns of a result as CSV (atomically)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    atomic_write(path, csv_text(result))
    return path
