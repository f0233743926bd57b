"""`camtrain check DECK` echoes the fields the deck sets, one per line, in its units (readable
at 80 columns, no field name broken); `check --full` the whole echo with every default and
description."""
from __future__ import annotations

from click.testing import CliRunner

from camtrain.cli import main
from tests.conftest import DECKS


def _check(*args):
    return CliRunner().invoke(main, ["check", *args], catch_exceptions=False,
                              env={"COLUMNS": "80"})


def test_summary_lists_what_the_deck_sets_in_its_units():
    res = _check(str(DECKS / "zeta_intake_camshaft.toml"))
    assert res.exit_code == 0, res.output
    lines = res.output.splitlines()
    assert "  cam.base_radius = 18 mm" in lines
    assert "  camshaft.lobes[2].max_lift_angle = 270 deg" in lines
    assert "  tribology.film_formula" not in res.output          # a default: only with --full
    assert any("check --full" in line for line in lines)
    echo = lines[1:lines.index(next(line for line in lines if "check --full" in line)) + 1]
    assert echo and all(len(line) <= 80 for line in echo), [x for x in echo if len(x) > 80]


def test_summary_is_far_shorter_than_the_full_echo():
    summary = _check(str(DECKS / "harrison_flat.toml")).output.splitlines()
    full = _check(str(DECKS / "harrison_flat.toml"), "--full").output
    assert "Number of cam angles" in full                            # descriptions
    assert len(summary) < 80 and "valid" in summary[-1]
    assert len(full.splitlines()) > 3 * len(summary)                  # and every default
