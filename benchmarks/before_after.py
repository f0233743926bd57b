"""The same work timed in two source trees, as alternating processes (docs/performance.md,
"Before and after the one-chain redesign").

``make bench`` times each workload against a floor; this script answers a different question:
is a change no slower than the code it replaced? Each item below runs as a process of its own
with ``PYTHONPATH`` set to one tree (the interpreter, the environment and the deck text are the
same), in strict rotation with the other tree and with a second run of the old tree (the A/A
control, which shows how far two runs of the *same* code differ on the machine of the moment).
Each round rotates the order of its three processes; the first round of each item is discarded
(it may fill numba's disk cache or the bytecode caches of a fresh checkout).

Two CPU figures per process: the child's ``time.process_time`` around the work alone (after a
small warm-up of the same work, so imports and first-call costs are outside it), and the whole
process' CPU from the kernel (``os.wait4``: user + system of the process and any child it
waited for). The report per item: median and minimum of each tree, the median of the rounds'
ratios new/old with its bootstrap 95 % interval, and the same for the A/A control; "no slower"
holds when the interval's upper end is at most 1 + the control's spread (its larger distance
from 1).

    python benchmarks/before_after.py OLD_TREE [--new NEW_TREE] [--pairs 15] [--items ...]
    python benchmarks/before_after.py OLD_TREE --compile [--runs 2]

OLD_TREE is a checkout of the code before (e.g. ``git worktree add --detach ../before REV``);
NEW_TREE defaults to the checkout holding this script. ``--compile`` instead measures the
coupled march's first call less its second, each run in a new process with an empty numba
cache of its own (``NUMBA_CACHE_DIR``), the two trees alternated. ``--json FILE`` keeps every
measurement.
"""
from __future__ import annotations

import argparse
import json
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve()
CASES = 1000          # the sweep benchmark's cases (benchmarks/test_bench_sweep.py)
CHAIN_RUNS = 1000     # in-process chain runs timed per process (test_bench_chain: 300 rounds)

# --- the work, run in the child process (only APIs both trees have) -----------------------------


def _sweep(tree: Path, points: int) -> float:
    """`camtrain sweep` of 1000 base radii of harrison_flat, tables only, --jobs 1 (the batch
    route), in process; a two-case sweep of other radii first imports and warms it."""
    from camtrain.cli import main

    deck = str(tree / "decks" / "harrison_flat.toml")

    def sweep(cases: str) -> None:
        with tempfile.TemporaryDirectory() as out:
            main(["sweep", deck, "-p", "base_radius", "--range", cases, "--set",
                  f"solver.angle_points={points}", "--no-plots", "--quiet", "--jobs", "1",
                  "--out", str(Path(out) / "sweep")], standalone_mode=False)

    sweep("12:13:2")
    start = time.process_time()
    sweep(f"14:22:{CASES}")
    return time.process_time() - start


def _chain(tree: Path, points: int) -> float:
    """`api.run` of harrison_flat at ``points`` angles, as benchmarks/test_bench_chain.py:
    five runs to warm, then the mean CPU of CHAIN_RUNS runs."""
    import re

    from camtrain import api
    from camtrain.deck.load import load_deck_text

    text = (tree / "decks" / "harrison_flat.toml").read_text("utf-8")
    model = load_deck_text(re.sub(r"(?m)^angle_points = \d+", f"angle_points = {points}",
                                  text)).model
    for _ in range(5):
        api.run(model)
    start = time.process_time()
    for _ in range(CHAIN_RUNS):
        api.run(model)
    return (time.process_time() - start) / CHAIN_RUNS


