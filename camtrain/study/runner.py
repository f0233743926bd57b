"""Run a sweep end to end: prepare the cases, run them on an executor, keep sweep.csv current,
then write the trend table and the plots.

sweep.csv is rewritten atomically as cases finish (at most about once a second) and once more on
the way out, also after Ctrl-C, so an interrupted sweep keeps what it finished and ``resume``
runs only the rest.
"""
from __future__ import annotations

import json
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from camtrain.errors import InputError, Problem
from camtrain.report.tables import atomic_write
from camtrain.study import sweep_output as so
from camtrain.study.assign import apply_fixed, parse_assignment
from camtrain.study.executors import Job, make_executor, run_case
from camtrain.study.sweep import Case, Parameter, build_parameters, cases


@dataclass
class Sweep:
    """A prepared sweep: the datum deck (raw, with --set applied), its parameters and cases."""

    raw: dict
    name: str
    base_dir: str
    sha256: str
    params: list[Parameter]
    fixed: list[Parameter]
    cases: list[Case]
    zipped: bool = False
    units: str = "deck"     # of sweep.csv, the curves and trends: "deck" or "si"
    #: {path: sha256} of every other file the deck reads (lift table, included decks)
    inputs: dict = field(default_factory=dict)


@dataclass
class Outcome:
    """What a sweep produced: all records (by case index), files written and status counts."""

    records: list[dict]
    written: list[Path] = field(default_factory=list)
    reused: int = 0
    trends: list = field(default_factory=list)
    #: how the cases ran (:class:`camtrain.study.batch.Route`; None when none had to run)
    route: object = None
    #: what the sweep wants its user to know (e.g. why finished cases were run again)
    notes: list[str] = field(default_factory=list)

    def to_dataframe(self):
        """One row per case (indexed by case number): the swept values, the status and its
        message, and every metric as a column ``name[unit]`` in the sweep's units. Needs
        pandas (``pip install 'camtrain[pandas]'``)."""
        from camtrain.result import _pandas

        pd = _pandas("Outcome.to_dataframe")
        rows = []
        for rec in self.records:
            row = dict(rec["values"])
            row["status"] = rec["status"]
            row["message"] = rec.get("message", "")
            for name, (value, unit) in (rec.get("metrics") or {}).items():
                row[f"{name}[{unit}]"] = value
            rows.append(row)
        index = pd.Index([rec["index"] for rec in self.records], name="case")
        return pd.DataFrame(rows, index=index)

    def count(self, status: str) -> int:
        return sum(r["status"] == status for r in self.records)


def prepare(deck: str | Path, specs: list[tuple[str, str, str]], sets: list[str] = (),
            zipped: bool = False, units: str = "deck") -> Sweep:
    """Read the deck, resolve and check every parameter, generate the cases.

    ``specs`` = [(name, 'values' | 'range' | 'relative', text)]; ``sets`` = ['path=value', ...].
    Bad arguments raise InputError naming the option and value; the datum deck (with the
    ``sets`` applied) must itself be valid.
    """
    datum = prepare_datum(deck, sets, units)
    params = build_parameters(datum.raw, list(specs))
    return Sweep(datum.raw, datum.name, datum.base_dir, datum.sha256, params, datum.fixed,
                 cases(params, zipped), zipped, units, datum.inputs)


def prepare_datum(deck: str | Path, sets: list[str] = (), units: str = "deck") -> Sweep:
    """The datum deck of a sweep, read with the ``sets`` applied and validated; no cases yet
    (the studies built on sweeps draw their own)."""
    from camtrain.deck.inputs import input_digests
    from camtrain.deck.load import load_deck, parse_toml, validate

    loaded = load_deck(str(deck))
    raw = parse_toml(loaded.text, loaded.path)
    base_dir = str(Path(deck).resolve().parent) if str(deck) != "-" else str(Path.cwd())
    fixed = [parse_assignment(raw, s) for s in sets]
    raw = apply_fixed(raw, fixed)
    model = validate(raw, loaded.path, Path(base_dir)) if fixed else loaded.model
    return Sweep(raw, loaded.path, base_dir, loaded.sha256, [], fixed, [], False, units,
                 input_digests(model))


def kept_indices(n: int, most: int) -> set[int]:
    """Evenly spaced cases whose per-angle curves are kept for the overlays."""
    if most <= 0 or n == 0:
        return set()
    if n <= most:
        return set(range(n))
    return {round(i * (n - 1) / (most - 1)) for i in range(most)} if most > 1 else {0}


