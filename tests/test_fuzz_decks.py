"""Property-based fuzzing: mutated valid decks give exit 2 with a message, never a traceback.

Mutations: wrong types, missing keys, extreme and non-finite numbers, unknown sections and keys.
A mutation may also leave the deck valid (exit 0); what must never happen is any other exit code
from `check` or an uncaught exception.
"""
from __future__ import annotations

import math
import os
import tomllib

import pytest
import tomli_w
from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from camtrain.cli import main
from camtrain.deck.templates import render_template
from tests.fuzz.mutate import ROOT, SLOW_KINDS, kind_of_case, kinds, small_grid
from tests.fuzz.mutate import case as fuzz_case
from tests.fuzz.mutate import sources as fuzz_sources
from tests.fuzz.verdict import Hang, assert_sane, run_deck, write_report

TEMPLATES = {m: tomllib.loads(render_template(m)) for m in ("flat", "finger", "rocker", "domed")}
TEMPLATE_TEXT = render_template("flat")

junk_values = st.one_of(
    st.none(), st.booleans(), st.integers(-10**12, 10**12),
    st.floats(allow_nan=True, allow_infinity=True), st.sampled_from([1e308, -1e308, 5e-324, 0.0]),
    st.text(max_size=8), st.lists(st.floats(allow_nan=True), max_size=5),
    st.dictionaries(st.text(max_size=5), st.integers(), max_size=2),
)


def _paths(node, prefix=()):
    if isinstance(node, dict):
        for k, v in node.items():
            yield prefix + (k,)
            yield from _paths(v, prefix + (k,))


def _set(raw, path, value):
    node = raw
    for key in path[:-1]:
        node = node[key]
    if value is None:
        del node[path[-1]]
    else:
        node[path[-1]] = value


def _to_text(raw) -> str:
    """TOML text; a NaN/inf value is written as TOML nan/inf literals by tomli-w."""
    return tomli_w.dumps(raw)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_mutated_decks_never_traceback(data):
    mechanism = data.draw(st.sampled_from(sorted(TEMPLATES)))
    raw = tomllib.loads(tomli_w.dumps(TEMPLATES[mechanism]))  # deep copy
    for _ in range(data.draw(st.integers(1, 3))):
        kind = data.draw(st.sampled_from(["replace", "delete", "unknown_key", "unknown_section"]))
        paths = list(_paths(raw))
        if kind == "replace" and paths:
            path = data.draw(st.sampled_from(paths))
            value = data.draw(junk_values)
            if value is None:
                continue
            _set(raw, path, value)
        elif kind == "delete" and paths:
            _set(raw, data.draw(st.sampled_from(paths)), None)
        elif kind == "unknown_key":
            section = data.draw(st.sampled_from([k for k, v in raw.items() if isinstance(v, dict)]
                                                or ["x"]))
            raw.setdefault(section, {})
            if isinstance(raw[section], dict):
                raw[section][data.draw(st.text(min_size=1, max_size=6))] = 1
        else:
            raw[data.draw(st.text(min_size=1, max_size=6))] = {"a": 1}
    res = CliRunner().invoke(main, ["check", "-", "--quiet"], input=_to_text(raw))
    # 3: check runs the cheap geometry and refuses what run would (e.g. a pivot that
    # cannot reach the cam)
    assert res.exit_code in (0, 2, 3), (res.exit_code, res.output, res.exception)
    if res.exit_code == 2:
        assert res.output.startswith("error:"), res.output
    if res.exit_code == 3:     # after any size warnings (a deck written in metres)
        assert "\nerror:" in "\n" + res.output, res.output
    assert "Traceback" not in res.output


@settings(max_examples=60, deadline=None)
@given(text=st.text(max_size=200))
def test_arbitrary_text_never_tracebacks(text):
    res = CliRunner().invoke(main, ["check", "-", "--quiet"], input=text)
    assert res.exit_code in (0, 2)
    assert "Traceback" not in res.output


