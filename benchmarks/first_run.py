"""First and warm run of every shipped deck, in CPU time: what the compiled kernels cost a user.

Each deck runs as the user runs it (``camtrain run DECK --no-plots -q``, a process of its own)
with numba's disk cache pointed at a directory of this script's own (``NUMBA_CACHE_DIR``), so the
installation's cache is neither used nor touched:

* ``cold``: an empty cache, then the same command again (``warm``): the compile a deck's first
  run pays when nothing was compiled before, and the run afterwards;
* ``warmup``: an empty cache, ``camtrain warmup`` once, then every deck's first run: what a user
  pays after ``make demo`` (which runs the warm-up).

    PYTHONPATH=. python benchmarks/first_run.py [--phase cold|warmup|both] [DECK ...]

CPU time is the child processes' user + system time (``getrusage``); it grows much less than
the wall clock on a shared machine. Prints a Markdown table (docs/performance.md, "First run").
"""
from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _env(cache: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), *filter(None, [env.get("PYTHONPATH")])])
    env["NUMBA_CACHE_DIR"] = str(cache)
    return env


def timed(args: list[str], cache: Path, out: Path) -> tuple[float, float]:
    """(CPU [s], wall [s]) of one camtrain process; raises if it failed to run."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "camtrain.cli", *args], cwd=out,
                          env=_env(cache), capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode not in (0, 1):
        raise RuntimeError(f"camtrain {' '.join(args)} exited {done.returncode}:\n{done.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall


def run_deck(deck: Path, cache: Path, out: Path) -> float:
    return timed(["run", str(deck), "--no-plots", "-q", "--out", str(out / deck.stem)],
                 cache, out)[0]


def cold_and_warm(decks: list[Path], work: Path) -> dict[str, tuple[float, float]]:
    rows = {}
    for deck in decks:
        cache = Path(tempfile.mkdtemp(prefix=f"cache-{deck.stem}-", dir=work))
        cold = run_deck(deck, cache, work)
        warm = run_deck(deck, cache, work)
        rows[deck.stem] = (cold, warm)
        print(f"{deck.stem}: cold {cold:.2f} s, warm {warm:.2f} s", file=sys.stderr, flush=True)
    return rows


def after_warmup(decks: list[Path], work: Path) -> tuple[float, dict[str, float]]:
    cache = Path(tempfile.mkdtemp(prefix="cache-warmup-", dir=work))
    warm_up = timed(["warmup"], cache, work)[0]
    print(f"warmup: {warm_up:.2f} s", file=sys.stderr, flush=True)
    rows = {}
    for deck in decks:
        rows[deck.stem] = run_deck(deck, cache, work)
        print(f"{deck.stem}: first after warm-up {rows[deck.stem]:.2f} s", file=sys.stderr,
              flush=True)
    return warm_up, rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phase", choices=("cold", "warmup", "both"), default="both")
    parser.add_argument("decks", nargs="*", type=Path)
    args = parser.parse_args()
    decks = [d.resolve() for d in args.decks] or sorted((ROOT / "decks").glob("*.toml"))
    with tempfile.TemporaryDirectory(prefix="camtrain-first-run-") as tmp:
        work = Path(tmp)
        cold = cold_and_warm(decks, work) if args.phase != "warmup" else {}
        warm_up, first = after_warmup(decks, work) if args.phase != "cold" else (None, {})
    print("| deck | cold [s CPU] | warm [s CPU] | cold / warm | first after warm-up [s CPU] "
          "| first / warm |")
    print("|---|---|---|---|---|---|")
    for deck in decks:
        c, w = cold.get(deck.stem, (float("nan"), float("nan")))
        f = first.get(deck.stem, float("nan"))
        print(f"| {deck.stem} | {c:.2f} | {w:.2f} | {c / w:.1f}x | {f:.2f} | {f / w:.2f}x |")
    if warm_up is not None:
        print(f"\n`camtrain warmup`: {warm_up:.1f} s CPU")


if __name__ == "__main__":
    main()