def _manifest(sweep: Sweep) -> dict:
    from camtrain import __version__

    return {"camtrain_version": __version__, "deck": sweep.name, "deck_sha256": sweep.sha256,
            "inputs_sha256": sweep.inputs, "zip": sweep.zipped, "cases": len(sweep.cases),
            "units": sweep.units,
            "set": {p.path: p.values[0] for p in sweep.fixed},
            "parameters": [{"name": p.name, "path": p.path, "unit": p.unit, "datum": p.datum,
                            "values": list(p.values)} for p in sweep.params]}


def _check_resume(out_dir: Path, sweep: Sweep) -> list[str]:
    """Refuse a resume whose sweep is not the one in ``out_dir``; return the files the deck reads
    whose content changed since (every finished case is then stale)."""
    path = out_dir / "sweep.json"
    if not path.is_file():
        return []
    try:
        old = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return []
    if old.get("units", "si") != sweep.units:
        raise InputError(Problem("--units", f"the sweep in {out_dir} wrote its tables in "
                                 f"{old.get('units', 'si')} units", sweep.units,
                                 f"--units {old.get('units', 'si')}",
                                 "resume with the same --units, or use another --out"))
    if old.get("deck_sha256") != sweep.sha256:
        raise InputError(Problem("--resume", f"the deck {sweep.name} changed since the sweep in "
                                 f"{out_dir} started", None, "the same deck",
                                 "start a new sweep (without --resume) or use another --out"))
    # a finished case is found again by its swept values alone: everything else that defines the
    # sweep (the --set values, which parameters, their datum, --zip) must be what it ran with
    def definition(manifest: dict) -> dict:
        return {"set": manifest.get("set"), "zip": manifest.get("zip"),
                "parameters": [{k: p.get(k) for k in ("name", "path", "unit", "datum")}
                               for p in manifest.get("parameters", [])]}

    new = definition(json.loads(json.dumps(_manifest(sweep))))
    was = definition(old)
    what = {"set": "the --set values", "parameters": "the swept parameters", "zip": "--zip"}
    changed = [what[k] for k in new if new[k] != was[k]]
    if changed:
        raise InputError(Problem(
            "--resume", f"the sweep definition changed since the sweep in {out_dir} started: "
            + ", ".join(changed) + f" (was {was}, now {new})", None,
            "the same --param/--set/--zip options",
            "its finished cases were computed with the old definition; start a new sweep "
            "(without --resume) or use another --out"))
    was_read = old.get("inputs_sha256")
    if was_read is None:    # a sweep from before camtrain recorded them: assume they changed
        return sorted(sweep.inputs)
    return sorted(set(sweep.inputs) ^ set(was_read)
                  | {p for p in sweep.inputs if was_read.get(p) != sweep.inputs[p]})


def run_sweep(sweep: Sweep, out_dir: str | Path, *, force: bool = False, resume: bool = False,
              **options) -> Outcome:
    """Run every case not already finished in ``out_dir`` and write all outputs (options: see
    :func:`_run_sweep`). One process at a time writes ``out_dir`` (a lock; a second is refused).
    A directory that holds a sweep already is continued with ``resume`` (its finished cases
    are kept unless a file the deck reads changed) or replaced with ``force``; otherwise
    refused."""
    from camtrain.output_lock import output_lock

    with output_lock(Path(out_dir)):
        if not (resume or force) and (Path(out_dir) / "sweep.json").exists():
            raise InputError(Problem("--out", "holds a sweep already", str(out_dir),
                                     "a new directory",
                                     "Give --resume to continue it, --force to replace it, or "
                                     "another --out"))
        return _run_sweep(sweep, Path(out_dir), resume=resume, **options)


