"""`camtrain dynamics-speed DECK`: the highest camshaft speed without separation of the elastic
train (docs/dynamics.md). Only click is imported at module level (`camtrain --help` stays fast).
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
@click.option("--json", "as_json", is_flag=True, help="Print the result as JSON.")
def dynamics_speed(deck: str, tolerance: float, start: float | None, as_json: bool) -> None:
    """Bracket and bisect the camshaft speed at which DECK's elastic train ([dynamics]) first
    loses the follower while the valve is off its seat; print it beside the rigid train's
    closed-form bounce speed. Speeds are camshaft rpm (a four-stroke engine turns at twice
    that), angles cam deg from maximum lift."""
    try:
        from camtrain.study.dynamics_speed import dynamics_speed as search
        from camtrain.study.dynamics_speed import render

        report = search(deck, rtol=tolerance, start_rpm=start)
    except CamtrainError as exc:
        click.echo(f"error: {exc}", err=True)
        sys.exit(exc.exit_code)
    click.echo(json.dumps(report, indent=2) if as_json else render(report))
