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

MECHANISM_CHOICES = ("flat", "domed", "finger", "rocker", "pushrod", "desmodromic")


def _console(stderr: bool = False):
    from rich.console import Console

    return Console(stderr=stderr, highlight=False, soft_wrap=True)


def _fail(exc: CamtrainError) -> None:
    click.echo(f"error: {exc}", err=True)
    sys.exit(exc.exit_code)


class _Group(click.Group):
    """Maps our errors to exit codes and keeps tracebacks away from users."""

    def invoke(self, ctx):
        try:
            return super().invoke(ctx)
        except CamtrainError as exc:
            _fail(exc)
        except (click.exceptions.Exit, click.exceptions.Abort, click.ClickException,
                SystemExit):
            raise
        except KeyboardInterrupt:
            click.echo("interrupted", err=True)
            sys.exit(130)
        except Exception as exc:  # noqa: BLE001 - last line of defence against tracebacks
            click.echo(f"internal error in camtrain {__version__}: {type(exc).__name__}: {exc}\n"
                       "This is a bug; please report it with the deck that caused it.", err=True)
            sys.exit(EXIT_INTERNAL)


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
def schema(out: str | None, markdown: bool) -> None:
    """Write the JSON Schema of a deck (for editors that validate while typing)."""
    import json

    if markdown:
        from camtrain.deck.reference import markdown as reference

        text = reference()
    else:
        from camtrain.deck.jsonschema import deck_json_schema

        text = json.dumps(deck_json_schema(), indent=2, ensure_ascii=False) + "\n"
    if out:
        Path(out).write_text(text, encoding="utf-8")
    else:
        click.echo(text, nl=False)


@main.command()
@click.argument("deck", type=str)
@click.option("--quiet", "-q", is_flag=True, help="Print nothing; the exit code tells.")
def check(deck: str, quiet: bool) -> None:
    """Validate DECK ('-' for standard input): echo the input and the plan. Exit 0 or 2."""
    from camtrain import api
    from camtrain.report.console import print_echo, print_plan

    loaded = api.load(deck)
    plan = api.plan(loaded)
    if not quiet:
        console = _console()
        print_echo(console, loaded)
        print_plan(console, plan)
        console.print(f"[green]{loaded.path}: valid[/]")


@main.command()
@click.argument("deck", type=str)
@click.option("--out", "out", type=click.Path(file_okay=False), default=None,
              help="Output directory (default: out/<deck name>).")
@click.option("--quiet", "-q", is_flag=True, help="Print only errors.")
@click.option("--json", "as_json", is_flag=True, help="Print summary.json to standard output.")
def run(deck: str, out: str | None, quiet: bool, as_json: bool) -> None:
    """Run DECK and write summary.json and cycle.csv into the output directory."""
    import json

    from camtrain import api
    from camtrain.report.console import print_plan, print_run
    from camtrain.report.tables import summary_dict

    start = time.perf_counter()
    loaded = api.load(deck)
    result = api.run(loaded)
    wall = time.perf_counter() - start
    out_dir = Path(out) if out else Path("out") / (Path(deck).stem if deck != "-" else "stdin")
    written = api.write(result, loaded, out_dir, wall)
    if as_json:
        click.echo(json.dumps(summary_dict(result, loaded, wall), indent=2, allow_nan=False))
    elif not quiet:
        console = _console()
        print_plan(console, result.plan)
        print_run(console, result, written)


@main.command("lift")
@click.argument("deck", type=str)
@click.option("--out", "out", type=click.Path(file_okay=False), default=None,
              help="Output directory (default: out/<deck name>).")
@click.option("--points", type=click.IntRange(16, 1_000_000), default=None,
              help="Angles over one revolution (default: the deck's solver.angle_points).")
@click.option("--no-plots", is_flag=True, help="Write the table only.")
@click.option("--quiet", "-q", is_flag=True, help="Print only errors.")
def lift_command(deck: str, out: str | None, points: int | None, no_plots: bool,
                 quiet: bool) -> None:
    """Lift, velocity, acceleration and jerk of DECK's lift law: lift.csv and a plot sheet."""
    from camtrain import api
    from camtrain.report.tables import write_table

    loaded = api.load(deck)
    result = api.lift(loaded, points)
    out_dir = Path(out) if out else Path("out") / (Path(deck).stem if deck != "-" else "stdin")
    written = [write_table(result, out_dir / "lift.csv")]
    if not no_plots:
        from camtrain.report.plots import lift_sheet

        written += lift_sheet(result, f"{loaded.model.title}: lift law", out_dir / "lift")
    if not quiet:
        from camtrain.report.console import print_run

        print_run(_console(), result, written)


if __name__ == "__main__":  # pragma: no cover
    main()