def _run_sweep(sweep: Sweep, out_dir: Path, *, jobs: int | None = 1, scheduler=None,
               executor=None, resume: bool = False, plots: bool = True, overlay_max: int = 20,
               progress: Callable[[dict, int, int], None] | None = None,
               write_decks: bool = False) -> Outcome:
    """Run every case not already finished in ``out_dir`` and write all outputs;
    ``write_decks`` also writes each case's deck as ``decks/case_NNNNN.toml``.

    ``progress(record, done, total)`` is called as each case finishes (also for reused ones).
    """
    out_dir = Path(out_dir)
    keep = kept_indices(len(sweep.cases), overlay_max)
    decks = write_case_decks(out_dir, sweep) if write_decks else []
    outcome = run_cases(sweep, out_dir, jobs=jobs, scheduler=scheduler, executor=executor,
                        resume=resume, keep=keep, progress=progress)
    outcome.written += decks
    records = outcome.records
    outcome.written += _write_trends(out_dir, sweep, outcome)
    from camtrain.study.flame_table import write_flame

    outcome.written += write_flame(out_dir, sweep.params, records, plots=plots, title=sweep.name)
    from camtrain.study.friction_map import write_sweep_map

    outcome.written += write_sweep_map(out_dir, sweep.params, records, plots=plots,
                                       title=sweep.name)
    if plots:
        outcome.written += so.metric_plots(out_dir, sweep.params, records, outcome.trends,
                                           title=Path(sweep.name).name)
        kept = [r for r in records if r["index"] in keep]
        outcome.written += so.overlay_plots(out_dir, sweep.params, kept,
                                            title=Path(sweep.name).name)
    return outcome


def run_cases(sweep: Sweep, out_dir: Path, *, jobs: int | None = 1, scheduler=None,
              executor=None, resume: bool = False, keep: set[int] = frozenset(),
              progress: Callable[[dict, int, int], None] | None = None) -> Outcome:
    """Run every case not already finished in ``out_dir`` (batch route where it applies, on
    ``executor`` or one made from ``jobs`` / ``scheduler``) and keep sweep.csv and sweep.json
    current; the per-angle curves of the cases in ``keep`` go to ``curves/``. The studies
    built on sweeps (trends and plots here, sensitivity) read the records it returns."""
    out_dir.mkdir(parents=True, exist_ok=True)
    csv_path = out_dir / "sweep.csv"
    done: dict[int, dict] = {}
    notes: list[str] = []
    stale = _check_resume(out_dir, sweep) if resume else []
    if resume and not stale:
        done = so.read_finished(csv_path, sweep.params, sweep.cases, sweep.units)
    else:
        if stale:
            notes.append("every case runs again: a file the deck reads changed since the "
                         "finished cases ran (" + ", ".join(stale) + ")")
        for stale in (out_dir / "curves").glob("case_*.csv"):
            stale.unlink()
    reused = len(done)
    todo = [c for c in sweep.cases if c.index not in done]
    from camtrain.study.batch import route as batch_route
    from camtrain.study.case_model import datum_key

    key = datum_key(sweep.raw, sweep.name, sweep.base_dir)
    route = batch_route(sweep.raw, sweep.params, sweep.name, sweep.base_dir, key) if todo \
        else None
    manifest = _manifest(sweep) | ({"route": route.as_dict()} if route else {})
    atomic_write(out_dir / "sweep.json", json.dumps(manifest, indent=2) + "\n")
    total = len(sweep.cases)
    if progress:
        for rec in sorted(done.values(), key=lambda r: r["index"]):
            progress(rec, reused, total)
    own = executor is None and todo
    if own:
        jobs = min(jobs, len(todo)) if jobs else jobs
        if route.batch and scheduler is None and (jobs is None or jobs > 1):
            # one case here first: workers forked next start with every module imported and
            # the lift curve and contact model cached, as this process has them
            from camtrain.study.batch import BatchJob, run_batch

            run_batch(BatchJob(sweep.raw, tuple(sweep.params), (todo[0],), sweep.name,
                               sweep.base_dir, frozenset(), key))
        executor = make_executor(jobs, scheduler)
    work, fn = _work(sweep, todo, keep, key, route, getattr(executor, "jobs", None))
    last, cost = time.monotonic(), 0.0
    try:
        for rec in _records(executor, fn, work, route):
            rec = so.in_units(rec, sweep.units)
            so.write_curves(out_dir, rec)
            rec["curves"] = None  # on disk now; keeps memory flat for long sweeps
            done[rec["index"]] = rec
            if progress:
                progress(rec, len(done), total)
            # at most once a second, and never more than a tenth of the time: the table
            # grows with the sweep, so a fast sweep would otherwise spend its time here
            if time.monotonic() - last > max(1.0, 10.0 * cost):
                tick = time.monotonic()
                so.write_csv(csv_path, sweep.params, list(done.values()), sweep.units)
                last = time.monotonic()
                cost = last - tick
    except BaseException:
        # interrupted (Ctrl-C, SIGTERM) or failed: the workers stop now, not after their chunks
        if own:
            getattr(executor, "abort", executor.close)()
            own = False
        raise
    finally:
        so.write_csv(csv_path, sweep.params, list(done.values()), sweep.units)
        if own:
            executor.close()
    records = sorted(done.values(), key=lambda r: r["index"])
    return Outcome(records, [csv_path, out_dir / "sweep.json"], reused, route=route, notes=notes)


