"""The result of a run: named per-angle arrays with units, scalar metrics, warnings, timings, plan.

Pure data: no printing, no files. The report layer and the CLI read it.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class Column:
    """One per-angle quantity on the run's angle grid."""

    values: np.ndarray
    unit: str
    description: str


@dataclass(frozen=True)
class Metric:
    """One scalar result; ``angle`` [rad] says where on the cycle it occurs, when it does."""

    value: float
    unit: str
    description: str
    angle: float | None = None


@dataclass
class Result:
    """Everything a run produced. Columns share one cam-angle grid (``columns['cam_angle']``)."""

    columns: dict[str, Column] = field(default_factory=dict)
    metrics: dict[str, Metric] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    timings: dict[str, float] = field(default_factory=dict)
    plan: object = None

    def add_column(self, name: str, values, unit: str, description: str) -> None:
        self.columns[name] = Column(np.asarray(values, dtype=float), unit, description)

    def add_metric(self, name: str, value: float, unit: str, description: str,
                   angle: float | None = None) -> None:
        self.metrics[name] = Metric(float(value), unit, description,
                                    None if angle is None else float(angle))

    def __getitem__(self, name: str) -> np.ndarray:
        """Per-angle array by name, e.g. ``result['lift']``."""
        return self.columns[name].values

    def warn(self, message: str) -> None:
        if message not in self.warnings:
            self.warnings.append(message)
