"""`camtrain fit`: calibrate deck constants to measured data (docs/sensitivity.md#calibration).

Imports only click at module level, so that `camtrain --help` stays fast.
"""
from __future__ import annotations

import math
import sys

import click

from camtrain.cli_sweep import _pair_specs

_HINT = "--bounds LOW:HIGH"


class _FitCommand(click.Command):
    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        ctx.meta["camtrain.fit.specs"] = _pair_specs(list(args), ("--bounds",), _HINT)
        return super().parse_args(ctx, args)


@click.command("fit", cls=_FitCommand, context_settings={"help_option_names": ["-h", "--help"]})
@click.argument("deck", type=str)
@click.option("--data", "-d", "data", multiple=True, required=True, metavar="CSV",
              help="Measured data: a CSV with cam_angle[deg], crank_angle[deg] or speed[rpm] "
                   "first, then quantities with units, e.g. friction_torque[N·m]. Repeatable.")
@click.option("--param", "-p", "params", multiple=True, metavar="NAME",
              help="Constant to calibrate (a sweep parameter name or dotted deck path), "
                   "followed by --bounds LOW:HIGH; the deck's value is the start.")
@click.option("--bounds", "bounds_", multiple=True, metavar="LOW:HIGH",
              help="Bounds of the preceding --param, in the deck field's unit.")
@click.option("--set", "sets", multiple=True, metavar="PATH=VALUE",
              help="Change a deck field before fitting (deck units).")
@click.option("--confidence", type=float, default=0.95, show_default=True,
              help="Level of the constants' confidence intervals.")
@click.option("--out", type=click.Path(file_okay=False), default=None,
              help="Output directory (default: out/<deck name>_fit).")
@click.option("--jobs", "-j", type=int, default=1, show_default=True,
              help="Processes sharing the runs of each Jacobian.")
@click.option("--scheduler", default=None, metavar="ADDRESS",
              help="Run the runs on this Dask distributed scheduler (needs camtrain[dask]).")
@click.option("--no-plots", is_flag=True, help="Write the tables and the deck only.")
@click.option("--quiet", "-q", is_flag=True, help="Print only errors and warnings.")
@click.pass_context
def fit(ctx: click.Context, deck: str, data, params, bounds_, sets, confidence: float,
        out: str | None, jobs: int, scheduler: str | None, no_plots: bool, quiet: bool) -> None:
    """Calibrate constants of DECK to measured data by least squares.

    \b
    Example:
      camtrain fit deck.toml --data rig_torque.csv --data rig_power.csv \\
          -p viscosity --bounds 0.004:0.03 -p tribology.boundary_friction --bounds 0.02:0.2

    Writes fit.csv / fit.json (values, confidence intervals, correlations, which constants
    the data cannot tell apart), residuals.csv, singular_values.csv, calibrated.toml (the
    deck with the fitted values) and fit.png (data against prediction before and after).
    Exit codes: 0 done, 2 bad arguments, deck or data, 130 interrupted.
    """
    from pathlib import Path

    from camtrain.errors import CamtrainError
    from camtrain.study.fit_run import run_fit

    specs = ctx.meta["camtrain.fit.specs"]
    if not specs:
        raise click.UsageError("nothing to fit: give --param NAME --bounds LOW:HIGH")
    stem = Path(deck).stem if deck != "-" else "stdin"
    out_dir = Path(out) if out else Path("out") / f"{stem}_fit"
    live = not quiet and sys.stderr.isatty()
    shown = (lambda n: click.echo(f"\r{n} runs of camtrain", nl=False, err=True)) if live \
        else None
    try:
        if scheduler is not None and jobs != 1:
            raise CamtrainError("--jobs and --scheduler: give one")
        report = run_fit(deck, list(data), [(n, v) for n, _, v in specs], out_dir,
                         sets=list(sets), jobs=jobs, scheduler=scheduler,
                         confidence=confidence, plots=not no_plots, progress=shown)
    except CamtrainError as exc:
        click.echo(f"\nerror: {exc}" if live else f"error: {exc}", err=True)
        sys.exit(exc.exit_code)
    f = report.fit
    if live:
        click.echo("", err=True)
    if not quiet:
        click.echo(f"{f.points} data points, {f.evaluations} runs: {f.status}")
        level = f"{100 * f.confidence:g} %"
        for r in f.rows():
            interval = (f"± {r['half_width']:.3g}" if math.isfinite(r["half_width"])
                        else "(not identifiable)")
            click.echo(f"  {r['constant']} = {r['value']:.6g} {interval} {r['unit']} "
                       f"({level}; start {r['start']:.6g})")
        click.echo(f"Wrote {out_dir}/fit.csv, fit.json, residuals.csv, calibrated.toml"
                   + ("" if no_plots else ", fit.png"))
    for combo in f.combinations:
        click.echo(f"warning: the data do not tell {', '.join(f.unidentifiable)} apart: they "
                   f"fix only {combo}", err=True)
    for name in f.poorly_determined():
        click.echo(f"warning: {name}: its interval is wider than its value: the data hardly "
                   "determine it", err=True)
    for a, b, r in f.correlated():
        click.echo(f"warning: {a} and {b} are correlated {r:+.3f}: the data barely tell them "
                   "apart", err=True)
    for name in f.at_bound:
        click.echo(f"warning: {name} ended at a bound: widen --bounds", err=True)

