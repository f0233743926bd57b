"""`camtrain run DECK --set PATH=VALUE` (and sweep's --set): numbers, whole numbers, choices,
booleans and strings, each in the deck's units, validated with the deck; bad ones exit 2."""
from __future__ import annotations

import json
import tomllib

import pytest
from click.testing import CliRunner

from camtrain import api
from camtrain.cli import main
from camtrain.errors import InputError
from camtrain.study.assign import apply_fixed, parse_assignment
from tests.conftest import DECKS

HARRISON = DECKS / "harrison_flat.toml"


def _raw(name: str = "harrison_flat.toml") -> dict:
    return tomllib.loads((DECKS / name).read_text(encoding="utf-8"))


def test_set_changes_numbers_choices_booleans_and_strings():
    raw = _raw()
    fixed = [parse_assignment(raw, t) for t in (
        "solver.angle_points=720", "tribology.entrainment=mean", "cam.base_radius=19.5",
        "lift.multipol.check_continuity=false", "title='changed'")]
    out = apply_fixed(raw, fixed)
    assert out["solver"]["angle_points"] == 720 and isinstance(out["solver"]["angle_points"], int)
    assert out["tribology"]["entrainment"] == "mean"
    assert out["cam"]["base_radius"] == 19.5
    assert out["lift"]["multipol"]["check_continuity"] is False
    assert out["title"] == "changed"


@pytest.mark.parametrize("text, says", [
    ("tribology.entrainment=meen", "did you mean mean"),
    ("lift.multipol.check_continuity=maybe", "true or false"),
    ("solver.angle_points=720.5", "whole numbers"),
    ("solver.angle_points", "PATH=VALUE"),
    ("solver.no_such_field=1", "is not a key of solver"),
])
def test_a_bad_assignment_names_the_option_and_value(text, says):
    with pytest.raises(InputError) as err:
        parse_assignment(_raw(), text)
    assert "--set" in str(err.value) and says in str(err.value)


def test_api_load_with_sets_records_them_in_the_deck_text():
    plain = api.load(HARRISON)
    changed = api.load(HARRISON, ["solver.angle_points=720", "tribology.entrainment=mean"])
    assert changed.model.solver.angle_points == 720
    assert changed.model.tribology.entrainment == "mean"
    assert changed.text.endswith("# --set solver.angle_points = 720\n"
                                 "# --set tribology.entrainment = mean\n")
    assert changed.sha256 != plain.sha256


def test_run_set_runs_the_changed_deck(tmp_path):
    res = CliRunner().invoke(main, [
        "run", str(HARRISON), "--out", str(tmp_path / "o"), "--no-plots", "--json",
        "--set", "solver.angle_points=720", "--set", "tribology.entrainment=mean"],
        catch_exceptions=False)
    assert res.exit_code == 0, res.output
    summary = json.loads(res.output)
    lines = (tmp_path / "o" / "cycle.csv").read_text().splitlines()
    assert sum(1 for line in lines if line[:1].isdigit() or line[:1] == "-") == 720
    assert summary


def test_run_set_bad_value_exits_2_without_output(tmp_path):
    res = CliRunner().invoke(main, ["run", str(HARRISON), "--out", str(tmp_path / "o"),
                                    "--no-plots", "--set", "tribology.entrainment=meen"])
    assert res.exit_code == 2
    assert "did you mean mean" in res.output
    assert not (tmp_path / "o").exists()
