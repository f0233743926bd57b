"""Where sweep cases run: in this process, in local worker processes, or on a Dask cluster.

Every executor calls the same pure function, :func:`run_case`, on the same picklable job, so the
results do not depend on the executor; only the order in which they arrive does, and the output
layer sorts by case index.
"""
from __future__ import annotations

import os
from collections import deque
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass

from camtrain.catalogue import planned_products
from camtrain.errors import EXIT_INTERNAL, CamtrainError
from camtrain.study.sweep import Case, Parameter

#: Per-angle columns kept for the overlay plots (film, load, stress; lift for kinematics-only
#: runs), each with the product whose effect writes it: a case keeps those its plan made
OVERLAY_COLUMNS = {"film_min": "ContactFilm", "load": "ContactLoad",
                   "hertz_pmax": "ContactHertz", "lift": "TrainKinematics"}


@dataclass(frozen=True)
class Job:
    """Everything one case needs, picklable: the raw datum deck and the case to apply to it."""

    raw: dict
    params: tuple[Parameter, ...]
    case: Case
    name: str
    base_dir: str
    keep_curves: bool = False
    #: identity of the datum deck (:func:`camtrain.study.case_model.datum_key`), computed once
    #: by the sweep so a worker recognises a deck it has already validated
    datum: str = ""


def _contact_lost(metrics: dict) -> bool:
    load_min = metrics.get("load_min")
    return load_min is not None and load_min[0] <= 0.0


def run_case(job: Job) -> dict:
    """Build, validate and run one case; never raises for a case that fails.

    The datum deck is validated once per process and each case changes only its swept fields
    (:mod:`camtrain.study.case_model`). Returns a plain record: index, values, status (ok |
    lost_contact | failed | error), message, metrics {name: (value, unit)} and, if asked, the
    overlay curves (the per-angle columns travel back only for those cases).
    """
    from camtrain.runner import run_plan
    from camtrain.study.case_model import build_case_model

    record = {"index": job.case.index, "values": job.case.as_dict(), "status": "ok",
              "message": "", "metrics": {}, "curves": None}
    try:
        model = build_case_model(job.raw, list(job.params), job.case, job.name, job.base_dir,
                                 job.datum)
        result = run_plan(model)
    except CamtrainError as exc:
        record.update(status="failed", message=f"{type(exc).__name__}: {exc}")
        return record
    except Exception as exc:  # noqa: BLE001 - a bug in one case must not end the sweep
        record.update(status="error", message=f"internal error {type(exc).__name__}: {exc}")
        return record
    record["metrics"] = {n: (m.value, m.unit) for n, m in result.metrics.items()}
    if _contact_lost(record["metrics"]):
        # Ball cuts his curves at valve bounce: the case ran, but its results are not physical
        why = [w for w in result.warnings if "contact" in w or "bounce" in w]
        record.update(status="lost_contact", message=why[0] if why else "minimum load <= 0")
    # the kinematics effect made the cam-angle grid the overlay curves are drawn on
    made = planned_products(result.plan)
    if job.keep_curves and "TrainKinematics" in made:
        import math

        curves = {"cam_angle": ("deg", [math.degrees(v) for v in result["cam_angle"]])}
        for name, product in OVERLAY_COLUMNS.items():
            if product in made:
                col = result.columns[name]
                curves[name] = (col.unit, [float(v) for v in col.values])
        record["curves"] = curves
    return record


class SerialExecutor:
    """Runs cases one after another in this process (``--jobs 1``)."""

    description = "serial"
    jobs = 1

    def map(self, fn: Callable, jobs: Iterable) -> Iterator:
        for job in jobs:
            yield fn(job)

    def close(self) -> None:
        pass


def run_chunk(fn: Callable, chunk: list) -> list:
    """``fn`` over a chunk of jobs in one worker round trip."""
    return [fn(job) for job in chunk]


class WorkerLost(CamtrainError):
    """A worker process ended without finishing its chunk (killed from outside, out of memory,
    a crash in compiled code): the sweep stops, its finished cases kept."""

    exit_code = EXIT_INTERNAL


