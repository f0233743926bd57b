"""The camtrain command line: a thin layer over camtrain.api.

Exit codes: 0 ok; 1 design limits violated; 2 invalid input; 3 physically impossible geometry;
4 a solver did not converge; 70 internal error (a bug: please report it).
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

import click

from camtrain import __version__
from camtrain.errors import EXIT_INTERNAL, CamtrainError
from camtrain.interrupts import Terminated, interruptible, terminable
from camtrain.lazy import resolve

#: --units of the commands that write tables: the deck's units (default) or SI for pipelines
UNITS_OPTION = dict(type=click.Choice(["deck", "si"]), default="deck", show_default=True,
                    help="Units of the written tables and JSON: deck (mm, deg, µm, MPa, ..., each "
                         "with its unit) or si (m, rad, Pa, ... for machine pipelines).")

MECHANISM_CHOICES = ("flat", "domed", "finger", "rocker", "pushrod", "desmodromic",
                     "roller_finger", "roller_rocker", "roller_tappet", "pushrod_roller",
                     "journal_bearing", "engine")


def _console(stderr: bool = False):
    """The report's output: rich on a terminal, plain text (no rich import) elsewhere."""
    from camtrain.report.console import terminal

    return terminal(stderr)


def _fail(exc: CamtrainError) -> None:
    click.echo(f"error: {exc}", err=True)
    sys.exit(exc.exit_code)


class _Group(click.Group):
    """Maps our errors to exit codes and keeps tracebacks away from users."""

    def invoke(self, ctx):
        try:
            with terminable():      # SIGTERM unwinds as Ctrl-C: no staging left behind
                return super().invoke(ctx)
        except CamtrainError as exc:
            _fail(exc)
        except (click.exceptions.Exit, click.exceptions.Abort, click.ClickException,
                SystemExit):
            raise
        except KeyboardInterrupt as exc:
            terminated = isinstance(exc, Terminated)
            click.echo("terminated" if terminated else "interrupted", err=True)
            sys.exit(143 if terminated else 130)
        except Exception as exc:  # noqa: BLE001 - last line of defence against tracebacks
            click.echo(f"internal error in camtrain {__version__}: {type(exc).__name__}: {exc}\n"
                       "This is a bug; please report it with the deck that caused it.", err=True)
            sys.exit(EXIT_INTERNAL)

    # The study commands live in modules of their own, imported when the command is invoked
    # or listed (click's lazy-loading group, "Advanced patterns" of click's documentation): a
    # process that runs one command loads only that command's module. `camtrain --help` lists
    # them all, and so imports them all.

    def list_commands(self, ctx) -> list[str]:
        return sorted({*super().list_commands(ctx), *LAZY_COMMANDS})

    def get_command(self, ctx, name: str):
        if name in LAZY_COMMANDS and name not in self.commands:
            command = resolve(LAZY_COMMANDS[name])
            assert command.name == name, (name, command.name)   # the table names it right
            self.add_command(command)
        return super().get_command(ctx, name)

    def resolve_command(self, ctx, args):
        if args and self.get_command(ctx, str(args[0])) is None:
            for name in LAZY_COMMANDS:  # a misspelt command's "did you mean" weighs them all
                self.get_command(ctx, name)
        return super().resolve_command(ctx, args)


#: the study commands by name: "module:command object" (their modules import only click, and
#: camtrain.errors, at module level; each is imported on first use, see _Group.get_command)
LAZY_COMMANDS = {
    "accuracy": "camtrain.cli_accuracy:accuracy",
    "design": "camtrain.cli_design:design",
    "dynamics-speed": "camtrain.cli_dynamics:dynamics_speed",
    "ehl": "camtrain.cli_ehl:ehl",
    "fit": "camtrain.cli_fit:fit",
    "friction-map": "camtrain.cli_friction_map:friction_map",
    "leakdown": "camtrain.cli_dynamics:leakdown",
    "optimize": "camtrain.cli_design:optimize",
    "sensitivity": "camtrain.cli_sensitivity:sensitivity",
    "sweep": "camtrain.cli_sweep:sweep",
    "warmup": "camtrain.cli_warmup:warmup",
}


@click.group(cls=_Group, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="camtrain")
def main() -> None:
    """camtrain: valve-train kinematics, loads and tribology from a TOML deck.

    \b
    Start with a template deck, edit it, check it, run it:
      camtrain template finger > my.toml
      camtrain check my.toml
      camtrain run my.toml --out out/my
    """
    from camtrain.numerics.compile_notice import listen

    listen(lambda text: click.echo(f"note: {text}", err=True))


@main.command()
@click.argument("mechanism", type=click.Choice(MECHANISM_CHOICES))
def template(mechanism: str) -> None:
    """Write a commented template deck for MECHANISM to standard output."""
    from camtrain.deck.templates import render_template

    click.echo(render_template(mechanism), nl=False)


