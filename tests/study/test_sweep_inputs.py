"""A sweep directory has one owner: an existing sweep is continued (--resume) or replaced (--force),
never silently overwritten; and --resume trusts its finished cases only while every file the deck
reads (a lift table, included decks) is what they were computed from."""
from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from camtrain.cli_sweep import sweep as sweep_command
from camtrain.study.executors import SerialExecutor
from camtrain.study.runner import prepare, run_sweep

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "camtrain" / "data"


def test_a_sweep_into_an_existing_sweep_needs_resume_or_force(fast_flat, tmp_path):
    out = tmp_path / "s"
    base = [str(fast_flat), "-p", "speed", "--values", "1500,2000", "--no-plots", "-q",
            "--out", str(out)]
    assert CliRunner().invoke(sweep_command, base).exit_code == 0
    before = (out / "sweep.csv").read_bytes()
    res = CliRunner().invoke(sweep_command, base)
    assert res.exit_code == 2, res.output
    assert "holds a sweep already" in res.output and "--resume" in res.output
    assert "--force" in res.output and (out / "sweep.csv").read_bytes() == before
    res = CliRunner().invoke(sweep_command, base + ["--force"])
    assert res.exit_code == 0, res.output


def _table_deck(tmp_path: Path) -> Path:
    """decks/zeta_intake.toml reading its lift table from a CSV file beside it."""
    (tmp_path / "lift.csv").write_bytes((DATA / "yang1992_zeta_intake_cam_lift.csv").read_bytes())
    text = (ROOT / "decks" / "zeta_intake.toml").read_text(encoding="utf-8")
    assert 'dataset = "zeta_intake"' in text
    text = text.replace('dataset = "zeta_intake"', 'file = "lift.csv"')
    deck = tmp_path / "deck.toml"
    deck.write_text(text + "\n[solver]\nangle_points = 180\n" if "[solver]" not in text
                    else text, encoding="utf-8")
    return deck


def test_resume_recomputes_every_case_when_the_lift_table_changed(tmp_path):
    deck = _table_deck(tmp_path)
    specs = [("speed", "values", "1500,2000")]
    out = tmp_path / "s"
    first = run_sweep(prepare(deck, specs), out, executor=SerialExecutor(), plots=False)
    assert first.count("ok") == 2
    again = run_sweep(prepare(deck, specs), out, executor=SerialExecutor(), resume=True,
                      plots=False)
    assert again.reused == 2 and not again.notes       # nothing changed: nothing reruns
    table = tmp_path / "lift.csv"
    lines = table.read_text(encoding="utf-8").splitlines()
    table.write_text("\n".join(lines[:-1] + [lines[-1] + "1"]) + "\n", encoding="utf-8")
    changed = run_sweep(prepare(deck, specs), out, executor=SerialExecutor(), resume=True,
                        plots=False)
    assert changed.reused == 0 and changed.count("ok") == 2
    assert changed.notes and str(table) in changed.notes[0]


def test_resume_sees_a_changed_included_deck(tmp_path):
    """An engine deck's included valve-train deck is among the files its resume compares."""
    from camtrain.study.runner import _check_resume, _manifest

    text = (ROOT / "decks" / "zeta_engine.toml").read_text(encoding="utf-8")
    for included in ("zeta_intake_camshaft.toml", "zeta_exhaust_camshaft.toml"):
        assert f'deck = "{included}"' in text
        (tmp_path / included).write_bytes((ROOT / "decks" / included).read_bytes())
    engine = tmp_path / "engine.toml"
    engine.write_text(text, encoding="utf-8")
    specs = [("speed", "values", "3000")]
    sweep = prepare(engine, specs)
    assert str(tmp_path / "zeta_exhaust_camshaft.toml") in sweep.inputs
    out = tmp_path / "s"
    out.mkdir()
    import json

    (out / "sweep.json").write_text(json.dumps(_manifest(sweep)), encoding="utf-8")
    assert _check_resume(out, prepare(engine, specs)) == []
    exhaust = tmp_path / "zeta_exhaust_camshaft.toml"
    exhaust.write_text(exhaust.read_text(encoding="utf-8") + "\n# edited\n", encoding="utf-8")
    assert _check_resume(out, prepare(engine, specs)) == [str(exhaust)]


@pytest.mark.parametrize("flag", ["--resume", "--force"])
def test_resume_and_force_start_a_sweep_where_there_is_none(fast_flat, tmp_path, flag):
    res = CliRunner().invoke(sweep_command, [str(fast_flat), "-p", "speed", "--values", "1500",
                                             "--no-plots", "-q", "--out", str(tmp_path / "s"),
                                             flag])
    assert res.exit_code == 0, res.output
