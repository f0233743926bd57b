"""Measured data for `camtrain fit`: CSV files of a quantity against cam or crank angle, or
against speed, with units in the header.

A data set is one CSV file::

    # speed.camshaft = 1500          (optional: deck fields set for this data set, deck units)
    cam_angle[deg],friction_torque[N·m]
    -60,0.121
    ...

The first column is the abscissa: ``cam_angle`` or ``crank_angle`` (a per-angle column of the
run is compared at those angles, interpolated linearly on the run's grid), or ``speed`` (each
row is a run at that speed, in the unit of the deck's speed field, and the other columns are
metrics of the run). Every further column is one measured quantity with its unit, which must
measure what camtrain computes (``N·m`` for a torque, ``µm`` for a film, ...).
"""
from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass
from pathlib import Path

from camtrain.errors import InputError, Problem

ANGLE_AXES = ("cam_angle", "crank_angle")
SPEED_AXIS = "speed"
_HEADER = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_.]*)\s*\[(.*)\]\s*$")


@dataclass(frozen=True)
class Series:
    """One measured quantity of a data set: its name, unit as written, values in that unit."""

    name: str
    unit: str
    values: tuple[float, ...]

    def si(self):
        import numpy as np

        from camtrain.units import UNITS

        return np.asarray(self.values) * UNITS[self.unit][0]


@dataclass(frozen=True)
class DataSet:
    """One CSV file: the abscissa (``axis`` in ``axis_unit``), the quantities and the deck
    fields it sets (``sets``: ['path=value', ...])."""

    path: str
    axis: str
    axis_unit: str
    x: tuple[float, ...]
    series: tuple[Series, ...]
    sets: tuple[str, ...] = ()

    @property
    def label(self) -> str:
        return Path(self.path).name

    @property
    def by_speed(self) -> bool:
        return self.axis == SPEED_AXIS

    def x_si(self):
        import numpy as np

        from camtrain.units import UNITS

        return np.asarray(self.x) * UNITS[self.axis_unit][0]

    @property
    def points(self) -> int:
        return len(self.x) * len(self.series)


def _bad(path: str, message: str, value=None, expected: str = "") -> InputError:
    return InputError(Problem("--data", message, value, expected), source=path)


def _column(text: str, path: str) -> tuple[str, str]:
    from camtrain.units import UNITS

    m = _HEADER.match(text)
    if m is None:
        raise _bad(path, f"column {text!r} has no unit", text, "name[unit], e.g. "
                   "cam_angle[deg] or friction_torque[N·m]")
    name, unit = m.group(1), m.group(2).strip()
    if unit not in UNITS:
        raise _bad(path, f"unit {unit!r} of column {name} is not a unit camtrain knows", unit,
                   ", ".join(UNITS))
    return name, unit


def read_data(path: str | Path) -> DataSet:
    """Read and check one data file (exit 2 with the file, column and value named)."""
    path = str(path)
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as exc:
        raise _bad(path, f"cannot read the data file: {exc.strerror}") from None
    sets = tuple(line.lstrip("#").strip() for line in text.splitlines()
                 if line.startswith("#") and "=" in line)
    rows = [r for r in csv.reader(line for line in text.splitlines()
                                  if line.strip() and not line.startswith("#"))]
    if len(rows) < 2:
        raise _bad(path, "needs a header and at least one row of numbers")
    head = [_column(c, path) for c in rows[0]]
    axis, axis_unit = head[0]
    if axis not in ANGLE_AXES + (SPEED_AXIS,):
        raise _bad(path, f"the first column {axis} is not an abscissa", axis,
                   "cam_angle[deg], crank_angle[deg] or speed[rpm]")
    from camtrain.units import UNITS

    speed = axis == SPEED_AXIS
    if UNITS[axis_unit][1] != ("rad/s" if speed else "rad"):
        raise _bad(path, f"the unit of {axis} does not measure {'a speed' if speed else 'an angle'}",
                   axis_unit, "rpm" if speed else "deg or rad")
    if len(head) < 2:
        raise _bad(path, "has no measured quantity beside the abscissa")
    values = []
    for k, row in enumerate(rows[1:], start=2):
        if len(row) != len(head):
            raise _bad(path, f"row {k} has {len(row)} fields", row, f"{len(head)} fields")
        try:
            numbers = [float(v) for v in row]
        except ValueError:
            raise _bad(path, f"row {k} is not all numbers", ",".join(row)) from None
        if not all(math.isfinite(v) for v in numbers):
            raise _bad(path, f"row {k} holds a value that is not finite", ",".join(row))
        values.append(numbers)
    columns = list(zip(*values, strict=True))
    series = tuple(Series(n, u, tuple(columns[j + 1])) for j, (n, u) in enumerate(head[1:]))
    return DataSet(path, axis, axis_unit, tuple(columns[0]), series, sets)
