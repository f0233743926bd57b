"""Sweep throughput (pytest-benchmark; run with `make bench`, never asserted in tests).

A 1000-case camshaft-speed sweep of decks/harrison_flat.toml on 2 worker processes, tables only;
the cases per second are reported in docs/performance.md.
"""
from __future__ import annotations

from pathlib import Path

from camtrain.study.runner import prepare, run_sweep

DECK = Path(__file__).resolve().parent.parent / "decks" / "harrison_flat.toml"


def test_bench_sweep_1000_speeds_2_jobs(benchmark, tmp_path):
    sweep = prepare(DECK, [("speed", "range", "500:3500:1000")])

    def once():
        return run_sweep(sweep, tmp_path, jobs=2, plots=False)

    outcome = benchmark.pedantic(once, rounds=1, iterations=1)
    benchmark.extra_info["cases"] = len(outcome.records)
    benchmark.extra_info["cases_per_second"] = len(outcome.records) / benchmark.stats.stats.mean


def test_bench_sweep_100_speeds_serial(benchmark, tmp_path):
    sweep = prepare(DECK, [("speed", "range", "500:3500:100")])
    benchmark.pedantic(lambda: run_sweep(sweep, tmp_path, jobs=1, plots=False), rounds=1,
                       iterations=1)
