"""`camtrain dynamics-speed DECK`: the highest camshaft speed without separation of the elastic
train (docs/dynamics.md), or with --pump-up the lowest where its hydraulic lash adjuster pumps up;
`camtrain leakdown DECK`: the adjuster's workshop leak-down test (docs/lash_adjusters.md). Only
click is imported at module level (`camtrain --help` stays fast).
"""
from __future__ import annotations

import json
import sys

import click

from camtrain.errors import CamtrainError


@click.command("dynamics-speed")
@click.argument("deck", type=str)
@click.option("--tolerance", default=0.002, show_default=True, type=click.FloatRange(1e-6, 0.5),
              help="Relative width of the final speed bracket.")
@click.option("--start", "start", default=None, type=click.FloatRange(min=1e-3),
              help="Camshaft speed [rpm] to start the bracket from (default: the deck's).")
@click.option("--pump-up", "pump_up", is_flag=True,
              help="Search the speed where the hydraulic lash adjuster ([dynamics.lash_adjuster]) "
                   "first pumps up (holds the valve off its seat) instead.")
@click.option("--json", "as_json", is_flag=True, help="Print the result as JSON.")
def dynamics_speed(deck: str, tolerance: float, start: float | None, pump_up: bool,
                   as_json: bool) -> None:
    """Bracket and bisect the camshaft speed at which DECK's elastic train ([dynamics]) first
    loses the follower while the valve is off its seat; print it beside the rigid train's
    closed-form bounce speed. Speeds are camshaft rpm (a four-stroke engine turns at twice
    that), angles cam deg from maximum lift."""
    try:
        if pump_up:
            from camtrain.study.lash_adjuster import pump_up_speed as search
            from camtrain.study.lash_adjuster import render_pump_up as render
        else:
            from camtrain.study.dynamics_speed import dynamics_speed as search
            from camtrain.study.dynamics_speed import render

        report = search(deck, rtol=tolerance, start_rpm=start)
    except CamtrainError as exc:
        click.echo(f"error: {exc}", err=True)
        sys.exit(exc.exit_code)
    click.echo(json.dumps(report, indent=2) if as_json else render(report))


@click.command("leakdown")
@click.argument("deck", type=str)
@click.option("--load", default=222.0, show_default=True, type=click.FloatRange(min=0.0,
              min_open=True), help="Constant load on the plunger [N] (the tester's weight).")
@click.option("--travel", default=1.0, show_default=True, type=click.FloatRange(min=0.0,
              min_open=True), help="Plunger travel timed [mm].")
@click.option("--start", "start", default=0.1, show_default=True, type=click.FloatRange(min=0.0),
              help="Collapse [mm] below full extension where the timing starts.")
@click.option("--json", "as_json", is_flag=True, help="Print the result as JSON.")
def leakdown(deck: str, load: float, travel: float, start: float, as_json: bool) -> None:
    """The workshop leak-down test of DECK's hydraulic lash adjuster
    ([dynamics.lash_adjuster]): the time for the plunger to travel a set distance under a
    constant load, marched (mass, compressible chamber, leak, check valve) and by the laminar
    annulus closed form (docs/lash_adjusters.md)."""
    try:
        from camtrain.study.lash_adjuster import leakdown as run
        from camtrain.study.lash_adjuster import render_leakdown

        report = run(deck, load=load, travel=travel * 1e-3, start=start * 1e-3)
    except CamtrainError as exc:
        click.echo(f"error: {exc}", err=True)
        sys.exit(exc.exit_code)
    click.echo(json.dumps(report, indent=2) if as_json else render_leakdown(report))
