"""Every example deck runs and writes its full outputs: every sheet renders (files exist, sane
sizes, no warnings), cycle.csv and summary.json parse back complete."""
from __future__ import annotations

import csv
import json

import pytest

from camtrain import api
from tests.conftest import DECKS

DECK_FILES = sorted(p.name for p in DECKS.glob("*.toml"))


@pytest.mark.filterwarnings("error")
@pytest.mark.parametrize("name", DECK_FILES)
def test_deck_outputs_render_and_parse(name, tmp_path):
    loaded = api.load(DECKS / name)
    result = api.run(loaded)
    written = api.write(result, loaded, tmp_path, 0.0, plots="pdf")
    names = {p.name for p in written}
    assert {"cycle.csv", "summary.json", "report.txt"} <= names
    pngs = [p for p in written if p.suffix == ".png"]
    assert pngs, "no plot sheet written"
    for png in pngs:
        # a blank A4 sheet is a few kB; an orbit plot is a small figure
        assert png.stat().st_size > (8_000 if png.name.startswith("orbit_") else 20_000), png.name
        assert png.with_suffix(".pdf").exists(), png.name
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["deck"]["sha256"] == loaded.sha256
    assert set(summary["metrics"]) == set(result.metrics)
    # cycle.csv holds the first axis' columns, cycle_<axis>.csv each further axis' (an engine's
    # piston columns on ring_angle)
    for k, axis in enumerate(result.axes or [None]):
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
