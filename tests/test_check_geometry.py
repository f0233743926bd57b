"""`camtrain check` runs the cheap geometry checks `run` would fail on (or says it did not), and
warns on part sizes no engine has (a deck written in metres)."""
from __future__ import annotations

from click.testing import CliRunner

from camtrain.cli import main
from tests.conftest import DECKS

HARRISON = (DECKS / "harrison_flat.toml").read_text(encoding="utf-8")


def _check(tmp_path, text, *args):
    deck = tmp_path / "deck.toml"
    deck.write_text(text, encoding="utf-8")
    return CliRunner().invoke(main, ["check", str(deck), *args])


def test_check_rejects_a_flat_follower_on_too_small_a_base_circle(tmp_path):
    """12 mm is below the 13.59 mm the Harrison lift law needs under a flat follower."""
    res = _check(tmp_path, HARRISON.replace("base_radius = 18.0", "base_radius = 12.0"))
    assert res.exit_code == 3, res.output
    assert "cam.base_radius" in res.output and "13.59" in res.output
    assert "Traceback" not in res.output
    assert "valid" not in res.output


def test_check_warns_on_a_deck_written_in_metres(tmp_path):
    res = _check(tmp_path, HARRISON.replace("width = 12.0", "width = 0.012"))
    assert res.exit_code == 0, res.output
    assert "cam.width = 0.012 mm" in res.output and "did you write metres?" in res.output
    res = _check(tmp_path, HARRISON.replace("base_radius = 18.0", "base_radius = 0.018"))
    assert res.exit_code == 3
    assert "cam.base_radius = 0.018 mm" in res.output and "metres" in res.output


def test_check_says_what_it_checked(tmp_path):
    res = _check(tmp_path, HARRISON)
    assert res.exit_code == 0, res.output
    assert "valid; geometry checked (kinematics)" in res.output
    assert "warning: cam" not in res.output
    bearing = CliRunner().invoke(main, ["check", str(DECKS / "bearing_ocvirk_check.toml")])
    assert bearing.exit_code == 0, bearing.output
    assert "geometry not checked" in bearing.output


def test_run_warns_on_a_deck_written_in_metres_and_reports_it(tmp_path):
    deck = tmp_path / "deck.toml"
    deck.write_text(HARRISON.replace("width = 12.0", "width = 0.012"), encoding="utf-8")
    out = tmp_path / "out"
    res = CliRunner().invoke(main, ["run", str(deck), "--no-plots", "--quiet", "--out", str(out)])
    assert res.exit_code == 0, res.output
    assert "cam.width = 0.012 mm" in res.output and "did you write metres?" in res.output
    assert "did you write metres?" in (out / "report.txt").read_text(encoding="utf-8")
