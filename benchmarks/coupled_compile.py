"""Compile time and warm speed of the shaft-and-trains revolution alone (docs/performance.md,
"First run" and "Before and after the one-chain redesign").

The arguments of a deck's first revolution are saved once (``save``: the deck runs until the
march calls :func:`camtrain.coupled._revolution.revolution`), then every ``measure`` runs in a
process of its own with an empty numba cache of its own and prints the revolution's first call
less its second (CPU s), so the deck's other kernels and set-up are left out. Alternate the
code before and after, on the same saved arguments, a new cache per measurement:

    PYTHONPATH=. python benchmarks/coupled_compile.py save DECK ARGS
    PYTHONPATH=. python benchmarks/coupled_compile.py measure ARGS [ARGS ...]

``warm`` times the revolution alone with the kernels cached (the disk cache of the checkout
on ``PYTHONPATH``): one call to load them, then ``CALLS`` calls each on a fresh copy of the
saved arguments (the revolution changes its state in place); it prints the minimum and median
CPU time of a call:

    PYTHONPATH=. python benchmarks/coupled_compile.py warm ARGS [CALLS]

The saved arguments are the records of :mod:`camtrain.coupled.records`: code whose records
changed needs them saved again.
"""
from __future__ import annotations

import contextlib
import io
import json
import os
import pickle
import subprocess
import sys
import tempfile
import time


class _Saved(Exception):
    """Stops the deck's run once the arguments are saved."""


def save(deck: str, dest: str) -> None:
    """Run ``deck`` until its first revolution and pickle that call's arguments to ``dest``."""
    import camtrain.coupled._revolution as revolution_module
    from camtrain.cli import main

    def capture(*args):
        with open(dest, "wb") as handle:
            pickle.dump(args, handle)
        raise _Saved

    revolution_module.revolution = capture
    heard = io.StringIO()     # the command line reports the stop as an internal error
    with tempfile.TemporaryDirectory() as out, contextlib.redirect_stderr(heard):
        try:
            main(["run", deck, "--no-plots", "-q", "--out", out], standalone_mode=False)
        except (_Saved, SystemExit):
            pass
    if "_Saved" not in heard.getvalue() or not os.path.exists(dest):
        raise SystemExit(f"{deck}: the march never called the revolution\n{heard.getvalue()}")
    print(f"saved the first revolution's arguments of {deck} to {dest}")


def _measure_here(paths: list[str]) -> dict:
    from camtrain.coupled import _lowrank, _revolution, _step

    rows = {}
    for path in paths:
        with open(path, "rb") as handle:
            data = handle.read()
        times = []
        for _ in range(2):
            start = time.process_time()
            _revolution.revolution(*pickle.loads(data))
            times.append(time.process_time() - start)
        rows[os.path.basename(path)] = {"first": round(times[0], 2), "second": round(times[1], 2),
                                        "compile": round(times[0] - times[1], 2)}
    several = {name: len(fn.signatures) for module in (_revolution, _step, _lowrank)
               for name, fn in vars(module).items()
               if hasattr(fn, "signatures") and len(fn.signatures) > 1}
    return {"runs": rows, "several_signatures": several}


def warm(path: str, calls: int = 20) -> None:
    """The revolution of the saved arguments ``path`` called ``calls`` times, warm."""
    from camtrain.coupled import _revolution

    with open(path, "rb") as handle:
        data = handle.read()
    _revolution.revolution(*pickle.loads(data))
    times = []
    for _ in range(calls):
        args = pickle.loads(data)
        start = time.process_time()
        _revolution.revolution(*args)
        times.append(time.process_time() - start)
    times.sort()
    print(f"{os.path.basename(path)}: revolution warm, {calls} calls: min "
          f"{1e3 * times[0]:.1f} ms, median {1e3 * times[len(times) // 2]:.1f} ms CPU")


def measure(paths: list[str]) -> None:
    """Each call in a new process with an empty numba cache of its own."""
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        done = subprocess.run([sys.executable, __file__, "_here", *paths], env=env,
                              capture_output=True, text=True, check=True)
    print(done.stdout.strip().splitlines()[-1])


if __name__ == "__main__":
    mode, rest = sys.argv[1], sys.argv[2:]
    if mode == "save":
        save(rest[0], rest[1])
    elif mode == "measure":
        measure(rest)
    elif mode == "warm":
        warm(rest[0], int(rest[1]) if len(rest) > 1 else 20)
    elif mode == "_here":
        print(json.dumps(_measure_here(rest)))
    else:
        raise SystemExit(__doc__)
