"""Sweep cases as one vectorised batch where the physics allows, case by case elsewhere.

:func:`route` decides once per sweep: a batch runs when every swept field is a scalar the chain
uses elementwise (speed, base radius, cam width, spring rate and preload, valve-side mass,
lubricant, boundary coefficient, materials) and the deck's chain has no branch that depends on
the case: a clockwise flat-faced follower (its load has no friction arm, so no friction/load
iteration), the rigid-train loads, the steady film and a shear friction law, and no effect
beyond kinematics, loads, Hertz, film, friction and power. Anything else (mechanism type, lift
law, tables, transient films, dynamics, camshaft and bearing effects, pivot rules) runs case by
case, and the route says why.

:func:`run_batch` runs one chunk of cases: each case's model is still the validated datum with
its swept fields replaced (:mod:`camtrain.study.case_model`); their scalars become (cases, 1)
columns and the chain runs on (cases, angles) arrays (:mod:`camtrain.study.batch_chain`) in
sub-batches of at most :data:`BATCH_POINTS` points, which keeps the peak memory near a single
run's. A case whose model is invalid, whose geometry fails a check, that loses contact or whose
per-angle curves are kept for the overlays runs alone through :func:`run_case`, so its status,
message and curves are exactly a single run's.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from camtrain.study.sweep import Case, Parameter

#: swept fields the chain uses elementwise (deck paths)
BATCH_PATHS = frozenset({
    "speed.camshaft", "speed.engine", "cam.base_radius", "cam.width", "spring.rate",
    "spring.preload_compression", "masses.valve_side", "lubricant.viscosity",
    "lubricant.pressure_viscosity", "lubricant.roughness", "lubricant.temperature",
    "tribology.boundary_friction", "materials.cam_modulus", "materials.cam_poisson",
    "materials.follower_modulus", "materials.follower_poisson", "mechanism.follower_radius"})
#: fields of the contact model itself (the Greenwood-Tripp law reads them unselected)
_CONTACT = ("cam.width", "lubricant.", "tribology.", "materials.")
#: the chain a batch computes, in plan order
CHAIN = ("kinematics", "loads", "hertz", "film", "friction", "power")
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
    from camtrain.study.case_model import changes_only_its_field

    kind = raw.get("kind", "valve_train")
    if kind != "valve_train":
        article = "an" if kind[:1] in "aeiou" else "a"
        return Route(False, f"{article} {kind} deck runs each case through its own plan")
    for p in params:
        if p.path not in BATCH_PATHS:
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
    chosen = tuple(e for e in plan.chosen if e != "guides")
    if chosen != CHAIN:
        other = [e for e in chosen if e not in CHAIN] or [e for e in CHAIN if e not in chosen]
        return Route(False, "the plan differs from the batched chain (kinematics, loads, hertz, "
                     f"film, friction, power) in {', '.join(other)}")
    mech = datum.mechanism
    if mech.type not in ("flat", "domed"):
        return Route(False, f"a {mech.type} follower: its kinematics are solved case by case "
                     "(the batch covers translating flat-faced and domed followers)")
    if mech.roller is not None and mech.roller.crown_radius is not None:
        return Route(False, "a crowned roller: its elliptical contact is solved case by case")
    from camtrain.mechanisms.base import CLOCKWISE, normalise_rotation

    if normalise_rotation(mech.rotation) != CLOCKWISE:
        return Route(False, "an anticlockwise cam (the batch covers clockwise rotation)")
    trib = datum.tribology
    if trib.film_model != "steady":
        return Route(False, f"the {trib.film_model} film is marched over the cycle case by case")
    if trib.friction_model == "greenwood_tripp" and any(
            p.path.startswith(_CONTACT) for p in params):
        return Route(False, "the greenwood_tripp friction law with a swept contact parameter")
    swept = ", ".join(p.path for p in params)
    verb = "enters" if len(params) == 1 else "enter"
    load = ("one pass" if mech.type == "flat" else
            "the friction/load iteration converging case by case")
    return Route(True, f"{swept} {verb} the chain elementwise ({mech.type} follower, rigid-train "
                 f"loads by {load}, steady film, {trib.friction_model} friction"
                 + (", guides" if "guides" in plan.chosen else "")
                 + "): one (cases, angles) array per quantity")


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


def _curves(degrees: list[float], valve, out: dict, row: int) -> dict:
    """The overlay curves of one case (:data:`camtrain.study.executors.OVERLAY_COLUMNS`, with
    the units of the result's columns), from its row of the batch."""
    return {"cam_angle": ("deg", degrees), "film_min": ("m", out["film"].min[row].tolist()),
            "load": ("N", out["load"][row].tolist()),
            "hertz_pmax": ("Pa", out["hertz"].pmax[row].tolist()),
            "lift": ("m", valve.lift.tolist())}


def _batched(job: BatchJob, models: list, cases: list[Case]) -> tuple[list[dict], list[Case]]:
    from camtrain.effects.kinematics import _cached_curve, lift_columns
    from camtrain.formulas._util import trusted_inputs
    from camtrain.metric_rows import per_case
    from camtrain.result import Result
    from camtrain.study import batch_chain as bc
    from camtrain.study.case_model import datum_model

    datum = datum_model(job.raw, job.name, job.base_dir, job.datum)
    points = datum.solver.angle_points
    lift = Result()
    lift_columns(datum, lift)
    head = [(n, m.value, m.unit) for n, m in lift.metrics.items()]
    valve = _cached_curve(datum.lift, points)
    size = max(1, BATCH_POINTS // points)
    degrees = [math.degrees(v) for v in valve.theta]
    records, rest = [], []
    with trusted_inputs():
        for start in range(0, len(cases), size):
            part, part_models = cases[start:start + size], models[start:start + size]
            n = len(part)
            scal = bc.columns(part_models)
            out = bc.run_chain(datum, valve, scal, n)
            ok = bc.geometry_ok(datum, out["kin"])
            converged = out["converged"]
            for r, (case, good, metrics) in enumerate(zip(part, ok,
                                                          per_case(out["metrics"], n),
                                                          strict=True)):
                m = {name: (value, unit) for name, value, unit in head + metrics}
                load_min = m.get("load_min")
                if not (good and converged[r]) or (load_min is not None and load_min[0] <= 0.0):
                    rest.append(case)   # a geometry error, no convergence or lost contact
                    continue
                curves = _curves(degrees, valve, out, r) if case.index in job.keep else None
                records.append({"index": case.index, "values": case.as_dict(), "status": "ok",
                                "message": "", "metrics": m, "curves": curves})
    return records, rest