def _serve(conn, siblings=()) -> None:
    """A worker's life: SIGTERM ends it at once (a forked worker inherits the sweep's handler,
    which turns SIGTERM into an interrupt for the parent to clean up after); import what a case
    needs, say so, then run chunks until told to stop or the sweep has gone.

    A thread reads the chunks as they arrive, so the sweep's process never waits to hand over
    the next chunk while this one sends its records (the two could otherwise each wait on a full
    pipe). ``siblings``: the sweep's ends of the pipes (this worker's and the others'), which a
    forked worker inherits and closes, so that it sees the end of its pipe when the sweep dies."""
    import queue
    import signal
    import threading

    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.signal(signal.SIGINT, signal.SIG_IGN)   # Ctrl-C reaches the whole group: the parent decides
    for other in siblings:
        other.close()
    import camtrain.runner  # noqa: F401 - the import is the work
    import camtrain.study.case_model  # noqa: F401

    tasks: queue.SimpleQueue = queue.SimpleQueue()

    def read() -> None:
        while True:
            try:
                task = conn.recv()
            except (EOFError, OSError):   # the sweep has ended or been killed
                task = None
            tasks.put(task)
            if task is None:
                return

    threading.Thread(target=read, daemon=True).start()
    conn.send(("ready", os.getpid()))
    while (task := tasks.get()) is not None:
        fn, chunk = task
        try:
            reply = ("done", run_chunk(fn, chunk))
        except BaseException as exc:  # noqa: BLE001 - reported to the parent, which raises it
            reply = ("raised", f"{type(exc).__name__}: {exc}")
        try:
            conn.send(reply)
        except OSError:   # the sweep has gone
            return


def _fork_is_safe() -> bool:
    """Forking is safe on Linux while this process runs no other Python thread (a thread
    holding a lock at the fork would leave the child's copy locked forever). On macOS the
    system libraries are not fork-safe (Python spawns there by default), so workers spawn."""
    import sys
    import threading

    return sys.platform.startswith("linux") and threading.active_count() == 1


class _Worker:
    """One worker process and this process's end of its pipe, with the chunks it holds."""

    def __init__(self, context, siblings: list):
        parent_end, child_end = context.Pipe()
        # a forked child holds copies of this process's pipe ends (its own and its siblings'):
        # it closes them, or it would never see its pipe end when this process dies
        inherited = (*siblings, parent_end) if context.get_start_method() == "fork" else ()
        self.process = context.Process(target=_serve, args=(child_end, inherited), daemon=True)
        self.process.start()
        child_end.close()
        self.conn = parent_end
        self.ready = False
        self.chunks: deque = deque()   # sent, in the order the worker runs them

    def died(self) -> WorkerLost:
        self.process.join(timeout=1)
        return WorkerLost(f"a sweep worker (pid {self.process.pid}) died (exit code "
                          f"{self.process.exitcode}); the finished cases are in sweep.csv, "
                          "continue with --resume")


