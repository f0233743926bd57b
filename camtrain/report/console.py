"""Terminal report with rich: input echo, plan, key numbers, warnings, limits, timings, progress."""
from __future__ import annotations

from contextlib import contextmanager
from pathlib import Path

from rich.console import Console
from rich.markup import escape
from rich.table import Table

from camtrain.deck.load import LoadedDeck
from camtrain.report.display import deg, shown
from camtrain.report.echo import echo_rows
from camtrain.report.findings import find
from camtrain.result import Result
from camtrain.scene import Plan

#: the numbers an engineer looks at first, in this order (all metrics are in summary.json)
KEY_METRICS = ("max_lift", "power_loss_mean", "film_min_at_max_lift", "film_min", "hertz_max",
               "hertz_at_max_lift", "load_max", "load_min", "bounce_speed",
               "friction_torque_peak", "max_velocity", "min_acceleration", "max_acceleration")


def print_echo(console: Console, deck: LoadedDeck) -> None:
    table = Table(title=escape(f"{deck.model.title}  ({deck.path})"), title_justify="left")
    for name in ("field", "value", "unit", "what it is"):
        table.add_column(name, overflow="fold")
    for path, doc, value, unit in echo_rows(deck.model):
        table.add_row(escape(path), escape(value), escape(unit), escape(doc))
    console.print(table)


def print_plan(console: Console, plan: Plan, timings: dict[str, float] | None = None) -> None:
    table = Table(title=f"plan ({plan.mode})", title_justify="left")
    for name in ("effect", "runs", "time", "why"):
        table.add_column(name, overflow="fold", justify="right" if name == "time" else "left")
    for step in plan.steps:
        runs = "yes" if step.chosen else "no"
        t = (timings or {}).get(step.effect)
        table.add_row(escape(step.effect), runs, "" if t is None else f"{t * 1e3:.1f} ms",
                      escape(step.reason))
    console.print(table)


def print_run(console: Console, result: Result, written: list[Path], checks=None,
              out_dir: Path | None = None) -> None:
    """Key numbers, warnings and findings, limits, and where the files went."""
    keys = [k for k in KEY_METRICS if k in result.metrics]
    if keys:
        table = Table(title="key results", title_justify="left")
        for name, just in (("quantity", "left"), ("value", "right"), ("unit", "left"),
                           ("at [deg]", "right"), ("what it is", "left")):
            table.add_column(name, justify=just, overflow="fold",
                             style="dim" if name == "what it is" else None)
        for name in keys:
            m = result.metrics[name]
            value, unit = shown(name, m.value, m.unit)
            table.add_row(name, value, unit, deg(m.angle), escape(m.description))
        console.print(table)
    elif result.metrics:
        console.print(f"{len(result.metrics)} results (see summary.json)")
    for w in result.warnings + find(result).messages(result.warnings):
        console.print(f"[yellow]warning:[/] {escape(w)}")
    print_checks(console, checks or [])
    if out_dir is not None:
        console.print(escape(f"wrote {len(written)} files to {out_dir}"))
    elif written:
        console.print(escape("wrote " + ", ".join(str(p) for p in written)))


def print_checks(console: Console, checks) -> None:
    for c in checks:
        mark = "[green]ok[/]  " if c.ok else "[bold red]FAIL[/]"
        console.print(f"{mark} {escape(c.text())}")


@contextmanager
def progress_bar(console: Console, enabled: bool = True):
    """A rich progress bar on the given console; yields a Progress (or None when disabled).

    Shown only on a terminal: logs and CI output stay clean.
    """
    if not enabled or not console.is_terminal:
        yield None
        return
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    with Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                  TimeElapsedColumn(), console=console, transient=True) as progress:
        yield progress
