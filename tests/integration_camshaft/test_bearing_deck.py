"""Stand-alone journal-bearing decks: Ocvirk anchor, CLI exit codes, template, plot."""
from __future__ import annotations

import numpy as np
import pytest
from click.testing import CliRunner

import camtrain.api as ct
from camtrain.cli import main
from camtrain.deck.templates import render_template
from tests.conftest import DECKS

OCVIRK = DECKS / "bearing_ocvirk_check.toml"


@pytest.mark.parametrize("method", ["mobility", "steady"])
def test_ocvirk_anchor(method):
    """D 25, L 18, c 0.025 mm, 0.01 Pa·s, 1500 rpm, 500 N: eps 0.7165, attitude 37.40 deg,
    h_min 7.09 µm, Petroff 2.180 W (formulas reference §4.3, closed-form Ocvirk).

    Tolerances: the anchor is printed to 4 significant figures (half a unit: 5e-5 in eps,
    0.005 deg); the orbit adds at most period_tolerance (1e-5) in eps, so 1e-4 and 0.01 deg.
    """
    deck = ct.load(OCVIRK)
    if method != "mobility":
        text = OCVIRK.read_text().replace('method = "mobility"', f'method = "{method}"')
        deck = ct.loads(text)
    r = ct.run(deck)
    assert r.metrics["max_eccentricity"].value == pytest.approx(0.7165, abs=1e-4)
    assert abs(np.degrees(r["attitude"]).max() - 37.40) < 0.01
    assert abs(np.degrees(r["attitude"]).min() - 37.40) < 0.01
    assert r.metrics["min_film"].value == pytest.approx(7.09e-6, abs=0.005e-6)
    assert r.metrics["petroff_power"].value == pytest.approx(2.180, abs=5e-4)
    assert r.plan.chosen == ["journal_bearing"]


def invoke(*args, input=None):
    return CliRunner().invoke(main, list(args), input=input)


def test_check_bearing_deck_exit_0_prints_plan():
    res = invoke("check", str(OCVIRK))
    assert res.exit_code == 0, res.output
    assert "journal_bearing" in res.output and "valid" in res.output


@pytest.mark.parametrize("old,new,name", [
    ("diameter = 25.0", "diameter = -25.0", "bearing.diameter"),
    ("diameter = 25.0", "diametre = 25.0", "bearing.diametre"),
    ('kind = "journal_bearing"', 'kind = "journal_bearings"', "kind"),
    ("load_x = [0.0, 0.0, 0.0, 0.0]", "load_x = [0.0, 0.0, 0.0]", "load.load_x"),
    ('method = "mobility"', 'method = "mobbility"', "solver.method"),
])
def test_bad_bearing_field_exit_2_names_it(tmp_path, old, new, name):
    deck = tmp_path / "bad.toml"
    deck.write_text(OCVIRK.read_text().replace(old, new))
    for command in ("check", "run"):
        res = invoke(command, str(deck))
        assert res.exit_code == 2, res.output
        assert name in res.output and "Traceback" not in res.output


def test_run_bearing_deck_exit_0(tmp_path):
    res = invoke("run", str(OCVIRK), "--out", str(tmp_path / "out"))
    assert res.exit_code == 0, res.output
    assert (tmp_path / "out" / "summary.json").is_file()


def test_template_journal_bearing_is_valid_and_runs():
    text = render_template("journal_bearing")
    assert "[mm]" in text and "[rpm]" in text and "[N]" in text
    assert invoke("check", "-", input=text).exit_code == 0
    r = ct.run(ct.loads(text))
    assert r.metrics["max_eccentricity"].value == pytest.approx(0.7165, abs=1e-4)


def test_valve_train_kind_is_optional(minimal_deck):
    plain = ct.loads(minimal_deck).model
    tagged = ct.loads('kind = "valve_train"\n' + minimal_deck).model
    assert plain == tagged


def test_orbit_plot_renders(tmp_path):
    from camtrain.report.bearing_plots import bearing_header_rows, orbit_series, write_orbit_plots

    deck = ct.load(OCVIRK)
    r = ct.run(deck)
    assert len(orbit_series(r)) == 1
    files = write_orbit_plots(r, tmp_path, title="Ocvirk")
    assert [f.name for f in files] == ["orbit_bearing.png"]
    assert files[0].read_bytes()[:4] == b"\x89PNG"
    rows = dict(bearing_header_rows(deck.model, r))
    assert rows["Diameter (mm)"] == "25"
    # report.txt and the sheets reach the bearing header through the deck kind, not a switch
    from camtrain.report.header import header_rows

    assert header_rows(deck.model, r) == bearing_header_rows(deck.model, r)
