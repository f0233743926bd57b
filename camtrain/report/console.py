"""Terminal report: input echo, plan, key numbers, warnings, limits, timings, progress.

On a terminal the report is drawn by rich (styles, colours); written anywhere else (a pipe, a
file) it is the same characters without styles, drawn by camtrain.report.boxes without
importing rich (a sixth of a short run's process). Both draw from the same :class:`Table`.
"""
from __future__ import annotations

import sys
from contextlib import contextmanager
from pathlib import Path

from camtrain.deck.load import LoadedDeck
from camtrain.report.display import deg, shown
from camtrain.report.echo import echo_rows
from camtrain.report.findings import find
from camtrain.result import Result
from camtrain.scene import Plan


class Table:
    """A table to print: a title, columns (header, justify, style) and rows of plain text (a
    cell may be a (text, style) pair); text is printed literally, never as markup."""

    def __init__(self, title: str, columns: list[tuple[str, str, str | None]]):
        self.title, self.columns, self.rows = title, columns, []

    def add_row(self, *cells) -> None:
        self.rows.append([c if isinstance(c, tuple) else (c, None) for c in cells])

    def texts(self) -> list[str]:
        return [self.title, *(c[0] for c in self.columns), *(t for r in self.rows for t, _ in r)]


class RichOut:
    """The report on a rich console (a terminal, or where plain text would differ)."""

    def __init__(self, stderr: bool = False, console=None):
        if console is None:
            from rich.console import Console

            console = Console(stderr=stderr, highlight=False, soft_wrap=True, emoji=False)
        self.console = console

    @property
    def is_terminal(self) -> bool:
        return self.console.is_terminal

    def rule(self, *parts) -> None:
        self.console.rule(_text(parts))

    def line(self, *parts) -> None:
        self.console.print(_text(parts))

    def table(self, table: Table) -> None:
        from rich.markup import escape
        from rich.table import Table as RichTable
        from rich.text import Text

        out = RichTable(title=escape(table.title), title_justify="left")
        for name, justify, style in table.columns:
            out.add_column(escape(name), justify=justify, overflow="fold", style=style)
        for row in table.rows:
            out.add_row(*(Text(text, style or "") for text, style in row))
        self.console.print(out)


def _text(parts):
    """A rich Text of plain strings and (string, style) pairs."""
    from rich.text import Text

    text = Text()
    for part in parts:
        text.append(*(part if isinstance(part, tuple) else (part,)))
    return text


class PlainOut:
    """The report as plain text on a stream that is not a terminal, character for character
    what :class:`RichOut` prints there (camtrain.report.boxes); text it cannot draw alike goes
    to rich."""

    is_terminal = False

    def __init__(self, stream=None, width: int | None = None):
        from camtrain.report import boxes

        self._stream, self._boxes = stream, boxes
        self.width = boxes.plain_width() if width is None else width
        self._rich = None

    def _write(self, lines: list[str]) -> None:
        (self._stream or sys.stdout).write("".join(line + "\n" for line in lines))

    def _fallback(self) -> RichOut:
        if self._rich is None:
            from rich.console import Console

            self._rich = RichOut(console=Console(
                file=self._stream, highlight=False, soft_wrap=True, emoji=False,
                width=self.width))
        return self._rich

    def rule(self, *parts) -> None:
        texts = [p[0] if isinstance(p, tuple) else p for p in parts]
        if not self._boxes.plain_ok(*texts):
            return self._fallback().rule(*parts)
        self._write([self._boxes.rule("".join(texts), self.width)])

    def line(self, *parts) -> None:
        texts = [p[0] if isinstance(p, tuple) else p for p in parts]
        if not self._boxes.plain_ok(*texts):
            return self._fallback().line(*parts)
        self._write(["".join(texts)])

    def table(self, table: Table) -> None:
        if not self._boxes.plain_ok(*table.texts()):
            return self._fallback().table(table)
        rows = [[text for text, _ in row] for row in table.rows]
        columns = [(name, justify) for name, justify, _ in table.columns]
        self._write(self._boxes.table(table.title, columns, rows, self.width))


