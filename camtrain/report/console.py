"""Terminal report with rich: input echo, plan, key numbers, warnings, timings."""
from __future__ import annotations

from pathlib import Path

from rich.console import Console
from rich.table import Table

from camtrain.deck.load import LoadedDeck
from camtrain.report.echo import echo_rows
from camtrain.result import Result
from camtrain.scene import Plan


def print_echo(console: Console, deck: LoadedDeck) -> None:
    table = Table(title=f"{deck.model.title}  ({deck.path})", title_justify="left")
    for name in ("field", "value", "unit", "what it is"):
        table.add_column(name, overflow="fold")
    for path, doc, value, unit in echo_rows(deck.model):
        table.add_row(path, value, unit, doc)
    console.print(table)


def print_plan(console: Console, plan: Plan) -> None:
    table = Table(title=f"plan ({plan.mode})", title_justify="left")
    for name in ("effect", "runs", "why"):
        table.add_column(name, overflow="fold")
    for step in plan.steps:
        runs = "yes" if step.chosen else "no"
        if step.chosen and not step.available:
            runs = "not available yet"
        table.add_row(step.effect, runs, step.reason)
    console.print(table)


def print_run(console: Console, result: Result, written: list[Path]) -> None:
    if result.metrics:
        table = Table(title="results", title_justify="left")
        for name in ("metric", "value", "unit", "at cam angle [deg]"):
            table.add_column(name)
        import math

        for name, m in result.metrics.items():
            where = "" if m.angle is None else f"{math.degrees(m.angle):.2f}"
            table.add_row(name, f"{m.value:.6g}", m.unit, where)
        console.print(table)
    for w in result.warnings:
        console.print(f"[yellow]warning:[/] {w}")
    if result.timings:
        times = ", ".join(f"{k} {v * 1e3:.1f} ms" for k, v in result.timings.items())
        console.print(f"time per effect: {times}")
    console.print("wrote " + ", ".join(str(p) for p in written))
