"""`camtrain run DECK... [--check] [--junit] [--json] [--quiet]`: outputs and exit codes 0/1/2."""
from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import pytest
from click.testing import CliRunner

from camtrain.cli import main
from tests.conftest import DECKS

PASSING = "\n[limits]\nmax_hertz = 650\nmax_power_loss = 80\nmin_bounce_margin = 10\n"
FAILING = "\n[limits]\nmax_hertz = 300\nmax_load = 5000\n"


@pytest.fixture
def decks(tmp_path):
    """Harrison decks (coarse grid for speed) with passing and failing limits, and a bad deck."""
    text = (DECKS / "harrison_flat.toml").read_text()
    # the shipped deck's own example limits are replaced by each test's
    base = text.split("\n[limits]")[0].replace("angle_points = 1440", "angle_points = 240")
    d = tmp_path / "decks"
    d.mkdir()
    (d / "good.toml").write_text(base + PASSING)
    (d / "over.toml").write_text(base + FAILING)
    (d / "bad.toml").write_text(base.replace("base_radius = 18.0", "base_radius = -18.0"))
    return d


def run(*args):
    return CliRunner().invoke(main, ["run", *map(str, args)], catch_exceptions=False)


def test_check_all_pass_exits_0_and_writes_each_deck(decks, tmp_path):
    out = tmp_path / "out"
    res = run(decks / "good.toml", decks / "over.toml", "--out", out, "--no-plots")
    assert res.exit_code == 0, res.output          # without --check violations do not fail
    for stem in ("good", "over"):
        for name in ("summary.json", "cycle.csv", "report.txt"):
            assert (out / stem / name).exists()
    assert not list(out.glob(".*staging*"))
    res = run(decks / "good.toml", "--out", out / "g", "--check", "--no-plots")
    assert res.exit_code == 0, res.output
    assert "max_hertz" in res.output and "ok" in res.output


def test_check_violation_exits_1_and_names_metric_value_limit_angle(decks, tmp_path):
    res = run(decks / "good.toml", decks / "over.toml", "--out", tmp_path / "o", "--check",
              "--no-plots", "--quiet")
    assert res.exit_code == 1, res.output
    line = next(ln for ln in res.output.splitlines() if "VIOLATED" in ln)
    assert line.startswith("FAIL max_hertz: maximum Hertz stress = ")
    assert "MPa at " in line and "° cam; limit ≤ 300 MPa" in line
    assert "good.toml" not in res.output           # quiet: only the violations


def test_invalid_deck_among_several_exits_2_and_others_still_run(decks, tmp_path):
    out = tmp_path / "o"
    junit = tmp_path / "ci" / "junit.xml"
    res = run(decks / "over.toml", decks / "bad.toml", decks / "good.toml", "--out", out,
              "--check", "--no-plots", "--junit", junit)
    assert res.exit_code == 2, res.output
    assert "cam.base_radius" in res.output
    assert (out / "over" / "summary.json").exists() and (out / "good" / "summary.json").exists()
    assert not (out / "bad").exists()
    root = ET.parse(junit).getroot()
    suites = {s.get("name"): s for s in root.findall("testsuite")}
    assert list(suites) == ["over", "bad", "good"]
    assert suites["over"].get("tests") == "2" and suites["over"].get("failures") == "1"
    assert suites["bad"].get("errors") == "1"
    assert suites["good"].get("tests") == "3" and suites["good"].get("failures") == "0"
    assert root.get("tests") == "6"


def test_json_prints_summary_with_limits_and_findings(decks, tmp_path):
    res = run(decks / "over.toml", "--out", tmp_path / "o", "--json", "--no-plots")
    data = json.loads(res.output)
    assert data["deck"]["sha256"] and data["camtrain_version"]
    assert {c["limit"] for c in data["limits"]} == {"max_hertz", "max_load"}
    fail = next(c for c in data["limits"] if c["limit"] == "max_hertz")
    assert fail["status"] == "fail" and fail["unit"] == "MPa" and fail["angle_deg"] is not None
    assert "zero_entrainment_deg" in data["findings"]
    assert data["timings_s"] and "plan" in data


def test_json_with_several_decks_is_a_list_with_errors(decks, tmp_path):
    res = CliRunner().invoke(main, ["run", str(decks / "good.toml"), str(decks / "bad.toml"),
                                    "--out", str(tmp_path / "o"), "--json", "--no-plots"])
    assert res.exit_code == 2
    data = json.loads(res.stdout)
    assert isinstance(data, list) and len(data) == 2
    assert data[0]["metrics"] and data[1]["exit_code"] == 2 and "error" in data[1]


def test_quiet_prints_nothing_on_success(decks, tmp_path):
    res = run(decks / "good.toml", "--out", tmp_path / "o", "--quiet", "--no-plots", "--check")
    assert res.exit_code == 0 and res.output == ""


def test_terminal_report_shows_key_numbers_warnings_plan_timings(decks, tmp_path):
    res = run(decks / "over.toml", "--out", tmp_path / "o", "--no-plots")
    out = res.output
    assert "key results" in out and "hertz_max" in out and "MPa" in out
    assert "plan (auto)" in out and " ms " in out
    assert "warning:" in out and "entrainment" in out
    assert "FAIL max_hertz" in out


def test_failed_write_leaves_nothing(decks, tmp_path, monkeypatch):
    import camtrain.report.sheets as sheets

    def boom(*args, **kwargs):
        raise RuntimeError("disk on fire")

    monkeypatch.setattr(sheets, "write_plots", boom)
    out = tmp_path / "o"
    res = CliRunner().invoke(main, ["run", str(decks / "good.toml"), "--out", str(out)])
    assert res.exit_code == 70
    assert not out.exists() and not list(tmp_path.glob(".*staging*"))


def test_repeated_deck_names_get_their_own_directories(decks, tmp_path):
    other = tmp_path / "other"
    other.mkdir()
    (other / "good.toml").write_text((decks / "good.toml").read_text())
    out = tmp_path / "o"
    res = run(decks / "good.toml", other / "good.toml", "--out", out, "--no-plots", "-q")
    assert res.exit_code == 0
    assert (out / "good" / "summary.json").exists() and (out / "good-2" / "summary.json").exists()


def test_sheets_are_written_for_a_real_deck(decks, tmp_path):
    out = tmp_path / "o"
    res = run(decks / "good.toml", "--out", out, "-q")      # default: PNG sheets only
    assert res.exit_code == 0, res.output
    assert (out / "sheet_kinematics.png").exists() and not (out / "sheet_kinematics.pdf").exists()
    assert not (out / "panels").exists()
    assert json.loads((out / "summary.json").read_text())["metrics"]
    res = run(decks / "good.toml", "--out", out, "-q", "--plots", "pdf")   # PDF when asked
    assert res.exit_code == 0, res.output
    assert (out / "sheet_kinematics.png").exists() and (out / "sheet_kinematics.pdf").exists()
    assert not (out / "panels").exists()


@pytest.mark.parametrize("codes,expected", [([0, 1, 0], 1), ([1, 2, 0], 2), ([4, 3, 1], 3),
                                            ([2, 70], 70), ([], 0), ([0, 0], 0), ([1, 9], 9)])
def test_batch_exit_code_precedence(codes, expected):
    from camtrain.cli import _batch_exit_code

    assert _batch_exit_code(codes) == expected
