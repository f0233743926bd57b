"""Sweep cases as one vectorised batch where the physics allows, case by case elsewhere.

:func:`route` decides once per sweep: a batch runs when every swept field is a scalar the
valve-train chain uses elementwise (:data:`camtrain.assemble.cases.CASE_PATHS`: speed, base
radius, cam width, spring rate and preload, valve-side mass, lubricant, boundary coefficient,
materials) and every effect the datum deck plans runs over a case axis: its module defines
``run_cases`` and does not refuse the deck (:func:`camtrain.runner.cases_refusal`; e.g. the
kinematics covers clockwise translating flat-faced and domed followers, the film the steady
film). Anything else runs case by case, and the route says why.

:func:`run_batch` runs one chunk of cases: each case's model is still the validated datum with
its swept fields replaced (:mod:`camtrain.study.case_model`); they are assembled into per-case
columns (:func:`camtrain.assemble.cases.assemble_cases`) and the plan's effects run on
(cases, angles) arrays (:func:`camtrain.runner.run_cases`, the same effect modules a single run
calls) in sub-batches of at most :data:`BATCH_POINTS` points, which keeps the peak memory near
a single run's. A case whose model is invalid, that an effect sets aside (a geometry error, no
convergence, lost contact) or whose per-angle curves are kept for the overlays runs alone
through :func:`run_case`, so its status, message and curves are exactly a single run's.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from camtrain.study.sweep import Case, Parameter

#: (cases x angles) points per sub-batch: a few MB per array, so the peak memory of a sweep
#: stays near a single run's (the friction integral holds a few such arrays at once)
BATCH_POINTS = 16_384


@dataclass(frozen=True)
class Route:
    """How a sweep's cases run: ``batch`` (True: vectorised) and why."""

    batch: bool
    reason: str

    def as_dict(self) -> dict:
        return {"batch": self.batch, "reason": self.reason}

    def describe(self) -> str:
        return ("cases run as one vectorised batch: " if self.batch
                else "cases run one by one: ") + self.reason


def route(raw: dict, params: list[Parameter], name: str, base_dir: str, key: str = "") -> Route:
    """Whether the cases of this sweep can run as one batch, and why (or why not)."""
    from camtrain.assemble.cases import CASE_PATHS
    from camtrain.study.case_model import changes_only_its_field

    kind = raw.get("kind", "valve_train")
    if kind != "valve_train":
        article = "an" if kind[:1] in "aeiou" else "a"
        return Route(False, f"{article} {kind} deck runs each case through its own plan")
    for p in params:
        if p.path not in CASE_PATHS:
            return Route(False, f"{p.path} is not a scalar the chain uses elementwise (batched: "
                         "speed, cam base radius and width, spring rate and preload, valve-side "
                         "mass, lubricant, boundary friction, materials)")
        if not changes_only_its_field(raw, p):
            mech = raw.get("mechanism") if isinstance(raw.get("mechanism"), dict) else {}
            return Route(False, f"on a {mech.get('type', 'pivoted')} follower {p.path} moves "
                         "other fields with it (Ball's pivot rules), so each case is built and "
                         "validated on its own")
    try:
        from camtrain.scene import resolve
        from camtrain.study.case_model import datum_model

        datum = datum_model(raw, name, base_dir, key)
        plan = resolve(datum)
    except Exception:  # noqa: BLE001 - the cases report their own errors one by one
        return Route(False, "the datum deck does not plan (each case reports why)")
    from camtrain.runner import cases_refusal

    refused = cases_refusal(datum, plan, tuple(p.path for p in params))
    if refused:
        return Route(False, refused)
    swept = ", ".join(p.path for p in params)
    verb = "enters" if len(params) == 1 else "enter"
    return Route(True, f"{swept} {verb} the chain elementwise ({datum.mechanism.type} "
                 f"follower; {', '.join(plan.chosen)} run over a case axis): one "
                 "(cases, angles) array per quantity")


