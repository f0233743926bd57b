"""`camtrain sweep`: parametric studies from the command line.

Imports only click at module level, so that `camtrain --help` stays fast; everything else is
imported when the command runs.
"""
from __future__ import annotations

import sys

import click

_SPEC_OPTIONS = ("--values", "--range", "--relative")


def _pair_specs(args: list[str], options: tuple[str, ...] = _SPEC_OPTIONS,
                hint: str = "--values A,B,C, --range START:STOP:N or --relative -50%:+50%:N"
                ) -> list[tuple[str, str, str]]:
    """Pair each --param with the option of ``options`` (--values/--range/--relative) that
    follows it, in order.

    click collects repeated options per option and loses how they interleave, so the raw
    arguments are read once here; click still parses (and documents) the options themselves.
    """
    out: list[list[str | None]] = []
    it = iter(args)
    for arg in it:
        if arg == "--":
            break
        opt, eq, inline = arg.partition("=")
        if opt not in ("--param", "-p") + options:
            continue
        value = inline if eq else next(it, None)
        if value is None:
            break  # click reports the missing value
        if opt in ("--param", "-p"):
            out.append([value, None, None])
            continue
        kind = opt[2:]
        if not out:
            raise click.UsageError(f"{opt} {value}: give --param NAME before it")
        if out[-1][1] is not None:
            raise click.UsageError(f"{opt} {value}: --param {out[-1][0]} already has "
                                   f"--{out[-1][1]} {out[-1][2]}; give one list per --param")
        out[-1][1], out[-1][2] = kind, value
    for name, kind, _ in out:
        if kind is None:
            raise click.UsageError(f"--param {name}: give its values with {hint}")
    return [(n, k, v) for n, k, v in out]


class _SweepCommand(click.Command):
    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        ctx.meta["camtrain.sweep.specs"] = _pair_specs(list(args))
        return super().parse_args(ctx, args)


@click.command(cls=_SweepCommand, context_settings={"help_option_names": ["-h", "--help"]})
@click.argument("deck", type=str)
@click.option("--param", "-p", "params", multiple=True, metavar="NAME",
              help="Parameter to vary: base_radius, cam_width, spring_rate, speed, "
                   "follower_radius, viscosity, equivalent_mass, or a dotted deck path such as "
                   "lift.four_power.max_lift. Repeat for a grid.")
@click.option("--values", "values_", multiple=True, metavar="A,B,C",
              help="Values of the preceding --param, in the deck field's unit.")
@click.option("--range", "range_", multiple=True, metavar="START:STOP:N",
              help="N evenly spaced values from START to STOP (both included).")
@click.option("--relative", "relative_", multiple=True, metavar="-P%:+P%:N",
              help="N values from -P % to +P % of the deck's datum value.")
@click.option("--zip", "zipped", is_flag=True,
              help="Pair the parameters' values (equal lengths) instead of a full grid.")
@click.option("--set", "sets", multiple=True, metavar="PATH=VALUE",
              help="Change a deck field for every case (deck units), e.g. "
                   "solver.angle_points=360.")
@click.option("--out", "out", type=click.Path(file_okay=False), default=None,
              help="Output directory (default: out/<deck name>_sweep).")
@click.option("--jobs", "-j", type=int, default=None,
              help="Processes: this one and N-1 workers (default: the CPUs available; 1 runs "
                   "in this process).")
@click.option("--scheduler", default=None, metavar="ADDRESS",
              help="Run the cases on this Dask distributed scheduler, e.g. tcp://host:8786 "
                   "(needs camtrain[dask]).")
@click.option("--resume", is_flag=True,
              help="Keep the finished cases in OUT/sweep.csv and run only the others (all run "
                   "again when a file the deck reads changed).")
@click.option("--force", is_flag=True,
              help="Replace the sweep already in OUT (without this or --resume it is refused).")
@click.option("--no-plots", is_flag=True, help="Write the tables only.")
@click.option("--overlay-max", type=click.IntRange(0, 200), default=20, show_default=True,
              help="At most this many cases in the per-angle overlay plot.")
@click.option("--quiet", "-q", is_flag=True, help="No progress bar or summary.")
@click.option("--write-decks", is_flag=True,
              help="Also write each case's deck as OUT/decks/case_NNNNN.toml.")
@click.option("--units", type=click.Choice(["deck", "si"]), default="deck", show_default=True,
              help="Units of sweep.csv, the curves and the trend tables: deck (mm, µm, MPa, ... "
                   "each with its unit) or si (for machine pipelines). Plots are in deck units.")