def _four_trains(tree: Path):
    """The problem of benchmarks/test_bench_camshaft_coupled.py: four elastic trains of the
    Zeta intake camshaft on the elastic shaft, two-way coupled, monolithic, Petroff bearings."""
    import tomllib

    from camtrain.deck.load import validate

    raw = tomllib.loads((tree / "decks" / "zeta_intake_camshaft_coupled.toml").read_text("utf-8"))
    raw["camshaft"]["lobes"] = raw["camshaft"]["lobes"][::2]
    raw["camshaft"]["flexibility"]["coupling_solver"] = "monolithic"
    raw["camshaft"]["method"] = "petroff"
    raw.setdefault("tribology", {})["film_model"] = "steady"
    return validate(raw, "four trains", tree / "decks")


def _coupled(tree: Path) -> float:
    """The coupled march warm: one run loads the compiled kernels, the second is timed."""
    from camtrain import api

    model = _four_trains(tree)
    api.run(model)
    start = time.process_time()
    api.run(model)
    return time.process_time() - start


def _compile(tree: Path) -> float:
    """First run less second run (CPU s) of the coupled problem; the caller empties the cache."""
    from camtrain import api

    model = _four_trains(tree)
    start = time.process_time()
    api.run(model)
    first = time.process_time() - start
    start = time.process_time()
    api.run(model)
    return first - (time.process_time() - start)


ITEMS = {"sweep-720": lambda t: _sweep(t, 720), "sweep-1440": lambda t: _sweep(t, 1440),
         "chain-720": lambda t: _chain(t, 720), "chain-1440": lambda t: _chain(t, 1440),
         "coupled": _coupled, "compile": _compile}

# --- the parent: processes in rotation and the statistics --------------------------------------


