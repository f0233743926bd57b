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
