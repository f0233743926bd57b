"""The local process pool of `sweep --jobs N`: no helper thread, a dead worker is reported."""
from __future__ import annotations

import os
import threading
import time

import pytest

from camtrain.study.executors import ProcessExecutor, SerialExecutor, WorkerLost


def _square(x: int) -> int:
    time.sleep(0.002)
    return x * x


def _dies_in_a_worker(x: int) -> int:
    # a worker whether forked or spawned: the pool spawns once another test has left a thread
    # running (forking a threaded process can deadlock); a pid taken at import would be the
    # spawned worker's own, so it would not die
    import multiprocessing

    if multiprocessing.parent_process() is not None:
        os._exit(9)
    time.sleep(0.02)
    return x


def test_process_pool_gives_every_result_and_runs_no_thread_of_its_own():
    # a thread reading the workers' pipes could be left waiting on half a message when a
    # worker is killed mid-send, and would then keep an interrupted sweep from exiting
    running = threading.active_count()    # (a test before may have left a thread running)
    pool = ProcessExecutor(3)
    try:
        results, threads = [], set()
        for value in pool.map(_square, range(200)):
            results.append(value)
            threads.add(threading.active_count())
    finally:
        pool.close()
    assert sorted(results) == [x * x for x in range(200)]
    assert sorted(results) == sorted(SerialExecutor().map(_square, range(200)))
    assert threads == {running}
    assert not any(w.process.is_alive() for w in pool._workers)


def test_a_worker_that_dies_is_reported_not_waited_for():
    pool = ProcessExecutor(2)
    try:
        with pytest.raises(WorkerLost, match=r"sweep worker \(pid \d+\) died \(exit code 9\)"):
            list(pool.map(_dies_in_a_worker, range(400)))
    finally:
        pool.abort()
    assert not any(w.process.is_alive() for w in pool._workers)