def _run_child(tree: Path, item: str, cache: str | None = None) -> tuple[float, float]:
    """Work CPU (the child's own clock) and whole-process CPU [s] (the kernel's accounting of
    the child and anything it waited for) of ``item`` run in ``tree``."""
    env = dict(os.environ, PYTHONPATH=str(tree))
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    if cache:
        env["NUMBA_CACHE_DIR"] = cache
    with tempfile.TemporaryFile("w+") as out:
        proc = subprocess.Popen([sys.executable, str(HERE), "--child", item, str(tree)],
                                cwd=tree, env=env, stdout=out, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
        if proc.returncode:
            raise SystemExit(f"{item} in {tree} failed (exit {proc.returncode})")
        out.seek(0)
        work = float(out.read().strip().splitlines()[-1])
    return work, usage.ru_utime + usage.ru_stime


def _ratio_interval(new: list[float], old: list[float], draws: int = 10000,
                    seed: int = 1) -> tuple[float, float, float]:
    """The median of the rounds' ratios new/old (each round's two processes ran back to back,
    so a change of the machine's load between rounds cancels) and its bootstrap 95 %
    percentile interval (rounds resampled with replacement)."""
    rng = random.Random(seed)
    ratios = [a / b for a, b in zip(new, old, strict=True)]
    medians = sorted(statistics.median(rng.choices(ratios, k=len(ratios)))
                     for _ in range(draws))
    return (statistics.median(ratios), medians[int(0.025 * draws)],
            medians[int(0.975 * draws) - 1])


def _summary(item: str, rows: list[dict], what: str) -> dict:
    new, old, ctl = ([r[k][what] for r in rows] for k in ("new", "old", "old2"))
    ratio, lo, hi = _ratio_interval(new, old)
    aa, aa_lo, aa_hi = _ratio_interval(ctl, old)
    spread = max(aa_hi - 1.0, 1.0 - aa_lo)
    return {"item": item, "cpu": what, "pairs": len(rows),
            "new_median": statistics.median(new), "new_min": min(new),
            "old_median": statistics.median(old), "old_min": min(old),
            "ratio": ratio, "ratio_lo": lo, "ratio_hi": hi,
            "aa": aa, "aa_lo": aa_lo, "aa_hi": aa_hi, "no_slower": hi <= 1.0 + spread}


def _fmt(seconds: float) -> str:
    return f"{seconds * 1e3:.4g} ms" if seconds < 1.0 else f"{seconds:.4g} s"


def _table(summaries: list[dict]) -> str:
    head = ("| item | CPU | new median / min | old median / min | new/old [95 %] | "
            "A/A old/old [95 %] | no slower |\n|---|---|---|---|---|---|---|")
    lines = [head]
    for s in summaries:
        lines.append(
            f"| {s['item']} | {s['cpu']} | {_fmt(s['new_median'])} / {_fmt(s['new_min'])} | "
            f"{_fmt(s['old_median'])} / {_fmt(s['old_min'])} | {s['ratio']:.3f}x "
            f"[{s['ratio_lo']:.3f}, {s['ratio_hi']:.3f}] | {s['aa']:.3f}x [{s['aa_lo']:.3f}, "
            f"{s['aa_hi']:.3f}] | {'yes' if s['no_slower'] else 'no'} |")
    return "\n".join(lines)


def compare(new: Path, old: Path, items: list[str], pairs: int) -> tuple[list[dict], dict]:
    """Every item: one discarded round, then ``pairs`` rounds of new, old and old again, the
    order rotated round by round."""
    trees = {"new": new, "old": old, "old2": old}
    order = ["new", "old", "old2"]
    runs: dict[str, list[dict]] = {}
    for item in items:
        rows = []
        for k in range(pairs + 1):
            turn = order[k % 3:] + order[:k % 3]
            row = {}
            for who in turn:
                work, whole = _run_child(trees[who], item)
                row[who] = {"work": work, "process": whole}
            if k:
                rows.append(row)
            print(f"{item} round {k}: " + ", ".join(
                f"{who} {row[who]['work']:.4g}/{row[who]['process']:.3g}" for who in order),
                file=sys.stderr, flush=True)
        runs[item] = rows
    summaries = [_summary(item, runs[item], what) for item in items
                 for what in ("work", "process")]
    return summaries, runs


def compile_times(new: Path, old: Path, runs: int) -> tuple[str, dict]:
    """The coupled problem's first call less its second, a new empty numba cache per run, the
    trees alternated (old first in odd runs)."""
    got: dict[str, list[tuple[float, float]]] = {"new": [], "old": []}
    for k in range(runs):
        for who in (("old", "new") if k % 2 == 0 else ("new", "old")):
            with tempfile.TemporaryDirectory() as cache:
                got[who].append(_run_child(new if who == "new" else old, "compile", cache))
            print(f"compile {who}: {got[who][-1]}", file=sys.stderr, flush=True)
    lines = ["| tree | first call less second, CPU s | whole process, CPU s |", "|---|---|---|"]
    for who in ("old", "new"):
        lines.append(f"| {who} | {' / '.join(f'{w:.1f}' for w, _ in got[who])} | "
                     f"{' / '.join(f'{p:.1f}' for _, p in got[who])} |")
    return "\n".join(lines), got


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("old", type=Path, help="checkout of the code before")
    parser.add_argument("--new", type=Path, default=HERE.parent.parent,
                        help="checkout of the code after (default: this one)")
    parser.add_argument("--pairs", type=int, default=15)
    parser.add_argument("--items", nargs="+", default=["sweep-720", "sweep-1440", "chain-720",
                                                      "chain-1440", "coupled"],
                        choices=sorted(set(ITEMS) - {"compile"}))
    parser.add_argument("--compile", action="store_true",
                        help="measure the coupled march's first-call compile instead")
    parser.add_argument("--runs", type=int, default=2, help="compile runs per tree")
    parser.add_argument("--json", type=Path, help="write every measurement here")
    args = parser.parse_args(argv)
    new, old = args.new.resolve(), args.old.resolve()
    if args.compile:
        table, data = compile_times(new, old, args.runs)
    else:
        summaries, data = compare(new, old, args.items, args.pairs)
        table = _table(summaries)
        data = {"summaries": summaries, "runs": data}
    print(table)
    if args.json:
        args.json.write_text(json.dumps(data, indent=1), "utf-8")


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--child":
        print(repr(ITEMS[sys.argv[2]](Path(sys.argv[3]))))
    else:
        main()
