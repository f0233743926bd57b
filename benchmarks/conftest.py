"""Shared machinery of the benchmarks: interleaved timing and the ratio table.

Every workload is timed against its floor in the same run, interleaved round by round, so that
load from other processes on the machine hits both alike; the ratio of the medians is what
docs/performance.md reports. At the end of ``make bench`` a table of all ratios is printed.
"""
from __future__ import annotations

import os
import resource
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


def cpu_seconds() -> float:
    """CPU time [s] of this process and of every child process it has waited for (a timed
    subprocess, a sweep's workers): unlike the wall clock, it does not grow while other work on
    a shared machine holds the cores."""
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.process_time() + kids.ru_utime + kids.ru_stime


def _timed(fn) -> tuple[float, float]:
    t, c = time.perf_counter(), cpu_seconds()
    fn()
    return time.perf_counter() - t, cpu_seconds() - c


def paired(subject, floor, rounds: int, warmup: int = 1) -> dict[str, float]:
    """Median and minimum wall and CPU times [s] of ``subject`` and ``floor``, run alternately.

    The CPU times (``cpu_*``) are this process' own clock plus the kernel's accounting of the
    children it waited for (``getrusage``)."""
    for _ in range(warmup):
        subject()
        floor()
    ts, tf, cs, cf = [], [], [], []
    for _ in range(rounds):
        wall, cpu = _timed(subject)
        ts.append(wall)
        cs.append(cpu)
        wall, cpu = _timed(floor)
        tf.append(wall)
        cf.append(cpu)
    med_s, med_f = statistics.median(ts), statistics.median(tf)
    return {"subject_median": med_s, "subject_min": min(ts), "floor_median": med_f,
            "floor_min": min(tf), "ratio": med_s / med_f, "ratio_min": min(ts) / min(tf),
            "cpu_subject_min": min(cs), "cpu_floor_min": min(cf),
            "cpu_ratio_min": min(cs) / max(min(cf), 1e-9)}


def _fmt(seconds: float) -> str:
    return f"{seconds * 1e3:.3g} ms" if seconds < 1.0 else f"{seconds:.3g} s"


def record(benchmark, workload: str, timing: dict[str, float], target: str = "",
           cpu: bool = False) -> None:
    """Keep a paired timing for the summary table and in the benchmark's JSON (``cpu``: also
    the ratio of the smallest CPU times, for whole processes)."""
    benchmark.extra_info.update(timing)
    extra = (f", cpu {_fmt(timing['cpu_subject_min'])} / {_fmt(timing['cpu_floor_min'])} = "
             f"{timing['cpu_ratio_min']:.2f}x") if cpu else ""
    _ROWS.append((workload, _fmt(timing["subject_median"]), _fmt(timing["floor_median"]),
                  f"{timing['ratio']:.2f}x (min {timing['ratio_min']:.2f}x{extra})"
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
