"""Metrics over a leading case axis: one definition serves a run and a batch of sweep cases.

An effect states each of its metrics once, as a :class:`CaseMetric` read from per-angle arrays
that may carry leading case axes (a run: none, so every value is one number; the sweep batch:
one row per case). :func:`one_case` turns them into the rows of ``Result.add_metrics`` for a
run, :func:`per_case` into the (name, value, unit) lists of every case of a batch. Light to
import (numpy only inside the functions that need it), so effect modules import it at their top.
"""
from __future__ import annotations

from functools import cache
from typing import NamedTuple


class CaseMetric(NamedTuple):
    """One metric of every case: ``value`` and ``angle`` one number or one per case;
    ``present`` whether the case has the metric at all (True, or one bool per case)."""

    name: str
    value: object
    unit: str
    description: str
    angle: object = None
    present: object = True


def at(values, index):
    """``values`` at ``index`` along the last (angle) axis, case by case; ``index`` one int
    for every case or one per case."""
    if values.ndim == 1:
        return values[index]
    if not getattr(index, "ndim", 0):
        return values[..., index]
    return values[_rows(values.shape[0]), index]


@cache
def _rows(n: int):
    """0 .. n-1, the row index of a batch of ``n`` cases (formed once per batch size: a batch's
    metrics index their rows a few dozen times)."""
    import numpy as np

    rows = np.arange(n)
    rows.flags.writeable = False
    return rows


def count(mask):
    """Number of true angles, case by case (the 1-D form of a run is the fast one)."""
    import numpy as np

    if mask.ndim == 1:
        return np.count_nonzero(mask)
    return np.count_nonzero(mask, axis=-1)


def anywhere(mask):
    """Whether any angle is true, case by case."""
    import numpy as np

    return np.count_nonzero(mask) > 0 if mask.ndim == 1 else np.any(mask, axis=-1)


def one_case(metrics) -> list:
    """The ``Result.add_metrics`` rows of a run: its metrics that are present (a CaseMetric
    is such a row: add_metrics reads name, value, unit, description and angle)."""
    return [m for m in metrics if m.present]


def per_case(metrics, n: int) -> list[list[tuple[str, float, str]]]:
    """For each of ``n`` cases, its present metrics as (name, value, unit), in order."""
    import numpy as np

    columns = []
    for m in metrics:
        value, present = m.value, m.present
        values = (np.asarray(value, dtype=float).tolist() if getattr(value, "ndim", 0)
                  else [float(value)] * n)
        if present is True:
            present = None   # every case has it
        elif getattr(present, "ndim", 0):
            present = present.tolist()
        else:
            present = [bool(present)] * n
        columns.append((m.name, m.unit, values, present))
    return [[(name, values[r], unit) for name, unit, values, present in columns
             if present is None or present[r]] for r in range(n)]


def case_metric(metrics: dict, name: str) -> tuple[float, str] | None:
    """(value, unit) of metric ``name`` among one sweep case's ``metrics`` (a case record's
    name -> (value, unit)), None when the case has none: a case that failed has no metrics,
    and a case whose plan ran no effect stating ``name`` has not that one. The one place a
    sweep's tables, plots and studies read a metric of a case by name; a blank cell or a
    missing point follows from it, never a choice of what to compute or draw."""
    return metrics.get(name)
