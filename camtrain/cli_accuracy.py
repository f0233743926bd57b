"""`camtrain accuracy DECK`: what accuracy costs in time, knob by knob (see docs/accuracy.md).

Only click is imported at module level so that `camtrain --help` stays fast; the study, numpy and
matplotlib come in when the command runs.
"""
from __future__ import annotations

import sys

import click

from camtrain.errors import CamtrainError


@click.command("accuracy")
@click.argument("deck", type=str)
@click.option("--knob", "knobs", multiple=True, metavar="NAME",
              help="Resolution knob to study (repeatable): angle_points, friction_tolerance, "
                   "table_smoothing, shaft_stations, bearing_mesh, bearing_model, "
                   "orbit_points; transient film: film_angle_step, film_nodes, "
                   "film_zone_width, film_tolerance; elastic film: ehl_nodes, ehl_inlet, "
                   "ehl_angle_step, ehl_tolerance; dynamics: steps_per_degree, "
                   "coupling_iterations, spring_elements, dynamics_rtol, adjuster_cycles; "
                   "roller: roller_substeps, roller_table_points, roller_tolerance; engine "
                   "decks: crank_step, period_tolerance, step_tolerance, "
                   "pressure_interpolation, mobility, piston_crank_step, ring_tolerance, "
                   "pass_tolerance, gas_tolerance. Default: every knob that applies to the "
                   "deck.")
@click.option("--tolerance", default="0.1%", show_default=True,
              help="Relative tolerance for the cheapest setting, e.g. 0.1% or 1e-3.")
@click.option("--out", "out", type=click.Path(file_okay=False), default=None,
              help="Write accuracy.csv, accuracy.json and accuracy.png into this directory.")
@click.option("--repeat", type=click.IntRange(1, 100), default=5, show_default=True,
              help="Time each rung up to this many times, until its two fastest runs agree "
                   "within 10 %; the table gives the fastest and that spread ('!' when it "
                   "stayed above 10 %).")
@click.option("--quiet", "-q", is_flag=True, help="Print only errors.")
@click.option("--units", type=click.Choice(["deck", "si"]), default="deck", show_default=True,
              help="Units of accuracy.csv and accuracy.json: deck (mm, µm, MPa, ...) or si.")
def accuracy(deck: str, knobs: tuple[str, ...], tolerance: str, out: str | None, repeat: int,
             quiet: bool, units: str) -> None:
    """Run DECK at a ladder of resolutions per knob: value, error, observed order, wall time.

    \b
    The error of each rung is relative to the Richardson extrapolation of the three finest
    rungs (or to the finest rung when no clean order can be read). The cheapest setting is the
    coarsest rung from which every finer rung stays within --tolerance for every key metric.
    """
    try:
        _accuracy(deck, knobs, tolerance, out, repeat, quiet, units)
    except CamtrainError as exc:  # also when run outside the main group (no traceback)
        click.echo(f"error: {exc}", err=True)
        sys.exit(exc.exit_code)


def _accuracy(deck, knobs, tolerance, out, repeat, quiet, units="deck") -> None:
    from camtrain.study.accuracy import in_units, parse_tolerance, render_table, study, write_outputs

    tol = parse_tolerance(tolerance)
    if out:     # before the study: a --out that cannot be a directory is refused at once
        from camtrain.output_lock import checked_output_dir

        checked_output_dir(out)
    progress = None if quiet else (lambda k: click.echo(f"studying {k} ...", err=True))
    report = study(deck, knobs, tol, repeat=repeat, progress=progress)
    written = write_outputs(report, out, units) if out else []
    if not quiet:
        click.echo(render_table(in_units(report)))
        for path in written:
            click.echo(f"wrote {path}")
