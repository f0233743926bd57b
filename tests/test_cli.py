"""The command line: exit codes, messages without tracebacks, templates, schema, atomic outputs."""
from __future__ import annotations

import json
import subprocess
import sys

import pytest
from click.testing import CliRunner

from camtrain.cli import main
from camtrain.deck.schema import MECHANISMS
from tests.conftest import DECKS, MINIMAL_DECK


def invoke(*args, input=None):
    return CliRunner().invoke(main, list(args), input=input, catch_exceptions=False)


@pytest.mark.parametrize("mechanism", MECHANISMS)
def test_template_passes_check(mechanism):
    """`camtrain template X | camtrain check -` passes for every mechanism."""
    text = invoke("template", mechanism).output
    assert "[mm]" in text and "[rpm]" in text  # every field prompt carries its unit
    res = invoke("check", "-", input=text)
    assert res.exit_code == 0, res.output


@pytest.mark.parametrize("mechanism", MECHANISMS)
def test_template_prompts_every_field(mechanism):
    """Every field line is preceded by a prompt naming what it is and its status."""
    lines = invoke("template", mechanism).output.splitlines()
    in_array_block = False  # entries of [[array]] blocks are prompted once above the blocks
    for i, line in enumerate(lines):
        if line.startswith("[["):
            in_array_block = True
        elif not line.strip():
            in_array_block = False
        stripped = line.lstrip("# ")
        if in_array_block:
            continue
        if "=" in stripped and not stripped.startswith("[") and not line.startswith("# camtrain"):
            prompt_block = "\n".join(lines[max(0, i - 3):i])
            assert "(required)" in prompt_block or "(optional)" in prompt_block \
                or "(default" in prompt_block, line


def test_check_reports_all_problems_exit_2(tmp_path):
    deck = tmp_path / "bad.toml"
    deck.write_text(MINIMAL_DECK.replace("base_radius = 18", "base_radius = -18")
                    .replace('type = "flat"', 'type = "flatt"'))
    res = CliRunner().invoke(main, ["check", str(deck)])
    assert res.exit_code == 2
    assert "cam.base_radius" in res.output and "mechanism.type" in res.output
    assert "Traceback" not in res.output


@pytest.mark.parametrize("content,fragment", [
    (b"title = \n", "malformed TOML"),
    (b"", "the deck is empty"),
    (b"\x00\x01\x02binary", "binary file"),
    (b"\xff\xfe\xfa", "not UTF-8"),
    (b"[cam]\nbase_radius = nan\n", "must be finite"),
    (b"title = 1\n", "title: must be a non-empty string"),
])
def test_bad_files_exit_2_without_traceback(tmp_path, content, fragment):
    deck = tmp_path / "d.toml"
    deck.write_bytes(content)
    res = CliRunner().invoke(main, ["check", str(deck)])
    assert res.exit_code == 2, res.output
    assert fragment in res.output
    assert "Traceback" not in res.output


def test_malformed_toml_names_line_and_column(tmp_path):
    deck = tmp_path / "d.toml"
    deck.write_text('title = "x"\n[cam\nbase_radius = 1\n')
    res = CliRunner().invoke(main, ["check", str(deck)])
    assert res.exit_code == 2 and "line 2" in res.output and "column" in res.output


def test_missing_file_and_directory(tmp_path):
    res = CliRunner().invoke(main, ["check", str(tmp_path / "nope.toml")])
    assert res.exit_code == 2 and "does not exist" in res.output
    res = CliRunner().invoke(main, ["check", str(tmp_path)])
    assert res.exit_code == 2 and "is a directory" in res.output


def test_schema_is_valid_json_schema_and_accepts_templates():
    from jsonschema import Draft202012Validator

    schema = json.loads(invoke("schema").output)
    Draft202012Validator.check_schema(schema)
    import tomllib

    for mechanism in MECHANISMS:
        raw = tomllib.loads(invoke("template", mechanism).output)
        Draft202012Validator(schema).validate(raw)
    cam = schema["$defs"]["valve_train"]["properties"]["cam"]
    assert cam["properties"]["base_radius"]["exclusiveMinimum"] == 0


def test_run_writes_summary_and_cycle(tmp_path):
    out = tmp_path / "out"
    res = invoke("run", str(DECKS / "harrison_flat.toml"), "--out", str(out), "--no-plots")
    assert res.exit_code == 0, res.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["deck"]["sha256"] and len(summary["deck"]["sha256"]) == 64
    assert summary["plan"]["mode"] == "auto"
    assert {s["effect"] for s in summary["plan"]["steps"]} >= {"kinematics", "loads"}
    assert (out / "cycle.csv").exists()


def test_run_json_prints_summary(tmp_path):
    res = invoke("run", str(DECKS / "harrison_flat.toml"), "--out", str(tmp_path), "--json",
                 "--no-plots")
    assert json.loads(res.output)["camtrain_version"]


def test_failed_run_writes_nothing(tmp_path):
    deck = tmp_path / "bad.toml"
    deck.write_text(MINIMAL_DECK.replace("base_radius = 18", "base_radius = 0"))
    out = tmp_path / "out"
    res = CliRunner().invoke(main, ["run", str(deck), "--out", str(out)])
    assert res.exit_code == 2
    assert not out.exists()


def test_explicit_effect_with_missing_data_is_input_error(tmp_path):
    deck = tmp_path / "d.toml"
    deck.write_text('effects = ["loads"]\n' + MINIMAL_DECK)
    res = CliRunner().invoke(main, ["check", str(deck)])
    assert res.exit_code == 2
    assert "effect 'loads' is requested" in res.output and "spring" in res.output


def test_help_is_fast_to_import():
    """`camtrain --help` must not import numpy, scipy, matplotlib or rich (start-up time)."""
    code = ("import sys, camtrain.cli; "
            "print(','.join(m for m in ('numpy','scipy','matplotlib','rich') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


def test_console_script_entry_point():
    out = subprocess.run([sys.executable, "-m", "camtrain.cli", "--version"],
                         capture_output=True, text=True)
    assert out.returncode == 0 and "camtrain" in out.stdout


def test_deck_reference_doc_is_up_to_date():
    """docs/deck_reference.md is generated from the schema; regenerate with
    `camtrain schema --markdown > docs/deck_reference.md`."""
    from camtrain.deck.reference import markdown
    from tests.conftest import ROOT

    assert (ROOT / "docs" / "deck_reference.md").read_text() == markdown()