@main.command()
@click.option("--out", "out", type=click.Path(dir_okay=False, writable=True), default=None,
              help="Write to this file instead of standard output.")
@click.option("--markdown", is_flag=True, help="Write the deck reference page instead.")
@click.option("--kind", "kind", type=click.Choice(["valve_train", "journal_bearing", "engine"]),
              default=None,
              help="The schema of this deck kind alone (default: one schema for every kind, "
                   "picked by the deck's kind; templates' #:schema line points at it).")
def schema(out: str | None, markdown: bool, kind: str | None) -> None:
    """Write the JSON Schema of a deck (for editors that validate while typing)."""
    import json

    if markdown:
        from camtrain.deck.reference import markdown as reference

        text = reference()
    else:
        from camtrain.deck.jsonschema import deck_json_schema

        text = json.dumps(deck_json_schema(kind), indent=2, ensure_ascii=False) + "\n"
    if out:
        Path(out).write_text(text, encoding="utf-8")
    else:
        click.echo(text, nl=False)


@main.command()
@click.argument("deck", type=str)
@click.option("--quiet", "-q", is_flag=True, help="Print nothing; the exit code tells.")
@click.option("--full", is_flag=True,
              help="Echo every field with its description (defaults included), not only the "
                   "fields the deck sets.")
def check(deck: str, quiet: bool, full: bool) -> None:
    """Validate DECK ('-' for standard input), run its cheap geometry checks and echo the input
    and the plan. Exit 0, 2 (invalid input) or 3 (impossible geometry, as `run` would)."""
    from camtrain import api
    from camtrain.report.console import print_echo, print_plan

    loaded = api.load(deck)
    plan = api.plan(loaded)
    for w in api.implausible(loaded):     # before the geometry: it explains a failure there
        click.echo(f"warning: {w}", err=True)
    checked, warnings = api.check(loaded)
    if not quiet:
        console = _console()
        if full:
            print_echo(console, loaded)
        else:
            _print_given(loaded)
        print_plan(console, plan)
        for message in getattr(loaded.model, "advisories", list)():
            click.echo(f"warning: {message}")
        for w in warnings:
            click.echo(f"warning: {w}")
        click.echo(f"{loaded.path}: valid; {checked}")


def _print_given(loaded) -> None:
    """The fields the deck sets, one per line (path = value unit): reads at 80 columns."""
    from camtrain.deck.load import parse_toml
    from camtrain.report.echo import given_rows

    rows, defaults = given_rows(loaded.model, parse_toml(loaded.text, loaded.path))
    click.echo(f"{loaded.model.title}  ({loaded.path})")
    for path, _doc, value, unit in rows:
        click.echo(f"  {path} = {value}" + ("" if unit in ("-", "") else f" {unit}"))
    click.echo(f"  ... and {defaults} fields at their defaults (check --full: every field)")


#: exit-code precedence over a batch of decks: a bug first, then invalid input, then the other
#: failures of a deck, then violated limits; 0 only when every deck ran and passed.
EXIT_PRECEDENCE = (EXIT_INTERNAL, 2, 3, 4, 1, 0)


@main.command()
@click.argument("decks", nargs=-1, required=True, type=str, metavar="DECK...")
@click.option("--out", "out", type=click.Path(file_okay=False), default=None,
              help="Output directory (default out/<deck name>); with several decks each goes "
                   "to OUT/<deck name>.")
@click.option("--check", is_flag=True,
              help="Check the decks' [limits]: exit 1 if any is violated (or cannot be checked).")
@click.option("--junit", type=click.Path(dir_okay=False), default=None,
              help="Write a JUnit XML report: a test suite per deck, a test case per limit.")
@click.option("--plots", type=click.Choice(["sheets", "pdf", "all", "none"]), default="sheets",
              show_default=True,
              help="sheets: the multi-panel sheets as PNG; pdf: the sheets as PNG and PDF; all: "
                   "also every panel on its own (PNG and PDF); none.")
@click.option("--no-plots", is_flag=True, help="Same as --plots none (fastest, for CI).")
@click.option("--quiet", "-q", is_flag=True, help="Print only errors and violated limits.")
@click.option("--json", "as_json", is_flag=True,
              help="Print summary.json to standard output (a list for several decks).")
@click.option("--units", **UNITS_OPTION)
@click.option("--set", "sets", multiple=True, metavar="PATH=VALUE",
              help="Change a deck field for this run, in the deck's units (repeatable), e.g. "
                   "solver.angle_points=720 or tribology.entrainment=mean.")
