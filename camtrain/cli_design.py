"""`camtrain design` and `camtrain optimize`: from analysis to design (docs/design.md).

Imports only click at module level, so that `camtrain --help` stays fast.
"""
from __future__ import annotations

import sys

import click


@click.command(context_settings={"help_option_names": ["-h", "--help"]})
@click.argument("deck", type=str)
@click.option("--out", type=click.Path(file_okay=False), default=None,
              help="Output directory (default: out/<deck name>_design).")
@click.option("--no-plots", is_flag=True, help="Write the deck and tables only.")
@click.option("--quiet", "-q", is_flag=True, help="Print nothing but errors.")
def design(deck: str, out: str | None, no_plots: bool, quiet: bool) -> None:
    """Build a lift law from the valve events and limits in DECK's [design] section.

    \b
    Writes OUT/designed.toml (the deck with a spline [lift] meeting the events: run, sweep or
    optimise it like any deck), design.md and design.csv (every event and limit, met or not
    and by how much) and design.png. Exit codes: 0 every event and limit met, 1 some not met,
    2 bad deck, 3 no lift can meet the events within the limits.
    """
    from pathlib import Path

    from camtrain.design.command import design_deck, report_text, write_design
    from camtrain.errors import CamtrainError

    try:
        outcome = design_deck(deck)
    except CamtrainError as exc:
        click.echo(f"error: {exc}", err=True)
        sys.exit(exc.exit_code)
    stem = Path(deck).stem if deck != "-" else "stdin"
    out_dir = Path(out) if out else Path("out") / f"{stem}_design"
    write_design(outcome, out_dir, deck, plots=not no_plots)
    if not quiet:
        click.echo(report_text(outcome, deck))
        click.echo(f"Wrote {out_dir}/designed.toml, design.md, design.csv"
                   + ("" if no_plots else ", design.png"))
    if not outcome.all_met:
        sys.exit(1)


@click.command(context_settings={"help_option_names": ["-h", "--help"]})
@click.argument("deck", type=str)
@click.option("--var", "variables", multiple=True, metavar="NAME=LOWER:UPPER",
              help="A design variable and its bounds, in the deck field's unit: one of Ball's "
                   "parameter names (base_radius, spring_rate, ...) or a dotted deck path, e.g. "
                   "spring.preload_compression=2:10. Repeat for more.")
@click.option("--objective", default="power_loss_mean", show_default=True,
              help="Metric to minimise (any metric of a run, e.g. hertz_max, "
                   "friction_torque_peak).")
@click.option("--constraint", "constraints", multiple=True, metavar="SPEC",
              help="no_concave_flank, no_separation=RPM, min_film_parameter=X, hertz_limit=MPA,"
                   " open_area=PCT, or METRIC>=X / METRIC<=X in the metric's deck unit. Repeat "
                   "for more.")
@click.option("--method", type=click.Choice(["slsqp", "trust-constr", "differential_evolution"]),
              default="slsqp", show_default=True, help="scipy optimiser.")
@click.option("--step", type=click.FloatRange(1e-8, 0.1), default=1e-3, show_default=True,
              help="Finite-difference step, as a fraction of each variable's range.")
@click.option("--maxiter", type=click.IntRange(1, 10000), default=100, show_default=True,
              help="Iterations (generations for differential_evolution).")
@click.option("--popsize", type=click.IntRange(2, 200), default=8, show_default=True,
              help="Population per variable (differential_evolution).")
@click.option("--seed", type=int, default=1, show_default=True,
              help="Random seed (differential_evolution).")
@click.option("--set", "sets", multiple=True, metavar="PATH=VALUE",
              help="Change a deck field before the search (deck units).")
@click.option("--jobs", "-j", type=int, default=1, show_default=True,
              help="Processes that share each set of cases.")
@click.option("--scheduler", default=None, metavar="ADDRESS",
              help="Run the cases on this Dask distributed scheduler (needs camtrain[dask]).")
@click.option("--out", type=click.Path(file_okay=False), default=None,
              help="Output directory (default: out/<deck name>_optimize).")
@click.option("--no-plots", is_flag=True, help="Write the deck and tables only.")
@click.option("--quiet", "-q", is_flag=True, help="No progress or report.")
def optimize(deck: str, variables, objective: str, constraints, method: str, step: float,
             maxiter: int, popsize: int, seed: int, sets, jobs: int, scheduler: str | None,
             out: str | None, no_plots: bool, quiet: bool) -> None:
    """Minimise a metric of DECK over deck fields, under constraints on metrics.

    \b
    Examples:
      camtrain optimize deck.toml --var base_radius=12:24 --constraint no_concave_flank
      camtrain optimize deck.toml --var spring.preload_compression=1:12 \\
                                  --constraint no_separation=3000
    Writes OUT/optimum.toml (runs as an ordinary deck), optimize.md and optimize.json (gain by
    part, constraints and which are active), path.csv (every evaluation) and comparison.csv /
    comparison.png (datum against optimum). Ctrl-C stops the search and writes the best point
    so far. Exit codes: 0 found, 1 no point meets the constraints, 2 bad arguments or deck,
    130 interrupted (outputs written).
    """
    from pathlib import Path

    from camtrain.errors import CamtrainError
    from camtrain.interrupts import terminable
    from camtrain.study.optimize import optimize as run
    from camtrain.study.optimize_output import report_text, write_optimize

    def progress(problem) -> None:
        feasible = [p for p in problem.path if p.feasible]
        best = min(feasible, key=lambda p: p.objective) if feasible else None
        where = ", ".join(f"{v.name}={x:.6g}" for v, x in zip(problem.variables, best.x,
                                                               strict=True)) if best else "-"
        click.echo(f"evaluations {len(problem.path):5d}  best feasible {problem.objective} = "
                   + (f"{best.objective:.6g}" if best else "none yet") + f"  at {where}",
                   err=True)

    if jobs < 1:
        click.echo(f"error: --jobs: {jobs} is not a number of processes (>= 1)", err=True)
        sys.exit(2)
    try:
        with terminable():
            outcome = run(deck, list(variables), objective, list(constraints), method=method,
                          step=step, maxiter=maxiter, jobs=jobs, scheduler=scheduler,
                          sets=list(sets), popsize=popsize, seed=seed,
                          progress=None if quiet else progress)
    except CamtrainError as exc:
        click.echo(f"error: {exc}", err=True)
        sys.exit(exc.exit_code)
    stem = Path(deck).stem if deck != "-" else "stdin"
    out_dir = Path(out) if out else Path("out") / f"{stem}_optimize"
    write_optimize(outcome, out_dir, plots=not no_plots)
    if not quiet:
        click.echo(report_text(outcome))
        click.echo(f"Wrote {out_dir}/optimum.toml, optimize.md, optimize.json, path.csv, "
                   "comparison.csv" + ("" if no_plots else ", comparison.png"))
    if outcome.status == "interrupted":
        sys.exit(130)
    if outcome.status == "infeasible":
        sys.exit(1)