@settings(max_examples=40, deadline=None)
@given(x=st.floats(allow_nan=True, allow_infinity=True))
def test_base_radius_any_float(x):
    raw = tomllib.loads(tomli_w.dumps(TEMPLATES["flat"]))
    raw["cam"]["base_radius"] = x
    res = CliRunner().invoke(main, ["check", "-", "--quiet"], input=_to_text(raw))
    valid = math.isfinite(x) and 1e-12 <= x <= 1e12   # beyond: a slip (camtrain.deck.fields)
    if not valid:
        assert res.exit_code == 2, res.output
    elif res.exit_code == 3:   # check runs the geometry: too small a base circle for a flat face
        assert x < 13.6 and "cam.base_radius" in res.output and "must exceed" in res.output
    else:
        assert res.exit_code == 0 and x > 13.5, res.output


# ------------------------------------------------------------------ `run` over mutated decks
# Every shipped deck and template, mutated (tests/fuzz/mutate.py: wrong types, NaN/inf, 0,
# +-1e300, 1e-300, unit strings, missing/unknown keys and sections, shuffled and duplicated table
# rows, text damage), through `camtrain run`: exit 0-4 only, no traceback, no output directory
# on failure, no non-finite metric without a warning naming it (tests/fuzz/verdict.py).
# `make test` runs FUZZ_CASES cases; `make fuzz` runs thousands (CAMTRAIN_FUZZ_CASES).

FUZZ_CASES = int(os.environ.get("CAMTRAIN_FUZZ_CASES", "200"))
FUZZ_START = int(os.environ.get("CAMTRAIN_FUZZ_START", "0"))
#: time box of one case [s]: a run still going after it fails the case as a hang (the slowest
#: kinds take about 10 s on a loaded machine)
FUZZ_BOX = float(os.environ.get("CAMTRAIN_FUZZ_BOX", "180"))
#: with CAMTRAIN_FUZZ_REPORT set, the cases per kind and their exit codes are written there
FUZZ_REPORT = os.environ.get("CAMTRAIN_FUZZ_REPORT")
_tally: dict[tuple[str, str], int] = {}


@pytest.fixture(scope="module")
def fuzz_report():
    import time

    start = time.monotonic()
    yield _tally
    if FUZZ_REPORT and _tally:
        write_report(FUZZ_REPORT, _tally, time.monotonic() - start)


@pytest.mark.parametrize("seed", range(FUZZ_START, FUZZ_START + FUZZ_CASES))
def test_mutated_deck_runs_or_fails_cleanly(seed, tmp_path, monkeypatch, fuzz_report):
    monkeypatch.chdir(ROOT / "decks")   # standard input: decks name their files from here
    name, text, done = fuzz_case(seed)
    out = tmp_path / "out"
    key = (kind_of_case(seed), "hang")
    try:
        res = run_deck(text, out, FUZZ_BOX)
        key = (key[0], str(res.exit_code))
    finally:
        fuzz_report[key] = fuzz_report.get(key, 0) + 1
    assert_sane(res, out, f"fuzz case {seed}: {name}: {done}")


@pytest.mark.slow   # make test-all (about a minute on two cores)
def test_every_source_is_fuzzed_and_runs_unmutated(tmp_path, monkeypatch):
    """The fuzz starts from every shipped deck and template, each valid as given."""
    monkeypatch.chdir(ROOT / "decks")   # standard input: decks name their files from here
    names = sorted(fuzz_sources())
    assert {n.split(":")[1] for n in names if n.startswith("deck:")} == {
        p.stem for p in (ROOT / "decks").glob("*.toml")}
    from camtrain.cli import MECHANISM_CHOICES

    assert len([n for n in names if n.startswith("template:")]) == len(MECHANISM_CHOICES)
    assert {n.split(":")[1] for n in names if n.startswith("repro:")} == {
        p.stem for p in (ROOT / "tests" / "repro").glob("*.toml")}
    every = {"valve_train", "dynamics", "camshaft", "elastic_camshaft", "coupled_camshaft",
             "transient_film", "journal_bearing", "finite_bearing", "engine"}
    assert set(kinds().values()) == every and set(SLOW_KINDS) <= every
    for i, name in enumerate(names):
        out = tmp_path / str(i)
        res = run_deck(tomli_w.dumps(small_grid(tomllib.loads(fuzz_sources()[name]))), out,
                       FUZZ_BOX)
        assert_sane(res, out, name)
        # the reproducers are refused on purpose (exit 2), except the slow ones, which run
        if not name.startswith("repro:") or name.endswith("_slow"):
            assert res.exit_code in (0, 1), (name, res.output[-500:])


