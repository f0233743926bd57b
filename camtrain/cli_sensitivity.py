"""`camtrain sensitivity`: which uncertain inputs a deck's metrics hang on (docs/sensitivity.md).

Imports only click at module level, so that `camtrain --help` stays fast.
"""
from __future__ import annotations

import click

from camtrain.cli_sweep import _pair_specs, run_resumable

_DIST_OPTIONS = ("--uniform", "--log-uniform", "--normal", "--relative")
_HINT = "--uniform LOW:HIGH, --log-uniform LOW:HIGH, --normal MEAN:SD or --relative -P%:+P%"


class _SensitivityCommand(click.Command):
    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        ctx.meta["camtrain.sensitivity.specs"] = _pair_specs(list(args), _DIST_OPTIONS, _HINT)
        return super().parse_args(ctx, args)


@click.command("sensitivity", cls=_SensitivityCommand,
               context_settings={"help_option_names": ["-h", "--help"]})
@click.argument("deck", type=str)
@click.option("--param", "-p", "params", multiple=True, metavar="NAME",
              help="Uncertain input: a sweep parameter name (viscosity, cam_width, ...) or a "
                   "dotted deck path; follow it with its distribution. Repeat for each input.")
@click.option("--uniform", "uniform_", multiple=True, metavar="LOW:HIGH",
              help="Uniform between LOW and HIGH (deck unit, or % of the deck's value).")
@click.option("--log-uniform", "log_uniform_", multiple=True, metavar="LOW:HIGH",
              help="Log-uniform between LOW > 0 and HIGH (deck unit, or % of the deck's value).")
@click.option("--normal", "normal_", multiple=True, metavar="MEAN:SD",
              help="Normal (deck unit; +0%:5% is the deck's value with a 5 % deviation).")
@click.option("--relative", "relative_", multiple=True, metavar="-P%:+P%",
              help="Uniform from -P % to +P % of the deck's value.")
@click.option("--metric", "-m", "metrics", multiple=True, metavar="NAME",
              help="Metric of interest (repeatable; default: every metric that varies).")
@click.option("--method", type=click.Choice(["sobol", "morris"]), default="sobol",
              show_default=True,
              help="sobol: first-order and total indices (Saltelli's design, N (D+2) cases); "
                   "morris: elementary-effects screening (N trajectories, N (D+1) cases).")
@click.option("--samples", "-n", type=int, default=1024, show_default=True,
              help="Sobol' base samples (a power of two) or Morris trajectories.")
@click.option("--seed", type=int, default=1, show_default=True, help="Seed of the sample.")
@click.option("--confidence", type=float, default=0.95, show_default=True,
              help="Level of the bootstrap confidence intervals.")
@click.option("--set", "sets", multiple=True, metavar="PATH=VALUE",
              help="Change a deck field for every case (deck units).")
@click.option("--out", type=click.Path(file_okay=False), default=None,
              help="Output directory (default: out/<deck name>_sensitivity).")
@click.option("--jobs", "-j", type=int, default=None,
              help="Processes: this one and N-1 workers (default: the CPUs available).")
@click.option("--scheduler", default=None, metavar="ADDRESS",
              help="Run the cases on this Dask distributed scheduler (needs camtrain[dask]).")
@click.option("--resume", is_flag=True,
              help="Keep the finished cases in OUT/sweep.csv and run only the others.")
@click.option("--no-plots", is_flag=True, help="Write the tables only.")
@click.option("--quiet", "-q", is_flag=True, help="No progress bar or table.")
@click.pass_context
def sensitivity(ctx: click.Context, deck: str, params, uniform_, log_uniform_, normal_,
                relative_, metrics, method: str, samples: int, seed: int, confidence: float,
                sets, out: str | None, jobs: int | None, scheduler: str | None, resume: bool,
                no_plots: bool, quiet: bool) -> None:
    """Which uncertain inputs DECK's metrics depend on: Sobol' or Morris indices.

    \b
    Examples:
      camtrain sensitivity deck.toml -p viscosity --log-uniform 0.005:0.02 \\
          -p lubricant.pressure_viscosity --relative -20%:+20% \\
          -p tribology.boundary_friction --uniform 0.06:0.12 -m power_loss_mean
      camtrain sensitivity deck.toml -p viscosity --normal +0%:10% --method morris -n 40

    Writes indices.csv / indices.md (indices with confidence intervals), convergence.csv
    (the indices against the number of cases), distribution.csv (quantiles of each metric),
    sweep.csv (every case) and plots. Exit codes: 0 done, 2 bad arguments or deck,
    130 interrupted, 143 terminated (continue with --resume).
    """
    report, out_dir = run_resumable(lambda: _run(
        ctx, deck, metrics, method, samples, seed, confidence, sets, out, jobs, scheduler,
        resume, no_plots, quiet))
    for metric, why in report.skipped.items():
        click.echo(f"warning: {metric}: indices not estimated: {why}", err=True)
    if not quiet:
        from camtrain.study.sensitivity_output import markdown

        if report.route is not None:
            click.echo(report.route.describe())
        click.echo(markdown(report))
        click.echo(f"Wrote {out_dir}/indices.md, indices.csv, convergence.csv, "
                   f"distribution.csv, sweep.csv" + ("" if no_plots else ", plots/"))


def _run(ctx, deck, metrics, method, samples, seed, confidence, sets, out, jobs, scheduler,
         resume, no_plots, quiet):
    from pathlib import Path

    from camtrain.errors import CamtrainError
    from camtrain.study.sensitivity import prepare
    from camtrain.study.sensitivity_run import run_study

    specs = ctx.meta["camtrain.sensitivity.specs"]
    if not specs:
        raise click.UsageError("no uncertain input: give --param NAME with " + _HINT)
    if jobs is not None and jobs < 1:
        raise CamtrainError(f"--jobs: {jobs} is not a number of worker processes (>= 1)")
    if jobs is not None and scheduler is not None:
        raise CamtrainError("--jobs and --scheduler: give one (the cluster decides its workers)")
    kinds = [(n, k.replace("_", "-"), v) for n, k, v in specs]
    study = prepare(deck, kinds, method=method, samples=samples, seed=seed,
                    metrics=tuple(metrics), sets=list(sets))
    stem = Path(deck).stem if deck != "-" else "stdin"
    out_dir = Path(out) if out else Path("out") / f"{stem}_sensitivity"
    run = dict(jobs=jobs, scheduler=scheduler, resume=resume, confidence=confidence,
               plots=not no_plots)
    if quiet:
        return run_study(study, out_dir, **run), out_dir
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

    with Progress(TextColumn(method), BarColumn(), MofNCompleteColumn(), TimeRemainingColumn(),
                  console=Console(stderr=True), auto_refresh=False) as bar:
        task = bar.add_task(method, total=study.evaluations)
        shown = [0.0]

        def progress(record, done, total):
            import time

            bar.update(task, completed=done)
            if time.monotonic() - shown[0] > 0.1 or done == total:
                bar.refresh()
                shown[0] = time.monotonic()

        return run_study(study, out_dir, progress=progress, **run), out_dir
