"""Lift tables shipped with camtrain (package data in ``camtrain/data``) and a CSV reader.

CSV layout: ``#`` comment lines (the source), one header line naming the columns with their
units (``angle_deg`` or ``angle_rad``; ``lift_mm`` or ``lift_m``), then one angle,lift pair per
line. Values keep the precision printed in the source, which the table law uses to judge the
noise of the data.
"""
from __future__ import annotations

from dataclasses import dataclass
from importlib import resources
from pathlib import Path

import numpy as np

from camtrain.lift import _checks as chk
from camtrain.lift.base import DEG, MM

DATASETS = {
    "pinto_inlet_cam": "ball1988_pinto_inlet_cam_lift.csv",      # Ball (1988) App E
    "pinto_inlet_valve": "ball1988_pinto_inlet_valve_lift.csv",  # derived from App E (datum)
    "zeta_intake": "yang1992_zeta_intake_cam_lift.csv",           # Yang (1992) App C
    "zeta_exhaust": "yang1992_zeta_exhaust_cam_lift.csv",         # Yang (1992) App C
}
_ANGLE_UNITS = {"angle_deg": DEG, "angle_rad": 1.0}
_LIFT_UNITS = {"lift_mm": MM, "lift_m": 1.0}


@dataclass(frozen=True)
class LiftTable:
    """A lift table in SI (angles rad, lift m), with its source note and printed precision."""

    angles: np.ndarray
    lift: np.ndarray
    source: str
    lift_quantum: float      # smallest printed lift step [m] (0 if not a decimal table)


def decimal_quantum(values_in_unit: np.ndarray, max_decimals: int = 9) -> float:
    """Step of the last printed decimal of ``values_in_unit`` (e.g. 1e-4 for 4-decimal data).

    0.0 if the values do not look rounded to at most ``max_decimals`` decimals.
    """
    v = np.asarray(values_in_unit, dtype=float)
    for k in range(max_decimals + 1):
        scaled = v * 10.0 ** k
        if np.all(np.abs(scaled - np.round(scaled)) <= 1e-6 * np.maximum(1.0, np.abs(scaled))):
            return 10.0 ** -k
    return 0.0


#: Largest lift-table file read (the same bound as a deck): a table at 0.01 deg steps is about
#: 1 MB, so anything near this is not a lift table, and reading it would only cost time.
MAX_TABLE_BYTES = 20 * 1024 * 1024


def read_lift_csv(text: str, path: str = "lift.table.file", name: str = "") -> LiftTable:
    """Parse the CSV layout above (``text`` is the file content, ``name`` the file's name for
    messages). A message names the file and the line, never the line's content: a table path
    may point at a file that holds secrets."""
    where = f"{name}, " if name else ""
    notes, rows, header = [], [], None
    for n, line in enumerate(text.splitlines(), start=1):
        line = line.strip()
        if not line:
            continue
        if line.startswith("#"):
            notes.append(line.lstrip("# "))
            continue
        cells = [c.strip() for c in line.split(",")]
        if header is None:
            header = cells
            if (len(cells) != 2 or cells[0] not in _ANGLE_UNITS or cells[1] not in _LIFT_UNITS):
                raise chk.fail(path, f"{where}line {n} is not a valid header", None,
                               "angle_deg|angle_rad , lift_mm|lift_m")
            continue
        if len(cells) != 2:
            raise chk.fail(path, f"{where}line {n} does not have two columns", None,
                           "angle, lift")
        try:
            rows.append([float(c) for c in cells])
        except ValueError:
            raise chk.fail(path, f"{where}line {n} is not a pair of numbers", None,
                           "angle, lift") from None
    if header is None or not rows:
        raise chk.fail(path, "contains no lift table", None, "a header line and data lines")
    data = np.array(rows)
    lift_unit = _LIFT_UNITS[header[1]]
    return LiftTable(data[:, 0] * _ANGLE_UNITS[header[0]], data[:, 1] * lift_unit,
                     " ".join(notes), decimal_quantum(data[:, 1]) * lift_unit)


def load_dataset(name: str) -> LiftTable:
    """One of the shipped tables by name (keys of ``DATASETS``)."""
    if name not in DATASETS:
        raise chk.fail("lift.table.dataset", "is not a shipped lift table", name,
                       ", ".join(sorted(DATASETS)))
    text = resources.files("camtrain").joinpath("data", DATASETS[name]).read_text("utf-8")
    return read_lift_csv(text)


def load_csv(file: str | Path, path: str = "lift.table.file") -> LiftTable:
    """A lift table from a CSV file on disk."""
    name = Path(file).name
    try:
        with Path(file).open("rb") as fh:
            data = fh.read(MAX_TABLE_BYTES + 1)
    except OSError as exc:
        raise chk.fail(path, "cannot be read", str(file), hint=str(exc.strerror)) from None
    if len(data) > MAX_TABLE_BYTES:
        raise chk.fail(path, f"{name} is larger than {MAX_TABLE_BYTES // 2**20} MiB", str(file),
                       "a lift table (a small CSV text file)")
    if b"\x00" in data:
        raise chk.fail(path, f"{name} is a binary file", str(file), "a CSV text file")
    try:
        text = data.decode("utf-8-sig")   # a byte-order mark (some editors write one) is read
    except UnicodeDecodeError as exc:
        raise chk.fail(path, f"{name} is not UTF-8 text (byte {exc.start})", str(file),
                       "a CSV text file") from None
    return read_lift_csv(text, path, name)
