"""SIGTERM (CI cancellation, `timeout`) to `camtrain sweep -j N` stops its workers too."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

psutil = pytest.importorskip("psutil")

ROOT = Path(__file__).resolve().parents[2]


def _sweep_with_workers(deck, out, jobs: int):
    """A long `sweep -j jobs` as a process, once jobs - 1 workers run (and half a second on)."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    cmd = [sys.executable, "-m", "camtrain.cli", "sweep", str(deck), "-p", "speed",
           "--range", "1000:3000:20000", "-j", str(jobs), "--no-plots", "-q", "--out", str(out)]
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    parent = psutil.Process(proc.pid)
    workers: list = []
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and proc.poll() is None:
        # forked workers run the sweep's own command line, spawned ones spawn_main
        workers = [p for p in parent.children(recursive=True)
                   if "resource_tracker" not in " ".join(p.cmdline())]
        if len(workers) >= jobs - 1:
            break
        time.sleep(0.2)
    assert len(workers) >= jobs - 1, f"the sweep never started its workers: {proc.poll()}"
    time.sleep(0.5)
    assert proc.poll() is None, "the sweep ended before the test could act on it"
    return proc, workers


def test_sigterm_to_a_parallel_sweep_leaves_no_worker_running(fast_flat, tmp_path):
    proc, workers = _sweep_with_workers(fast_flat, tmp_path / "s", 3)
    proc.send_signal(signal.SIGTERM)
    proc.wait(timeout=30)
    _, alive = psutil.wait_procs(workers, timeout=10)
    for p in alive:
        p.kill()
    _, err = proc.communicate(timeout=10)
    assert not alive, f"workers still running after SIGTERM: {[p.pid for p in alive]}"
    assert proc.returncode == 143, err.decode()
    assert b"--resume" in err and b"Traceback" not in err


def test_a_worker_killed_from_outside_ends_the_sweep_with_a_message(fast_flat, tmp_path):
    proc, workers = _sweep_with_workers(fast_flat, tmp_path / "s", 2)
    workers[0].kill()
    _, err = proc.communicate(timeout=30)
    assert proc.returncode == 70, err.decode()
    assert b"died (exit code -9)" in err and b"--resume" in err and b"Traceback" not in err
    assert (tmp_path / "s" / "sweep.csv").exists()


def test_workers_end_when_the_sweep_is_killed(fast_flat, tmp_path):
    # SIGKILL cannot be handled: each worker must see its pipe end and stop by itself
    proc, workers = _sweep_with_workers(fast_flat, tmp_path / "s", 3)
    proc.kill()
    proc.communicate(timeout=10)
    _, alive = psutil.wait_procs(workers, timeout=20)
    for p in alive:
        p.kill()
    assert not alive, f"workers still running after the sweep was killed: {[p.pid for p in alive]}"
