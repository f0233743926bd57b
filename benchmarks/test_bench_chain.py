"""The analysis chain and whole `camtrain run` processes, each as a ratio to its floor measured in
the same run (`make bench`; the table in docs/performance.md). Nothing here asserts a time.

Floors: the bare-numpy Harrison chain of ``harrison_floor.py`` (same physics, same columns to
1e-13, tested in tests/test_harrison_floor.py) for the in-process chain; the interpreter importing
numpy and scipy for a whole ``run --no-plots`` process; ``run --no-plots`` for a run with sheets.
"""
from __future__ import annotations

import re
import subprocess
import sys

import pytest
from conftest import ENV, ROOT, paired, record
from harrison_floor import harrison_floor

from camtrain import api
from camtrain.deck.load import load_deck_text

DECK = (ROOT / "decks" / "harrison_flat.toml").read_text()


def harrison_model(points: int):
    text = re.sub(r"(?m)^angle_points = \d+", f"angle_points = {points}", DECK)
    model = load_deck_text(text).model
    assert model.solver.angle_points == points
    return model


@pytest.mark.parametrize(("points", "target"), [(720, "<= 3x"), (1440, ""), (3600, "<= 2x")])
def test_bench_chain(benchmark, points, target):
    """All effects of the Harrison deck in process (`api.run`) against the bare-numpy chain.
    1440 angles is the default grid (the coarsest meeting the default 0.1 % accuracy on power
    loss, `camtrain accuracy`); 720 and 3600 are the grids the targets were set at."""
    model = harrison_model(points)
    timing = paired(lambda: api.run(model), lambda: harrison_floor(points), rounds=300,
                    warmup=5)
    record(benchmark, f"chain, {points} angles, in-process", timing, target, cpu=True)
    benchmark(api.run, model)


def _forget_kinematics() -> None:
    """Empty the per-process kinematics caches (camtrain.effects.kinematics): the chain then
    forms the Kinematics, their columns and metrics again, as a deck's first run does."""
    from camtrain.effects import kinematics

    for cache in (kinematics._deck_kinematics, kinematics._cached_kinematics,
                  kinematics._column_rows, kinematics._metric_rows):
        cache.cache_clear()


@pytest.mark.parametrize("points", [720, 3600])
def test_bench_chain_kinematics_formed(benchmark, points):
    """As test_bench_chain, with the kinematics caches emptied before every run: the cost of a
    deck's first run (the lift curve stays cached, as before those caches)."""
    model = harrison_model(points)

    def first_run():
        _forget_kinematics()
        return api.run(model)

    timing = paired(first_run, lambda: harrison_floor(points), rounds=300, warmup=5)
    record(benchmark, f"chain, {points} angles, kinematics formed each run", timing, cpu=True)
    benchmark(first_run)


def _process(*args: str):
    cmd = [sys.executable, *args]
    return lambda: subprocess.run(cmd, capture_output=True, check=True, cwd=ROOT, env=ENV)


@pytest.mark.parametrize("display", ["report", "quiet"])
def test_bench_run_process(benchmark, tmp_path, display):
    """`camtrain run DECK --no-plots` against `python -c "import numpy, scipy"`: the command a
    user runs, its report printed (here into a pipe, as rich would print it there), and with
    `--quiet` (nothing printed)."""
    deck = str(ROOT / "decks" / "harrison_flat.toml")
    quiet = ["--quiet"] if display == "quiet" else []
    run = _process("-m", "camtrain.cli", "run", deck, "--no-plots", *quiet, "--out",
                   str(tmp_path / "out"))
    timing = paired(run, _process("-c", "import numpy, scipy"), rounds=7)
    record(benchmark, f"`run --no-plots{' --quiet' if quiet else ''}` process / "
           "`import numpy, scipy`", timing, "<= 2.5x" if not quiet else "", cpu=True)
    benchmark.pedantic(run, rounds=3, iterations=1)


def test_bench_run_with_sheets(benchmark, tmp_path):
    """The default `camtrain run` (four plot sheets) against the same run with `--no-plots`."""
    deck = str(ROOT / "decks" / "harrison_flat.toml")
    base = ["-m", "camtrain.cli", "run", deck, "--quiet", "--out", str(tmp_path / "out")]
    sheets, bare = _process(*base), _process(*base, "--no-plots")
    timing = paired(sheets, bare, rounds=3)
    record(benchmark, "default `run` with sheets / `run --no-plots`", timing, "<= 2x", cpu=True)
    benchmark.pedantic(sheets, rounds=1, iterations=1)


def test_bench_help_process(benchmark):
    """`camtrain --help` against the bare interpreter (the CLI imports no numpy for --help)."""
    helper = _process("-m", "camtrain.cli", "--help")
    timing = paired(helper, _process("-c", "pass"), rounds=7)
    record(benchmark, "`camtrain --help` / bare interpreter", timing, cpu=True)
    benchmark.pedantic(helper, rounds=3, iterations=1)
