"""`camtrain friction-map DECK`: FLAME and the friction correlations over speed x load x oil
temperature (docs/engine.md, "Friction maps").

Only click is imported at module level so that `camtrain --help` stays fast.
"""
from __future__ import annotations

import sys

import click

from camtrain.errors import CamtrainError


def _numbers(option: str, text: str) -> list[float]:
    from camtrain.errors import field_error

    try:
        values = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise field_error(option, "is not a list of numbers", text,
                          "e.g. 2000,3000,4000") from None
    if not values:
        raise field_error(option, "no values given", text, "comma-separated numbers")
    return values


@click.command("friction-map")
@click.argument("deck", type=str)
@click.option("--speeds", required=True, help="Engine speeds [rpm], comma separated (a deck "
              "with pressure tables: speeds its [[pressure]] tables list).")
@click.option("--loads", required=True, help="Loads, comma separated: the [load] value in bar "
              "(peak pressure or IMEP, --measure) on a deck with pressure tables; the intake "
              "pressure ratio p_i/p_a on a bare engine deck.")
@click.option("--temperatures", required=True, help="Oil temperatures [°C], comma separated "
              "(the deck's [oil] grade gives the viscosity).")
@click.option("--measure", type=click.Choice(["imep", "peak_pressure"]), default=None,
              help="What the load sets on a deck with pressure tables (default: its [load] "
                   "measure, else imep).")
@click.option("--flame/--correlations-only", default=True, show_default=True,
              help="With [flame] in the deck, run FLAME at every point through the sweep "
                   "machinery (slow); --correlations-only maps the correlations alone "
                   "(vectorised, milliseconds).")
@click.option("--out", "out", type=click.Path(file_okay=False), required=True,
              help="Directory for friction_map.csv, friction_map.md, plots/ (and sweep/).")
@click.option("--jobs", "-j", type=int, default=None,
              help="Worker processes of the FLAME sweep (default: 1).")
@click.option("--scheduler", default=None, metavar="ADDRESS",
              help="Run the FLAME sweep on this Dask distributed scheduler.")
@click.option("--no-plots", is_flag=True, help="Tables only.")
@click.option("--quiet", "-q", is_flag=True, help="Print only errors.")
def friction_map(deck: str, speeds: str, loads: str, temperatures: str, measure: str | None,
                 flame: bool, out: str, jobs: int | None, scheduler: str | None,
                 no_plots: bool, quiet: bool) -> None:
    """Map DECK's engine friction over speed x load x oil temperature: FLAME (when the deck
    has [flame]) and PNH 1989, Sandoval-Heywood 2003 and Chen-Flynn (its [correlations])."""
    try:
        _run(deck, speeds, loads, temperatures, measure, flame, out, jobs, scheduler,
             no_plots, quiet)
    except CamtrainError as exc:
        click.echo(f"error: {exc}", err=True)
        sys.exit(exc.exit_code)


def _run(deck, speeds, loads, temperatures, measure, flame, out, jobs, scheduler, no_plots,
         quiet) -> None:
    from pathlib import Path

    from camtrain.deck.load import load_deck
    from camtrain.deck.schema_engine import EngineDeck
    from camtrain.errors import field_error
    from camtrain.study.friction_map import correlation_map, with_load_measure, write_map
    from camtrain.study.friction_sweep import sweep_map

    S, L, T = (_numbers(o, v) for o, v in (("--speeds", speeds), ("--loads", loads),
                                           ("--temperatures", temperatures)))
    if jobs is not None and scheduler is not None:
        raise CamtrainError("--jobs and --scheduler: give one (the cluster decides its workers)")
    model = load_deck(deck).model
    if not isinstance(model, EngineDeck):
        raise field_error("kind", "a friction map needs an engine deck", None, "engine")
    out_dir = Path(out)
    if flame and model.flame is not None:
        m = measure or (model.load.measure if model.load is not None else "imep")
        with_load_measure(model, m, S)    # every speed needs its pressure table (exit 2)
        fmap = sweep_map(deck, S, L, T, out_dir / "sweep", measure=m,
                         jobs=1 if jobs is None and scheduler is None else jobs,
                         scheduler=scheduler)
    else:
        if model.correlations is None:
            raise field_error("correlations", "the deck has no [correlations] (and no "
                              "[flame] to map)", None, "a [correlations] section")
        fmap = correlation_map(model, S, L, T, measure)
    written = write_map(fmap, out_dir, plots=not no_plots, title=model.title)
    if not quiet:
        for path in written:
            click.echo(f"wrote {path}")
