"""Sweep and accuracy tables in the deck's units with the unit beside each number; SI on request."""
from __future__ import annotations

import csv
import json

import pytest
from click.testing import CliRunner

from camtrain.cli_accuracy import accuracy
from camtrain.cli_sweep import sweep as sweep_command
from camtrain.errors import InputError
from camtrain.study.executors import SerialExecutor
from camtrain.study.runner import prepare, run_sweep


def _rows(path):
    with path.open(newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


@pytest.fixture(scope="module")
def both(tmp_path_factory):
    """The same two-case sweep written in deck units and in SI."""
    from tests.study.conftest import DECKS

    root = tmp_path_factory.mktemp("sweeps")
    deck = root / "flat.toml"
    deck.write_text((DECKS / "harrison_flat.toml").read_text(encoding="utf-8")
                    .replace("angle_points = 720", "angle_points = 120"), encoding="utf-8")
    out = {}
    for units in ("deck", "si"):
        sweep = prepare(deck, [("base_radius", "values", "17,19")], units=units)
        out[units + "_records"] = run_sweep(sweep, root / units, executor=SerialExecutor(),
                                            plots=False, overlay_max=2).records
        out[units] = root / units
    return deck, out


def test_sweep_csv_in_deck_units(both):
    _, out = both
    deck, si = _rows(out["deck"] / "sweep.csv"), _rows(out["si"] / "sweep.csv")
    assert deck[0]["base_radius[mm]"] == "17.0" and si[0]["base_radius[m]"] == "0.017"
    for row_d, row_s in zip(deck, si, strict=True):
        assert float(row_d["film_min[µm]"]) == pytest.approx(1e6 * float(row_s["film_min[m]"]),
                                                             rel=1e-12)
        assert float(row_d["hertz_max[MPa]"]) == pytest.approx(
            1e-6 * float(row_s["hertz_max[Pa]"]), rel=1e-12)
        assert float(row_d["max_lift[mm]"]) == pytest.approx(1e3 * float(row_s["max_lift[m]"]),
                                                             rel=1e-12)
    assert "film_min [µm]" in (out["deck"] / "trends.md").read_text(encoding="utf-8")
    trends = _rows(out["deck"] / "trends.csv")
    assert {r["unit"] for r in trends if r["metric"] == "hertz_max"} == {"MPa"}
    curve = (out["deck"] / "curves" / "case_00000.csv").read_text(encoding="utf-8")
    assert curve.startswith("cam_angle[deg]") and "film_min[µm]" in curve.splitlines()[0]
    assert json.loads((out["si"] / "sweep.json").read_text())["units"] == "si"


def test_resume_rereads_its_own_units_and_refuses_others(both, tmp_path):
    deck, out = both
    for units in ("deck", "si"):
        before = (out[units] / "sweep.csv").read_bytes()
        sweep = prepare(deck, [("base_radius", "values", "17,19")], units=units)
        outcome = run_sweep(sweep, out[units], executor=SerialExecutor(), resume=True,
                            plots=False)
        assert outcome.reused == 2
        assert (out[units] / "sweep.csv").read_bytes() == before
    other = prepare(deck, [("base_radius", "values", "17,19")], units="si")
    with pytest.raises(InputError, match="--units"):
        run_sweep(other, out["deck"], executor=SerialExecutor(), resume=True, plots=False)


def test_sweep_command_units_option(both, tmp_path):
    deck, _ = both
    res = CliRunner().invoke(sweep_command, [str(deck), "--param", "speed", "--values", "2000",
                                             "--out", str(tmp_path), "--quiet", "--no-plots",
                                             "--units", "si", "-j", "1"])
    assert res.exit_code == 0, res.output
    header = (tmp_path / "sweep.csv").read_text(encoding="utf-8").splitlines()[0]
    assert header.startswith("case,speed[rad/s],") and "hertz_max[Pa]" in header


def test_metric_sheet_has_a_title_and_no_offset(both, tmp_path, monkeypatch):
    """Every metric sheet names the sweep; no axis shows an offset such as '1e-8' or '+4.17e2'."""
    from camtrain.study import sweep_output as so

    deck, out = both
    records = out["deck_records"]
    seen = []
    monkeypatch.setattr(so, "_save", lambda plt, fig, path: seen.append(fig) or path)
    sweep = prepare(deck, [("base_radius", "values", "17,19")])
    so.metric_plots(tmp_path, sweep.params, records, title="flat.toml")   # every metric
    fig = seen[0]
    fig.canvas.draw()
    assert "flat.toml" in fig._suptitle.get_text() and "base_radius[mm]" in fig._suptitle.get_text()
    for ax in fig.axes:
        if ax.get_visible():
            assert ax.yaxis.get_offset_text().get_text() == ""


def test_accuracy_tables_in_deck_units(fast_flat, tmp_path):
    for units, unit in (("deck", "MPa"), ("si", "Pa")):
        out = tmp_path / units
        res = CliRunner().invoke(accuracy, [str(fast_flat), "--knob", "angle_points",
                                            "--tolerance", "1%", "--out", str(out), "-q",
                                            "--units", units])
        assert res.exit_code == 0, res.output
        rows = [r for r in _rows(out / "accuracy.csv") if r["metric"] == "hertz_max"]
        assert rows and {r["unit"] for r in rows} == {unit}
        report = json.loads((out / "accuracy.json").read_text(encoding="utf-8"))
        assert report["units"] == units
        assert report["knobs"]["angle_points"]["metrics"]["hertz_max"]["unit"] == unit


def test_si_curves_and_speeds_are_si(both):
    """The overlay curves' angle and a metric in rpm (bounce speed) come out in rad and rad/s."""
    _, out = both
    curve = (out["si"] / "curves" / "case_00000.csv").read_text(encoding="utf-8")
    assert curve.startswith("cam_angle[rad]")
    si, deck = _rows(out["si"] / "sweep.csv"), _rows(out["deck"] / "sweep.csv")
    assert float(si[0]["bounce_speed[rad/s]"]) == pytest.approx(
        float(deck[0]["bounce_speed[rpm]"]) * 3.141592653589793 / 30, rel=1e-12)
