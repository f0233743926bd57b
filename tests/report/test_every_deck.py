"""Every example deck runs and writes its full outputs: every sheet renders (files exist, sane
sizes, no warnings) with a clean layout (no text outside the page, no title or legend over a
plot or its ticks, no legend over the data), cycle.csv and summary.json parse back complete,
and the terminal prints what the effects declare."""
from __future__ import annotations

import csv
import json
import math
import re
from pathlib import Path

import pytest

from camtrain import api
from camtrain.catalogue import kind_of
from camtrain.report.display import fmt
from tests.conftest import DECKS
from tests.shared_runs import run_deck

DECK_FILES = sorted(p.name for p in DECKS.glob("*.toml"))


@pytest.mark.filterwarnings("error")
@pytest.mark.parametrize("name", DECK_FILES)
def test_deck_outputs_render_and_parse(name, tmp_path, monkeypatch):
    import camtrain.report.canvas as canvas
    from camtrain.report.layout import layout_problems
    from tests.report.declarations import axes_drawn

    problems, panels, save_png = {}, {}, canvas.save_png

    def checked_save_png(fig, path, software=""):
        save_png(fig, path, software)
        problems[path.name] = layout_problems(fig, draw=False)   # as it was just drawn
        panels[path.stem] = axes_drawn(fig)

    monkeypatch.setattr(canvas, "save_png", checked_save_png)
    loaded, result = run_deck(DECKS / name)   # the session's run of the deck (golden, docs)
    written = api.write(result, loaded, tmp_path, 0.0, plots="pdf")
    assert set(problems) == {p.name for p in written if p.suffix == ".png"}
    assert {k: v for k, v in problems.items() if v} == {}
    names = {p.name for p in written}
    assert {"summary.json", "report.txt"} <= names
    # a cycle table when the run has per-angle columns, none for single values alone
    assert ("cycle.csv" in names) == bool(result.columns)
    pngs = [p for p in written if p.suffix == ".png"]
    assert pngs, "no plot sheet written"
    # the sheets the effects declare are those the column-name code wrote before
    # (tests/report/declarations.py wrote the fixture)
    fixture = json.loads((Path(__file__).parent / "data" / "declarations.json").read_text())
    assert sorted(p.stem for p in pngs) == fixture[name.removesuffix(".toml")]["sheets"]
    # and each holds the panels (and curves) it held then
    assert panels == fixture[name.removesuffix(".toml")]["panels"]
    for png in pngs:
        # a blank A4 sheet is a few kB; an orbit plot is a small figure
        assert png.stat().st_size > (8_000 if png.name.startswith("orbit_") else 20_000), png.name
        assert png.with_suffix(".pdf").exists(), png.name
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["deck"]["sha256"] == loaded.sha256
    assert set(summary["metrics"]) == set(result.metrics)
    # cycle.csv holds the first axis' columns, cycle_<axis>.csv each further axis' (an engine's
    # piston columns on ring_angle)
    for k, axis in enumerate(result.axes or ([None] if result.columns else [])):
        on_axis = [c for c in result.columns.values() if axis is None or c.axis == axis]
        with (tmp_path / ("cycle.csv" if k == 0 else f"cycle_{axis}.csv")).open() as fh:
            rows = list(csv.reader(fh))
        header = rows[0]
        assert len(header) == len(on_axis)
        assert all("[" in h and h.endswith("]") for h in header)
        body = rows[1:]
        assert len(body) == len(on_axis[0].values)
        assert all(len(r) == len(header) for r in body)
    assert sum(len([c for c in result.columns.values() if c.axis == a])
               for a in result.axes) in (0, len(result.columns))
    _check_terminal(name, result, loaded.model)
    heading = (tmp_path / "report.txt").read_text(encoding="utf-8").splitlines()[1]
    kind = kind_of(loaded.model)
    assert kind.title in heading
    assert (kind.name == "valve_train") == ("CAM OPERATING" in heading)


def _check_terminal(name, result, deck):
    """What the terminal prints after the run: the declared key results and summary tables;
    an engine its crank-bearing table and FLAME total, a crank train the big-end's film."""
    import io

    from camtrain.report.console import PlainOut, key_metric_names, print_run, summary_tables

    stream = io.StringIO()
    print_run(PlainOut(stream, width=100), result, [], None, None, deck)
    out = stream.getvalue()
    assert key_metric_names(result), "no key result printed"
    for table in summary_tables(result, deck):
        assert table.title in out
    if name == "zeta_engine.toml":
        m = result.metrics
        assert "engine friction (FLAME total)" in out and "crank bearings" in out
        assert _row(out, "fmep [kPa]", fmt(m["fmep"].value * 1e-3))
        assert _row(out, "total", fmt(m["flame_total"].value), "100.0")
        share = 100 * m["flame_piston"].value / m["flame_total"].value
        assert _row(out, "pistons", fmt(m["flame_piston"].value), f"{share:.1f}")
    if name in ("zeta_engine.toml", "ruston_6veb.toml", "zeta_crank_bearings.toml"):
        film = result.metrics["big_end_1_min_film_dynamic"]
        assert _row(out, "big-end 1", fmt(film.value * 1e6), f"{math.degrees(film.angle):.1f}")


def _row(out: str, *cells: str) -> bool:
    """A table row that starts with these cells (whatever their padding)."""
    pattern = r"│\s*" + r"\s*│\s*".join(re.escape(c) for c in cells) + r"\s*│"
    return re.search(pattern, out) is not None