def terminal(stderr: bool = False):
    """The report's output on standard output (or error): plain text when rich would print
    no styles there, else rich."""
    from camtrain.report.boxes import is_plain_stream

    if is_plain_stream(sys.stderr if stderr else sys.stdout):
        return PlainOut(sys.stderr if stderr else None)
    return RichOut(stderr=stderr)


def key_metric_names(result: Result) -> list[str]:
    """The metrics an engineer reads first, in plan order: those the effects that ran declare
    (``EffectSpec.key_metrics``); a run without a plan (``camtrain lift``) takes what the
    valve-train effects declare. Every metric is in summary.json and report.txt."""
    from camtrain.catalogue import DEFAULT_KIND, KINDS

    specs = result.plan.effects if result.plan is not None else KINDS[DEFAULT_KIND].effects
    names = dict.fromkeys(n for spec in specs for n in spec.key_metrics)
    return [n for n in names if n in result.metrics]


def summary_tables(result: Result, deck) -> list[Table]:
    """The summary tables the effects that ran declare (``EffectSpec.summary``), in plan
    order: the crank-bearing table, the FLAME total, the camshaft bearings' orbits."""
    import importlib

    if result.plan is None:
        return []
    tables: list[Table] = []
    for spec in result.plan.effects:
        if spec.summary:
            module, function = spec.summary.split(":")
            tables += getattr(importlib.import_module(module), function)(result, deck)
    return tables


def print_echo(out, deck: LoadedDeck) -> None:
    table = Table(f"{deck.model.title}  ({deck.path})",
                  [(name, "left", None) for name in ("field", "value", "unit", "what it is")])
    for path, doc, value, unit in echo_rows(deck.model):
        table.add_row(path, value, unit, doc)
    out.table(table)


def print_plan(out, plan: Plan, timings: dict[str, float] | None = None) -> None:
    table = Table(f"plan ({plan.mode})", [(name, "right" if name == "time" else "left", None)
                                          for name in ("effect", "runs", "time", "why")])
    for step in plan.steps:
        runs = "yes" if step.chosen else "no"
        t = (timings or {}).get(step.effect)
        table.add_row(step.effect, runs, "" if t is None else f"{t * 1e3:.1f} ms", step.reason)
    out.table(table)


def print_run(out, result: Result, written: list[Path], checks=None,
              out_dir: Path | None = None, deck=None) -> None:
    """Key numbers, the effects' summary tables, warnings and findings, limits, and where the
    files went. ``deck`` is the run's deck model (the summaries read its geometry)."""
    keys = key_metric_names(result)
    if keys:
        table = Table("key results", [
            ("quantity", "left", None), ("value", "right", None), ("unit", "left", None),
            ("at [deg]", "right", None), ("what it is", "left", "dim")])
        for name in keys:
            m = result.metrics[name]
            value, unit = shown(name, m.value, m.unit)
            table.add_row(name, value, unit, deg(m.angle), m.description)
        out.table(table)
    for table in summary_tables(result, deck):
        out.table(table)
    if result.metrics and out_dir is not None:      # a run's files (camtrain lift has a table)
        out.line(f"{len(result.metrics)} results in all (summary.json, report.txt)")
    for w in result.warnings + find(result).messages(result.warnings):
        out.line(("warning:", "yellow"), f" {w}")
    print_checks(out, checks or [])
    if out_dir is not None:
        out.line(f"wrote {len(written)} files to {out_dir}")
    elif written:
        out.line("wrote " + ", ".join(str(p) for p in written))


def print_checks(out, checks) -> None:
    for c in checks:
        mark = ("ok  ", "green") if c.ok else ("FAIL", "bold red")
        out.line(mark, f" {c.text()}")


@contextmanager
def progress_bar(enabled: bool = True):
    """A rich progress bar on standard error; yields a Progress (or None when disabled).

    Shown only on a terminal: logs and CI output stay clean (and rich is not imported).
    """
    from camtrain.report.boxes import is_plain_stream

    if not enabled or is_plain_stream(sys.stderr):
        yield None
        return
    from rich.console import Console

    console = Console(stderr=True, highlight=False, soft_wrap=True)
    if not console.is_terminal:
        yield None
        return
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    with Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                  TimeElapsedColumn(), console=console, transient=True) as progress:
        yield progress