def test_the_time_box_stops_a_hanging_case(monkeypatch, tmp_path):
    import time

    import camtrain.effects.kinematics as kinematics

    monkeypatch.setattr(kinematics, "run", lambda *a, **k: time.sleep(30))
    with pytest.raises(Hang, match="time box of 0.5 s"):
        run_deck(tomli_w.dumps(small_grid(tomllib.loads(TEMPLATE_TEXT))), tmp_path / "o", 0.5)
    assert not (tmp_path / "o").exists()


class _Crash(RuntimeError):
    pass


def _crash(*args, **kwargs):
    raise _Crash("injected")


def test_the_verdict_catches_an_internal_error(monkeypatch, tmp_path):
    """An effect that crashes gives exit 70: the fuzz assertion must fail on it."""
    import camtrain.effects.kinematics as kinematics

    monkeypatch.setattr(kinematics, "run", _crash)
    out = tmp_path / "out"
    res = run_deck(tomli_w.dumps(small_grid(tomllib.loads(TEMPLATE_TEXT))), out)
    assert res.exit_code == 70
    with pytest.raises(AssertionError, match="exit code 70"):
        assert_sane(res, out)


def test_the_verdict_catches_a_traceback(monkeypatch, tmp_path):
    """A crash that escapes the CLI's last line of defence (a traceback for the user) fails
    the fuzz assertion too, whether it escapes or is printed."""
    import traceback

    import click

    import camtrain.cli as cli
    import camtrain.effects.kinematics as kinematics

    monkeypatch.setattr(kinematics, "run", _crash)
    monkeypatch.setattr(cli._Group, "invoke", click.Group.invoke)   # no last line of defence
    monkeypatch.setattr(cli, "_run_one", lambda deck, *a, **k: _crash())
    out = tmp_path / "out"
    res = run_deck(tomli_w.dumps(small_grid(tomllib.loads(TEMPLATE_TEXT))), out)
    with pytest.raises(AssertionError, match="exception escaped"):
        assert_sane(res, out)

    def printed(deck, *a, **k):
        try:
            _crash()
        except _Crash:
            click.echo(traceback.format_exc(), err=True)
        raise SystemExit(2)

    monkeypatch.setattr(cli, "_run_one", printed)
    res = run_deck(tomli_w.dumps(small_grid(tomllib.loads(TEMPLATE_TEXT))), out)
    with pytest.raises(AssertionError, match="traceback printed"):
        assert_sane(res, out)


def test_the_verdict_catches_a_silent_non_finite_metric(monkeypatch, tmp_path):
    from dataclasses import replace

    import camtrain.runner as runner

    def silent_nan_max_lift(result):
        # in place of the runner's warning pass: a NaN metric that no warning names (set on the
        # finished result: the lift law's metrics are formed once per process, not per run)
        result.metrics["max_lift"] = replace(result.metrics["max_lift"], value=float("nan"))

    monkeypatch.setattr(runner, "warn_non_finite", silent_nan_max_lift)
    out = tmp_path / "out"
    res = run_deck(tomli_w.dumps(small_grid(tomllib.loads(TEMPLATE_TEXT))), out)
    with pytest.raises(AssertionError, match="non-finite metrics without a warning"):
        assert_sane(res, out)


def test_the_verdict_catches_an_output_directory_left_by_a_failure(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    res = run_deck("title = 1\n", out)
    assert res.exit_code == 2
    with pytest.raises(AssertionError, match="output directory left"):
        assert_sane(res, out)