def _records(executor, fn, work: list, route):
    """Case records as the executor returns them (a batch chunk gives a list of records)."""
    if not work:
        return
    for out in executor.map(fn, work):
        if route.batch:
            yield from out
        else:
            yield out


def _work(sweep: Sweep, todo: list[Case], keep: set[int], key: str, route, jobs: int | None):
    """What the executor maps: one Job per case, or chunks of cases as BatchJobs (about eight
    per process, so the workers share them out as they start; ``jobs`` None: a cluster of
    unknown size; each chunk runs in sub-batches sized for memory)."""
    if route is None or not route.batch:
        return [Job(sweep.raw, tuple(sweep.params), c, sweep.name, sweep.base_dir,
                    c.index in keep, key) for c in todo], run_case
    from camtrain.study.batch import BatchJob, run_batch

    # a cluster (jobs unknown) gets as many chunks as four eight-process machines would
    procs = 32 if jobs is None else max(1, jobs)
    size = max(1, min(_BATCH_CHUNK, -(-len(todo) // (8 * procs)))) if procs > 1 else _BATCH_CHUNK
    chunks = [tuple(todo[i:i + size]) for i in range(0, len(todo), size)]
    return [BatchJob(sweep.raw, tuple(sweep.params), chunk, sweep.name, sweep.base_dir,
                     frozenset(c.index for c in chunk if c.index in keep), key)
            for chunk in chunks], run_batch


#: cases per batch chunk when one process runs them (sweep.csv is rewritten between chunks)
_BATCH_CHUNK = 250


def write_case_decks(out_dir: Path, sweep: Sweep) -> list[Path]:
    """Each case's deck as TOML (the datum deck with the case's values written in, deck
    units), so any case can be run, checked or handed on by itself."""
    import tomli_w

    from camtrain.study.sweep import case_raw

    (out_dir / "decks").mkdir(parents=True, exist_ok=True)
    written = []
    for case in sweep.cases:
        values = ", ".join(f"{p.name} = {case.as_dict()[p.name]:g} {p.unit}"
                           for p in sweep.params)
        head = f"# case {case.index} of the sweep of {sweep.name}: {values}\n\n"
        path = out_dir / "decks" / f"case_{case.index:05d}.toml"
        atomic_write(path, head + tomli_w.dumps(case_raw(sweep.raw, sweep.params, case)))
        written.append(path)
    return written


def _write_trends(out_dir: Path, sweep: Sweep, outcome: Outcome) -> list[Path]:
    import csv
    import io

    from camtrain.study.trends import trend_table, trends_markdown

    names = so.metric_order(outcome.records)
    units = so.metric_units(outcome.records)
    pnames = [p.name for p in sweep.params]
    outcome.trends = trend_table(outcome.records, pnames, names, zipped=sweep.zipped)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["metric", "unit", "parameter", "trend", "detail", "cases"])
    for t in outcome.trends:
        w.writerow([t.metric, units.get(t.metric, ""), t.parameter, t.trend, t.detail, t.points])
    atomic_write(out_dir / "trends.csv", buf.getvalue())
    counts = ", ".join(f"{s} {outcome.count(s)}" for s in ("ok", "lost_contact", "failed", "error")
                       if outcome.count(s))
    head = (f"# Trends: {sweep.name}\n\n{len(outcome.records)} cases ({counts}). "
            + "; ".join(f"{p.name} = {p.path} [{p.unit}], datum {p.datum:g}" if p.datum is not None
                        else f"{p.name} = {p.path} [{p.unit}]" for p in sweep.params) + ".\n\n")
    atomic_write(out_dir / "trends.md", head + trends_markdown(outcome.trends, pnames, names,
                                                                  units))
    return [out_dir / "trends.csv", out_dir / "trends.md"]
