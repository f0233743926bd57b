"""Decks and invocations that once ended in an internal error, a leak of file content, a hang or
a file left behind (tests/repro holds the decks): each now gives a clear message and the exit
code docs/README promise, and leaves nothing."""
from __future__ import annotations

import os
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from camtrain.cli import main
from tests.conftest import DECKS

REPRO = Path(__file__).resolve().parent / "repro"


def _cli(*args, input=None):
    return CliRunner().invoke(main, [str(a) for a in args], input=input)


def _run(deck, out: Path, *extra):
    return _cli("run", deck, "--out", out, "--no-plots", "-q", *extra)


def _clean_failure(res, out: Path, code: int = 2) -> str:
    assert res.exit_code == code, res.output
    assert "Traceback" not in res.output and "internal error" not in res.output, res.output
    assert not out.exists(), "output written by a failed run"
    assert not [p for p in out.parent.iterdir() if p.name.startswith(f".{out.name}.")]
    return res.output


# ---------------------------------------------------------------- decks

def test_a_follower_mass_without_a_link_stiffness_is_refused_by_check_and_run(tmp_path):
    deck = REPRO / "dynamics_no_stem_stiffness_valueerror.toml"
    res = _cli("check", deck, "-q")
    assert res.exit_code == 2 and "dynamics.stem_stiffness" in res.output, res.output
    text = _clean_failure(_run(deck, tmp_path / "o"), tmp_path / "o")
    assert "dynamics.stem_stiffness" in text and "follower_mass" in text


def test_a_very_low_camshaft_speed_is_refused_before_the_march_allocates(tmp_path):
    text = _clean_failure(_run(REPRO / "dynamics_speed_1.5e-3rpm_memoryerror.toml",
                               tmp_path / "o"), tmp_path / "o")
    assert "speed.camshaft" in text and "0.0015 rpm" in text
    assert "steps_per_degree" in text and "time steps per camshaft revolution" in text


def test_a_huge_steps_per_degree_names_that_knob(tmp_path):
    deck = (DECKS / "zeta_intake_dynamics.toml").read_text(encoding="utf-8")
    deck = deck.replace("[dynamics]\n", "[dynamics]\nsteps_per_degree = 90000.0\n", 1)
    text = _clean_failure(_cli("run", "-", "--out", tmp_path / "o", "--no-plots", "-q",
                               input=deck), tmp_path / "o")
    assert "dynamics.steps_per_degree" in text


def test_an_engine_deck_including_itself_is_refused_naming_the_chain(tmp_path):
    res = _cli("check", REPRO / "engine_include_self.toml", "-q")
    assert res.exit_code == 2, res.output
    assert "include cycle" in res.output
    assert res.output.count("engine_include_self.toml ->") == 1


def test_two_engine_decks_including_each_other_are_refused_naming_both(tmp_path):
    text = (REPRO / "engine_include_self.toml").read_text(encoding="utf-8")
    for me, other in (("a", "b"), ("b", "a")):
        (tmp_path / f"{me}.toml").write_text(
            text.replace('deck = "engine_include_self.toml"', f'deck = "{other}.toml"'),
            encoding="utf-8")
    res = _cli("check", tmp_path / "a.toml", "-q")
    assert res.exit_code == 2, res.output
    chain = f"{tmp_path / 'a.toml'} -> {tmp_path / 'b.toml'} -> {tmp_path / 'a.toml'}"
    assert "include cycle" in res.output and chain in res.output, res.output


def test_a_two_way_coupled_camshaft_without_a_lubricant_is_refused_by_check():
    """Found by the fuzz (case 2071: [lubricant] deleted): the coupled march reads every lobe's
    contact friction, which needs the lubricant; it ended in an AttributeError (exit 70)."""
    import tomllib

    import tomli_w

    raw = tomllib.loads((REPRO / "coupled_no_camshaft_viscosity_slow.toml").read_text("utf-8"))
    del raw["lubricant"]
    res = _cli("check", "-", "-q", input=tomli_w.dumps(raw))
    assert res.exit_code == 2, res.output
    assert "lubricant" in res.output and "two_way" in res.output


def test_a_utf8_byte_order_mark_is_read_as_utf8(tmp_path):
    res = _cli("check", REPRO / "utf8_bom_zeta_intake.toml", "-q")
    assert res.exit_code == 0, res.output


def test_a_lift_table_file_of_another_kind_is_named_not_echoed(tmp_path):
    res = _run(REPRO / "lift_table_file_proc_environ.toml", tmp_path / "o")
    text = _clean_failure(res, tmp_path / "o")
    assert "lift.table.file" in text and "environ" in text
    for name in os.environ:          # the file holds NAME=value entries: none is shown
        assert f"{name}=" not in text
    assert "\\x00" not in text


