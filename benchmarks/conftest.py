"""Shared machinery of the benchmarks: interleaved timing and the ratio table.

Every workload is timed against its floor in the same run, interleaved round by round, so that
load from other processes on the machine hits both alike; the ratio of the medians is what
docs/performance.md reports. At the end of ``make bench`` a table of all ratios is printed.
"""
from __future__ import annotations

import os
import statistics
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(Path(__file__).resolve().parent))

#: Environment of the timed processes: bytecode caching on, as for an installed package (a
#: PYTHONDONTWRITEBYTECODE in the caller's environment would make every process recompile).
ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
ENV["PYTHONPATH"] = os.pathsep.join([str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])])

_ROWS: list[tuple[str, str, str, str]] = []


def paired(subject, floor, rounds: int, warmup: int = 1) -> dict[str, float]:
    """Median and minimum times [s] of ``subject`` and ``floor``, run alternately."""
    for _ in range(warmup):
        subject()
        floor()
    ts, tf = [], []
    for _ in range(rounds):
        t = time.perf_counter()
        subject()
        ts.append(time.perf_counter() - t)
        t = time.perf_counter()
        floor()
        tf.append(time.perf_counter() - t)
    med_s, med_f = statistics.median(ts), statistics.median(tf)
    return {"subject_median": med_s, "subject_min": min(ts), "floor_median": med_f,
            "floor_min": min(tf), "ratio": med_s / med_f, "ratio_min": min(ts) / min(tf)}


def _fmt(seconds: float) -> str:
    return f"{seconds * 1e3:.3g} ms" if seconds < 1.0 else f"{seconds:.3g} s"


def record(benchmark, workload: str, timing: dict[str, float], target: str = "") -> None:
    """Keep a paired timing for the summary table and in the benchmark's JSON."""
    benchmark.extra_info.update(timing)
    _ROWS.append((workload, _fmt(timing["subject_median"]), _fmt(timing["floor_median"]),
                  f"{timing['ratio']:.2f}x (min {timing['ratio_min']:.2f}x)"
                  + (f"  target {target}" if target else "")))


def note(workload: str, value: str, target: str = "") -> None:
    """A figure that is not a ratio (throughput, compile time, memory)."""
    _ROWS.append((workload, value, "-", f"target {target}" if target else "-"))


@pytest.fixture
def record_ratio():
    return record


def pytest_terminal_summary(terminalreporter):
    if not _ROWS:
        return
    w = max(len(r[0]) for r in _ROWS)
    terminalreporter.section("camtrain against its floors (medians, same run)")
    for name, subject, floor, ratio in _ROWS:
        terminalreporter.write_line(f"{name:<{w}}  {subject:>10}  {floor:>10}  {ratio}")