def run(decks: tuple[str, ...], out: str | None, check: bool, junit: str | None, plots: str,
        no_plots: bool, quiet: bool, as_json: bool, units: str, sets: tuple[str, ...]) -> None:
    """Run DECK... and write cycle.csv, report.txt, plot sheets and summary.json for each.

    \b
    Exit codes over all decks, the first that applies: 70 internal error, 2 invalid input,
    3 impossible geometry, 4 no convergence, 1 a limit violated (--check), 0 all passed.
    An invalid deck among several is reported and the others still run.
    """
    import json

    from camtrain.report.junit import junit_xml

    plots = "none" if no_plots else plots
    show = not (quiet or as_json)
    # a quiet or --json run prints no tables: it does not import the terminal library
    console = _console() if show else None
    targets = _output_dirs(decks, out)
    from camtrain.numerics import compile_notice

    if quiet:
        compile_notice.listen(None)
    reports, summaries, codes = [], [], []
    from contextlib import nullcontext

    if show:
        from camtrain.report.console import progress_bar
    with interruptible():
        for i, (deck, out_dir) in enumerate(zip(decks, targets, strict=True)):
            place = f"[{i + 1}/{len(decks)}] " if len(decks) > 1 else ""
            # one transient bar per deck, gone before the deck's report is printed: nothing
            # is drawn under a live bar, so the terminal keeps no trace of it
            with progress_bar(enabled=True) if show else nullcontext() as bar:
                if bar:     # a compile notice goes above the live bar, not onto its line
                    compile_notice.listen(lambda text, bar=bar: bar.console.print(
                        f"note: {text}", markup=False, highlight=False))
                report, summary, after = _run_one(deck, out_dir, plots, bar, console,
                                                  show=show, check=check, units=units,
                                                  place=place, sets=sets)
            after()
            reports.append(report)
            summaries.append(summary)
            codes.append(report.exit_code if (check or report.exit_code != 1) else 0)
    if junit:
        from camtrain.report.tables import atomic_write

        Path(junit).parent.mkdir(parents=True, exist_ok=True)
        atomic_write(Path(junit), junit_xml(reports))
    if as_json:
        data = summaries[0] if len(decks) == 1 else summaries
        click.echo(json.dumps(data, indent=2, allow_nan=False, ensure_ascii=False))
    elif len(decks) > 1 and not quiet:
        _print_batch(console, reports, check)
    sys.exit(_batch_exit_code(codes))


def _batch_exit_code(codes: list[int]) -> int:
    """The most severe code of a batch (an unknown non-zero code ranks just below a bug)."""
    rank = {c: i for i, c in enumerate(EXIT_PRECEDENCE)}
    return min(codes, key=lambda c: rank.get(c, 0.5), default=0)


def _output_dirs(decks: tuple[str, ...], out: str | None) -> list[Path]:
    """One directory per deck; deck names that repeat get a numeric suffix."""
    stems, dirs = {}, []
    for deck in decks:
        stem = Path(deck).stem if deck != "-" else "stdin"
        stems[stem] = stems.get(stem, 0) + 1
        name = stem if stems[stem] == 1 else f"{stem}-{stems[stem]}"
        if len(decks) == 1:
            dirs.append(Path(out) if out else Path("out") / name)
        else:
            dirs.append(Path(out or "out") / name)
    return dirs


def _escape(text: str) -> str:
    """User and deck text as rich prints it literally (a '[' is not markup); imports rich only
    when something is printed with it."""
    from rich.markup import escape

    return escape(text)


def _say(bar, text: str) -> None:
    """A line on standard error now: through the live bar's console when one is drawn (it is
    printed above the bar, which is then redrawn below it), else plainly."""
    if bar is not None:
        bar.console.print(text, markup=False, highlight=False, soft_wrap=True)
    else:
        click.echo(text, err=True)