@pytest.mark.parametrize("content, where", [
    ("API_TOKEN=s3cr3t-value-0123\nangle_deg,lift_mm\n", "line 1 is not a valid header"),
    ("angle_deg,lift_mm\n0,0\nroot:s3cr3t-value-0123:19000:0\n", "line 3 does not have two"),
    ("angle_deg,lift_mm\n0,0\npassword,s3cr3t-value-0123\n", "line 3 is not a pair"),
])
def test_a_lift_table_error_names_file_and_line_never_the_content(tmp_path, content, where):
    table = tmp_path / "secret.csv"
    table.write_text(content, encoding="utf-8")
    deck = (REPRO / "utf8_bom_zeta_intake.toml").read_text(encoding="utf-8-sig")
    deck = deck.replace('dataset = "zeta_intake"', f'file = "{table.as_posix()}"')
    text = _clean_failure(_cli("run", "-", "--out", tmp_path / "o", "--no-plots", "-q",
                               input=deck), tmp_path / "o")
    assert "secret.csv" in text and where in text
    assert "s3cr3t" not in text


def test_a_lift_table_file_past_the_size_cap_is_refused_unread(tmp_path):
    from camtrain.lift.datasets import MAX_TABLE_BYTES

    table = tmp_path / "huge.csv"
    with table.open("wb") as fh:
        fh.write(b"angle_deg,lift_mm\n")
        fh.truncate(MAX_TABLE_BYTES + 10)     # sparse: no time spent writing it
    deck = (REPRO / "utf8_bom_zeta_intake.toml").read_text(encoding="utf-8-sig")
    deck = deck.replace('dataset = "zeta_intake"', f'file = "{table.as_posix()}"')
    text = _clean_failure(_cli("run", "-", "--out", tmp_path / "o", "--no-plots", "-q",
                               input=deck), tmp_path / "o")
    assert "larger than 20 MiB" in text and "lift.table.file" in text


def test_a_lift_table_with_a_byte_order_mark_reads(tmp_path):
    from camtrain.lift.datasets import load_csv

    table = tmp_path / "bom.csv"
    table.write_bytes(b"\xef\xbb\xbfangle_deg,lift_mm\n0,0\n10,1\n20,0\n")
    assert load_csv(table).lift.size == 3


@pytest.mark.parametrize("method", ["mobility", "steady"])
def test_a_finite_bearing_beyond_its_map_names_the_film_model_field(tmp_path, method):
    deck = (DECKS / "bearing_ocvirk_check.toml").read_text(encoding="utf-8")
    deck = re.sub(r'model = "short".*', 'model = "finite"', deck).replace("-500.0", "-2.0e6")
    deck = deck.replace('method = "mobility"', f'method = "{method}"')
    text = _clean_failure(_cli("run", "-", "--out", tmp_path / "o", "--no-plots", "-q",
                               input=deck), tmp_path / "o", code=4)
    assert "solver.model" in text and "extend the map" not in text


# ---------------------------------------------------------------- output directories

def test_out_naming_a_dangling_symbolic_link_is_refused(tmp_path):
    link = tmp_path / "o"
    link.symlink_to(tmp_path / "nowhere")
    res = _run(DECKS / "harrison_flat.toml", link)
    assert res.exit_code == 2, res.output
    assert "--out" in res.output and "symbolic link" in res.output
    assert link.is_symlink() and not (tmp_path / "nowhere").exists()


def test_a_second_writer_of_the_same_out_is_refused(tmp_path):
    from camtrain.output_lock import output_lock

    out = tmp_path / "o"
    with output_lock(out):           # another process writing there
        res = _run(DECKS / "harrison_flat.toml", out)
        assert res.exit_code == 2, res.output
        assert "another camtrain process" in res.output and f"pid {os.getpid()}" in res.output
        res = _cli("lift", DECKS / "harrison_flat.toml", "--out", out, "--no-plots", "-q")
        assert res.exit_code == 2 and "another camtrain process" in res.output
    assert not out.exists()
    assert _run(DECKS / "harrison_flat.toml", out).exit_code == 0
    assert [p.name for p in tmp_path.iterdir()] == ["o"]     # the lock file went too


def _raise_sigterm(*args, **kwargs):
    import signal

    signal.raise_signal(signal.SIGTERM)
    return []


def _swallowed_sigterm(*args, **kwargs):
    try:
        _raise_sigterm()
    except BaseException:  # noqa: BLE001 - what clean-up code in plotting libraries does
        pass
    return []


@pytest.mark.parametrize("plot", [_raise_sigterm, _swallowed_sigterm])
def test_sigterm_while_plotting_leaves_no_staging_directory(monkeypatch, tmp_path, plot):
    import camtrain.report.sheets as sheets

    monkeypatch.setattr(sheets, "write_plots", plot)
    deck = (DECKS / "harrison_flat.toml").read_text(encoding="utf-8")
    deck = deck.replace("angle_points = 1440", "angle_points = 120")
    res = _cli("run", "-", "--out", tmp_path / "o", "--plots", "all", "-q", input=deck)
    assert res.exit_code == 143, res.output
    assert "terminated" in res.output
    assert list(tmp_path.iterdir()) == []


def test_sigterm_while_writing_a_lift_table_leaves_nothing(monkeypatch, tmp_path):
    import camtrain.report.plots as plots

    monkeypatch.setattr(plots, "lift_sheet", _raise_sigterm)
    res = _cli("lift", DECKS / "harrison_flat.toml", "--out", tmp_path / "o", "-q")
    assert res.exit_code == 143, res.output
    assert list(tmp_path.iterdir()) == []