class ProcessExecutor:
    """``--jobs N``: this process and N - 1 worker processes share the cases.

    The workers start when the executor is made and each first reports that it is ready; only
    then do they get cases. The cases go out in chunks (about eight per process): each ready
    worker holds up to two chunks, taken from the front of the queue (the second is there when
    it finishes the first, so it never waits for this process to look up from a chunk of its
    own), while this process works through chunks from the end. A sweep that this process
    finishes before the workers are ready does not wait for them. Workers are forked while this
    process runs no other thread (they start at once, with everything imported and the deck
    loaded) and spawned otherwise: forking a threaded process can deadlock.

    Each worker talks over a pipe of its own and this process reads them itself, with no
    helper thread: a worker killed while it sends (SIGTERM to the sweep) leaves no thread
    waiting on half a message, so an interrupted sweep always exits. Results arrive in
    completion order (the output layer sorts by case).
    """

    def __init__(self, jobs: int):
        import multiprocessing

        self.jobs = jobs
        method = "fork" if _fork_is_safe() else "spawn"
        self.description = f"{jobs} processes (this one and {jobs - 1} {method}ed workers)"
        context = multiprocessing.get_context(method)
        self._workers: list[_Worker] = []
        for _ in range(max(jobs - 1, 1)):
            self._workers.append(_Worker(context, [w.conn for w in self._workers]))

    def _receive(self, worker: _Worker) -> list:
        """What a worker has sent: its ready report, or a finished chunk's records."""
        try:
            kind, payload = worker.conn.recv()
        except (EOFError, OSError):
            raise worker.died() from None
        if kind == "ready":
            worker.ready = True
            return []
        worker.chunks.popleft()
        if kind == "raised":
            raise RuntimeError(f"in a sweep worker: {payload}")
        return payload

    def _poll(self, timeout: float | None) -> list:
        """Records of the chunks finished within ``timeout`` (None: wait for the first)."""
        from multiprocessing.connection import wait

        waiting = {w.conn: w for w in self._workers if not w.ready or w.chunks}
        if not waiting:
            return []
        sentinels = {w.process.sentinel: w for w in waiting.values()}
        ready = wait([*waiting, *sentinels], timeout)
        out: list = []
        for conn in (c for c in ready if c in waiting):
            out += self._receive(waiting[conn])
        for worker in (sentinels[s] for s in ready if s in sentinels):
            # ended: what it sent before it ended was read above (a dead pipe reads as EOF)
            if worker.conn not in ready:
                raise worker.died()
        return out

    def map(self, fn: Callable, jobs: Iterable) -> Iterator:
        jobs = list(jobs)
        size = max(1, min(100, len(jobs) // (8 * self.jobs)))
        pending = deque(jobs[i:i + size] for i in range(0, len(jobs), size))
        while pending or any(w.chunks for w in self._workers):
            for worker in self._workers:
                while worker.ready and len(worker.chunks) < 2 and pending:
                    worker.chunks.append(pending.popleft())
                    try:
                        worker.conn.send((fn, worker.chunks[-1]))
                    except OSError:   # it ended since it last reported
                        raise worker.died() from None
            yield from self._poll(0)
            if pending:
                yield from run_chunk(fn, pending.pop())
            else:   # the queue is empty: wait for the chunks still out
                yield from self._poll(None)

    def close(self) -> None:
        """Tell ready workers to stop and wait for them; stop those still starting."""
        for worker in self._workers:
            if worker.ready and not worker.chunks:
                try:
                    worker.conn.send(None)
                except OSError:
                    pass
        for worker in self._workers:
            if worker.ready and not worker.chunks:
                worker.process.join(timeout=10)
        self.abort()

    def abort(self) -> None:
        """Stop at once: terminate the workers (what they were running is dropped)."""
        for worker in self._workers:
            if worker.process.is_alive():
                worker.process.terminate()
        for worker in self._workers:
            worker.process.join(timeout=5)
            if worker.process.is_alive():
                worker.process.kill()
                worker.process.join(timeout=5)
            worker.conn.close()


class DaskExecutor:
    """Cases on an existing Dask distributed cluster (``--scheduler ADDRESS``).

    The workers must have camtrain installed; the deck travels inside each job, so the workers
    need no access to the deck file (a lift-table *file* must be readable by them, though).
    """

    def __init__(self, address):
        try:
            from dask.distributed import Client
        except ImportError:
            raise CamtrainError("--scheduler needs Dask: pip install 'camtrain[dask]'") from None
        try:
            self._client = Client(address, set_as_default=False)
        except (OSError, TimeoutError, ValueError) as exc:
            raise CamtrainError(f"--scheduler: cannot connect to {address!r}: {exc}") from None
        self.description = f"Dask cluster at {self._client.scheduler.address}"

    def map(self, fn: Callable, jobs: Iterable) -> Iterator:
        # results in submission order: the client is not the process default (set_as_default
        # is False), so helpers that look up a default client, like as_completed, cannot be used
        futures = self._client.map(fn, list(jobs), pure=False)
        try:
            for fut in futures:
                yield fut.result()
        finally:
            self._client.cancel(futures)

    def close(self) -> None:
        self._client.close()


def default_jobs() -> int:
    """CPUs this process may use (respects affinity masks and container limits where visible)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not on Linux
        return max(1, os.cpu_count() or 1)


def make_executor(jobs: int | None = None, scheduler=None):
    """Dask if a scheduler is given, else serial for one job, else a local process pool."""
    if scheduler is not None:
        return DaskExecutor(scheduler)
    jobs = default_jobs() if jobs is None else jobs
    if jobs < 1:
        raise CamtrainError(f"--jobs: {jobs} is not a number of worker processes (>= 1)")
    return SerialExecutor() if jobs == 1 else ProcessExecutor(jobs)
