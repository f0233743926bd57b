"""The plot sheets' floor: what a run with sheets costs before a single panel is drawn.

`test_bench_run_with_sheets` (test_bench_chain.py) times the default run against the same run
with `--no-plots` (target <= 2x). Drawing with matplotlib first imports its Agg path; these time
that import on top of the same `--no-plots` run (the best any matplotlib sheet could reach) and
the four Harrison sheets drawn in process once matplotlib is loaded. Nothing here asserts a time.
"""
from __future__ import annotations

import subprocess
import sys

from conftest import ENV, ROOT, note, paired, record

DECK = str(ROOT / "decks" / "harrison_flat.toml")
AGG = "import matplotlib.figure, matplotlib.backends.backend_agg"


def _process(*args: str):
    cmd = [sys.executable, *args]
    return lambda: subprocess.run(cmd, capture_output=True, check=True, cwd=ROOT, env=ENV)


def test_bench_sheets_floor(benchmark, tmp_path):
    """`run --no-plots` that also imports matplotlib's Agg path, against `run --no-plots`."""
    args = ["run", DECK, "--no-plots", "--quiet", "--out", str(tmp_path / "out")]
    floor = _process("-c", f"{AGG}\nfrom camtrain.cli import main\nmain()", *args)
    bare = _process("-m", "camtrain.cli", *args)
    timing = paired(floor, bare, rounds=5)
    record(benchmark, "`run --no-plots` + import of matplotlib's Agg path / `run --no-plots` "
           "(the sheets' floor)", timing, cpu=True)
    benchmark.pedantic(floor, rounds=1, iterations=1)


def test_bench_four_sheets_in_process(benchmark, tmp_path):
    """The four Harrison sheets (PNG) drawn and written in a process that has matplotlib
    loaded: the drawing alone, first call (a fresh page and text cache) and warm."""
    import time

    from camtrain import api
    from camtrain.deck.load import load_deck
    from camtrain.report import canvas
    from camtrain.report.sheets import write_plots

    loaded = load_deck(DECK)
    result = api.run(loaded.model)

    def draw():
        write_plots(result, loaded.model, tmp_path, single_panels=False, formats=("png",),
                    sha=loaded.sha256)

    def cpu_of_draw() -> float:
        start = time.process_time()
        draw()
        return time.process_time() - start

    canvas._STRINGS.clear()
    first = cpu_of_draw()
    warm = min(cpu_of_draw() for _ in range(3))
    benchmark.pedantic(draw, rounds=1, iterations=1)
    note("four Harrison sheets (PNG) drawn in process, matplotlib loaded",
         f"cpu first {first * 1e3:.0f} ms, warm {warm * 1e3:.0f} ms")