def _run_one(deck: str, out_dir: Path, plots: str, bar, console, *, show: bool, check: bool,
             units: str = "deck", place: str = "", sets: tuple[str, ...] = ()):
    """Load, run, check and write one deck; errors become a report, never an exception.

    Returns (report, summary, after): ``after()`` prints the deck's report once its progress
    bar is gone."""
    from contextlib import ExitStack
    from functools import partial

    from camtrain import api
    from camtrain.output_lock import output_lock
    from camtrain.report.junit import DeckReport
    from camtrain.report.limits import violated
    from camtrain.report.outputs import check_limits, write_run
    from camtrain.report.tables import summary_dict

    name = out_dir.name
    report = DeckReport(name=name, path=deck)
    start = time.perf_counter()
    task = bar.add_task(_escape(f"{place}{name}: loading"), total=None) if bar else None

    def step(label: str, done: int, total: int) -> None:
        if bar:
            bar.update(task, description=_escape(f"{place}{name}: {label}"), completed=done,
                       total=total)

    lock = ExitStack()
    try:
        lock.enter_context(output_lock(out_dir))   # one writer per directory, from the start
        loaded = api.load(deck, sets)
        sizes = api.implausible(loaded)
        for w in sizes:                   # before the run: it explains a geometry failure there
            _say(bar, f"warning: {w}")
        result = api.run(loaded, progress=lambda effect, done, total: step(
            f"running {effect} (effect {min(done + 1, total)} of {total})", done, total))
        for w in sizes:
            result.warn(w)
        wall = time.perf_counter() - start
        checks = check_limits(result, loaded)
        step("writing tables", 0, 1)
        written = write_run(result, loaded, out_dir, wall, checks=checks, plots=plots,
                            progress=step, units=units)
    except CamtrainError as exc:
        shown = "<stdin>" if deck == "-" else deck
        message = str(exc) if shown in str(exc) else f"{shown}: {exc}"
        report.error, report.exit_code = message, exc.exit_code
        report.seconds = time.perf_counter() - start
        return report, {"deck": {"path": deck}, "error": str(exc), "exit_code": exc.exit_code}, \
            lambda: click.echo(f"error: {report.error}", err=True)
    except Exception as exc:  # noqa: BLE001 - one bad deck must not hide the others' results
        report.error = f"{deck}: internal error: {type(exc).__name__}: {exc}"
        report.exit_code = EXIT_INTERNAL
        report.seconds = time.perf_counter() - start
        return report, {"deck": {"path": deck}, "error": report.error,
                        "exit_code": EXIT_INTERNAL}, \
            lambda: click.echo(f"error: {report.error}\nThis is a bug; please report it with "
                               "the deck.", err=True)
    finally:
        lock.close()
        if bar and task is not None:
            bar.remove_task(task)
    report.seconds = time.perf_counter() - start
    report.checks = checks
    report.exit_code = 1 if violated(checks) else 0
    after = partial(_print_deck, console, deck, loaded, result, written, checks, out_dir,
                    show=show, check=check)
    return report, summary_dict(result, loaded, wall, checks, units), after


def _print_deck(console, deck: str, loaded, result, written, checks, out_dir, *, show: bool,
                check: bool) -> None:
    """A deck's report after its run (or only its violated limits with --check --quiet)."""
    from camtrain.report.limits import violated

    if show:
        from camtrain.report.console import print_plan, print_run

        console.rule((loaded.model.title, "bold"), f"  ({deck})")
        print_plan(console, result.plan, result.timings)
        print_run(console, result, written, checks, out_dir, loaded.model)
    elif check and violated(checks):
        from camtrain.report.console import print_checks

        click.echo(f"{deck}:")
        print_checks(console or _console(), violated(checks))


def _print_batch(console, reports, check: bool) -> None:
    from camtrain.report.console import Table

    table = Table("decks", [(col, "right" if col == "time [s]" else "left", None)
                            for col in ("deck", "status", "limits", "time [s]")])
    for r in reports:
        bad = sum(1 for c in r.checks if not c.ok)
        if r.error:
            status = (f"error (exit {r.exit_code})", "red")
        elif bad:
            status = ("limits violated", "red" if check else "yellow")
        else:
            status = ("ok", "green")
        limits = f"{len(r.checks) - bad}/{len(r.checks)} pass" if r.checks else "none set"
        table.add_row(r.path, status, limits, f"{r.seconds:.2f}")
    console.table(table)


@main.command("lift")
@click.argument("deck", type=str)
@click.option("--out", "out", type=click.Path(file_okay=False), default=None,
              help="Output directory (default: out/<deck name>).")
@click.option("--points", type=click.IntRange(16, 1_000_000), default=None,
              help="Angles over one revolution (default: the deck's solver.angle_points).")
@click.option("--no-plots", is_flag=True, help="Write the table only.")
@click.option("--quiet", "-q", is_flag=True, help="Print only errors.")
@click.option("--units", **UNITS_OPTION)
def lift_command(deck: str, out: str | None, points: int | None, no_plots: bool,
                 quiet: bool, units: str) -> None:
    """Lift, velocity, acceleration and jerk of DECK's lift law: lift.csv and a plot sheet."""
    from camtrain import api
    from camtrain.output_lock import output_lock
    from camtrain.report.outputs import write_staged
    from camtrain.report.tables import write_table

    loaded = api.load(deck)
    result = api.lift(loaded, points)
    out_dir = Path(out) if out else Path("out") / (Path(deck).stem if deck != "-" else "stdin")

    def write(stage: Path) -> None:
        write_table(result, stage / "lift.csv", units)
        if not no_plots:
            from camtrain.report.plots import lift_sheet

            lift_sheet(result, f"{loaded.model.title}: lift law", stage / "lift")

    with interruptible(), output_lock(out_dir):
        written = write_staged(out_dir, write)
    if not quiet:
        from camtrain.report.console import print_run

        print_run(_console(), result, written)


if __name__ == "__main__":  # pragma: no cover
    main()