@click.pass_context
def sweep(ctx: click.Context, deck: str, params, values_, range_, relative_, zipped: bool,
          sets, out: str | None, jobs: int | None, scheduler: str | None, resume: bool,
          force: bool, no_plots: bool, overlay_max: int, quiet: bool, write_decks: bool,
          units: str) -> None:
    """Run DECK for many values of one or more parameters (Ball's parametric studies).

    \b
    Examples:
      camtrain sweep deck.toml --param base_radius --values 14,16,18,20
      camtrain sweep deck.toml --param speed --range 1000:4000:13 --jobs 4
      camtrain sweep deck.toml --param spring_rate --relative -50%:+50%:11
      camtrain sweep deck.toml -p base_radius --values 16,18 -p speed --values 1500,2500

    Writes sweep.csv (one row per case, with status and message), trends.csv and trends.md
    (rises / falls per metric and parameter), and plots. Failed cases are recorded and the
    sweep goes on. Exit codes: 0 done (even with failed cases), 2 bad arguments or deck,
    70 an internal error in some case, 130 interrupted, 143 terminated (use --resume).
    """
    from camtrain.errors import EXIT_INTERNAL

    outcome, out_dir = run_resumable(lambda: _run(
        ctx, deck, zipped, sets, out, jobs, scheduler, resume, no_plots, overlay_max, quiet,
        units, write_decks, force))
    for note in outcome.notes:
        click.echo(f"note: {note}", err=True)
    if not quiet:
        counts = ", ".join(f"{outcome.count(s)} {s}" for s in ("ok", "lost_contact", "failed",
                                                              "error") if outcome.count(s))
        reused = f" ({outcome.reused} reused)" if outcome.reused else ""
        if outcome.route is not None:
            click.echo(outcome.route.describe())
        click.echo(f"{len(outcome.records)} cases{reused}: {counts}. Wrote {out_dir}/sweep.csv, "
                   f"trends.md"
                   + (", flame.md" if any(p.name == "flame.md" for p in outcome.written) else "")
                   + ("" if no_plots else ", plots/"))
    if outcome.count("error"):
        click.echo("some cases hit an internal error (a bug in camtrain; see sweep.csv)",
                   err=True)
        sys.exit(EXIT_INTERNAL)


def run_resumable(study):
    """Run ``study()``, a study that keeps its finished cases in sweep.csv: an input error
    exits with its code, Ctrl-C (130) and SIGTERM (143) say how to continue."""
    from camtrain.errors import CamtrainError
    from camtrain.interrupts import Terminated, terminable

    try:
        with terminable():   # the workers are stopped and the finished cases kept
            return study()
    except CamtrainError as exc:
        click.echo(f"error: {exc}", err=True)
        sys.exit(exc.exit_code)
    except KeyboardInterrupt as exc:
        click.echo("interrupted: finished cases are in sweep.csv; continue with --resume",
                   err=True)
        sys.exit(143 if isinstance(exc, Terminated) else 130)


def _run(ctx, deck, zipped, sets, out, jobs, scheduler, resume, no_plots, overlay_max, quiet,
         units="deck", write_decks=False, force=False):
    from pathlib import Path

    from camtrain.errors import CamtrainError
    from camtrain.study.runner import prepare, run_sweep

    specs = ctx.meta["camtrain.sweep.specs"]
    if not specs:
        raise click.UsageError("nothing to sweep: give --param NAME with --values, --range or "
                               "--relative")
    if jobs is not None and jobs < 1:
        raise CamtrainError(f"--jobs: {jobs} is not a number of worker processes (>= 1)")
    if jobs is not None and scheduler is not None:
        raise CamtrainError("--jobs and --scheduler: give one (the cluster decides its workers)")
    sweep_def = prepare(deck, specs, list(sets), zipped, units)
    stem = Path(deck).stem if deck != "-" else "stdin"
    out_dir = Path(out) if out else Path("out") / f"{stem}_sweep"
    if quiet:
        return run_sweep(sweep_def, out_dir, jobs=jobs, scheduler=scheduler, resume=resume,
                         force=force, plots=not no_plots, overlay_max=overlay_max,
                         write_decks=write_decks), out_dir
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

    columns = (TextColumn("sweep"), BarColumn(), MofNCompleteColumn(), TextColumn("{task.fields[bad]}"),
               TimeRemainingColumn())
    # refreshed from the callback, not by a thread of its own: with no other thread running,
    # --jobs workers can be forked (they start at once) instead of spawned
    with Progress(*columns, console=Console(stderr=True), transient=False,
                  auto_refresh=False) as bar:
        task = bar.add_task("sweep", total=len(sweep_def.cases), bad="")
        failed, shown = [0], [0.0]
        from camtrain.numerics.compile_notice import listen

        # a compile notice goes above the bar, not onto its line
        listen(lambda text: bar.console.print(f"note: {text}", markup=False, highlight=False))

        def progress(record, done, total):
            import time

            failed[0] += record["status"] != "ok"
            bar.update(task, completed=done, bad=f"{failed[0]} not ok" if failed[0] else "")
            if time.monotonic() - shown[0] > 0.1 or done == total:
                bar.refresh()
                shown[0] = time.monotonic()

        outcome = run_sweep(sweep_def, out_dir, jobs=jobs, scheduler=scheduler, resume=resume,
                            force=force, plots=not no_plots, overlay_max=overlay_max, progress=progress,
                            write_decks=write_decks)
    return outcome, out_dir