@dataclass(frozen=True)
class BatchJob:
    """A chunk of cases of one sweep, picklable (the datum deck travels with it)."""

    raw: dict
    params: tuple[Parameter, ...]
    cases: tuple[Case, ...]
    name: str
    base_dir: str
    keep: frozenset[int] = frozenset()
    datum: str = ""


def run_batch(job: BatchJob) -> list[dict]:
    """Records of every case of the chunk (as :func:`run_case` gives them), by case index."""
    from camtrain.study.case_model import case_model
    from camtrain.study.executors import Job, run_case

    alone: list[Case] = []
    models, cases = [], []
    for case in job.cases:
        try:
            models.append(case_model(job.raw, list(job.params), case, job.name, job.base_dir,
                                     job.datum))
        except Exception:  # noqa: BLE001 - invalid here: the case runs alone and says why
            alone.append(case)
            continue
        cases.append(case)
    records: list[dict] = []
    if cases:
        try:
            batched, rest = _batched(job, models, cases)
        except Exception:  # noqa: BLE001 - never lose a case to the batch: run it alone
            batched, rest = [], cases
        records += batched
        alone += rest
    records += [run_case(Job(job.raw, job.params, c, job.name, job.base_dir,
                             c.index in job.keep, job.datum)) for c in alone]
    return sorted(records, key=lambda r: r["index"])


#: the overlay curves a batch row gives: column -> (product, how to read its row, unit)
_OVERLAYS = {
    "film_min": ("ContactFilm", lambda p: p.main.min, "m"),
    "load": ("ContactLoad", lambda p: p.load, "N"),
    "hertz_pmax": ("ContactHertz", lambda p: p.main.pmax, "Pa"),
}


def _curves(degrees: list[float], valve, products: dict, row: int) -> dict:
    """The overlay curves of one case (:data:`camtrain.study.executors.OVERLAY_COLUMNS`, with
    the units of the result's columns, of the products the plan made), from its row of the
    batch."""
    curves = {"cam_angle": ("deg", degrees)}
    for name, (product, rows, unit) in _OVERLAYS.items():
        if product in products:
            curves[name] = (unit, rows(products[product])[row].tolist())
    curves["lift"] = ("m", valve.lift.tolist())
    return curves


def _batched(job: BatchJob, models: list, cases: list[Case]) -> tuple[list[dict], list[Case]]:
    from camtrain.assemble.cases import assemble_cases
    from camtrain.formulas._util import trusted_inputs
    from camtrain.metric_rows import per_case
    from camtrain.runner import run_cases
    from camtrain.scene import resolve
    from camtrain.study.case_model import datum_model
    from camtrain.tabulate.lift import lift_curve

    datum = datum_model(job.raw, job.name, job.base_dir, job.datum)
    plan = resolve(datum)
    points = datum.solver.angle_points
    valve = lift_curve(datum.lift, points)
    size = max(1, BATCH_POINTS // points)
    degrees = [math.degrees(v) for v in valve.theta]
    records, rest = [], []
    with trusted_inputs():   # every case's model was validated: no per-formula checks
        for start in range(0, len(cases), size):
            part = cases[start:start + size]
            batch = assemble_cases(datum, models[start:start + size])
            products = run_cases(datum, plan, batch)
            rows = per_case(batch.metrics, batch.n)
            for r, (case, usable, metrics) in enumerate(zip(part, batch.usable, rows,
                                                            strict=True)):
                if not usable:
                    rest.append(case)   # a geometry error, no convergence or lost contact
                    continue
                keep = case.index in job.keep
                curves = _curves(degrees, valve, products, r) if keep else None
                records.append({"index": case.index, "values": case.as_dict(), "status": "ok",
                                "message": "", "metrics": {n: (v, u) for n, v, u in metrics},
                                "curves": curves})
            # freed before the next sub-batch allocates its own: the allocator then reuses
            # the same memory (kept until rebound, the run measured ~10 % slower)
            del products, batch
    return records, rest
