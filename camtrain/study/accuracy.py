"""What accuracy costs in time: run one deck at a ladder of resolutions per knob (`camtrain accuracy`).

A rung is the deck's raw TOML dictionary with one resolution knob changed, validated and run like
any deck. For every key metric the study reports the value, its relative error against a reference,
the observed order of convergence and the wall time of the run. The reference is the Richardson
extrapolation of the three finest rungs when they converge monotonically at a plausible order, and
the finest rung otherwise. Everything returned is plain data (dicts, lists, floats, strings).

    >>> from camtrain.study.accuracy import study                                  # doctest: +SKIP
    >>> report = study("decks/harrison_flat.toml", knobs=["angle_points"], tolerance=1e-3)
    >>> report["knobs"]["angle_points"]["cheapest"]                                 # doctest: +SKIP

Nothing here is imported by `camtrain --help`; numpy comes in with the first run.
"""
from __future__ import annotations

import copy
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from camtrain.errors import CamtrainError, InputError, Problem

#: Metrics studied when a run produces them (scalar results a designer acts on).
KEY_METRICS = ("power_loss_mean", "film_min_at_max_lift", "hertz_max", "load_max",
               "bounce_speed", "cam_radius_at_max_lift", "equivalent_radius_at_max_lift",
               "shaft_deflection_max", "shaft_twist_max",
               "min_film", "max_eccentricity", "power_mean", "bearings_power_total",
               # engine decks: crank-train loads and crank bearings
               "big_end_max_load", "big_end_1_min_film_dynamic", "main_3_min_film_dynamic",
               "total_power_dynamic", "total_power_steady",
               # transient cam film
               "film_at_zero_entrainment_1", "film_max",
               # engine decks: piston assembly and FLAME
               "piston_power_total", "ring_1_min_film_flooded", "inter_ring_pressure_1_peak",
               "flame_total",
               # valve-train dynamics
               "separation_angle")

#: Per-bearing metrics of a camshaft (``bearing_<k>_<name>``) studied with the key metrics.
BEARING_METRICS = ("min_film", "max_eccentricity", "power_mean",
                   # the elastic camshaft: load from the shaft and its orders 1 and 4
                   "reaction_max", "reaction_order_1", "reaction_order_4")

#: Observed orders outside this range are treated as noise, not as asymptotic convergence.
PLAUSIBLE_ORDER = (0.5, 8.0)


@dataclass(frozen=True)
class Knob:
    """One resolution knob: the deck field it sets and its ladder, coarsest first.

    ``step`` maps a knob value to the discretisation size h (smaller is finer), so the ladder's
    refinement ratio and the observed order are in terms of h.
    """

    name: str
    path: str
    ladder: tuple[float, ...]
    step: Callable[[float], float]
    applies: Callable[[dict], bool]
    description: str
    integer: bool = False
    #: sets the knob's value in a raw deck when one path is not enough (default: set_path)
    setter: Callable[[dict, object], dict] | None = None
    #: time a rung's second run (caches warm): for knobs whose first run builds a table
    warm: bool = False
    #: a deck-specific ladder (None: ``ladder``), e.g. a cheaper one where a rung is costly
    ladder_for: Callable[[dict], tuple | None] | None = None

    def ladder_of(self, raw: dict) -> tuple:
        """The ladder this knob climbs on the deck ``raw``."""
        special = self.ladder_for(raw) if self.ladder_for is not None else None
        return tuple(special) if special else self.ladder


def _valve_train(raw: dict) -> bool:
    return raw.get("kind", "valve_train") == "valve_train"


def _engine(raw: dict) -> bool:
    return raw.get("kind") == "engine"


def _engine_orbits(raw: dict) -> bool:
    methods = raw.get("solver", {}).get("methods", ("dynamic",))
    return _engine(raw) and "dynamic" in methods


def _choice_step(choices: tuple[str, ...]) -> Callable[[str], float]:
    """A model choice has no step size: the rungs are ranked in ladder order (the last, the
    default, is the reference), so errors are differences from the default model."""
    return lambda v: float(len(choices) - choices.index(v))


def _lift_form(raw: dict) -> str:
    return str(raw.get("lift", {}).get("form", ""))


def _iterates(raw: dict) -> bool:
    # Only followers whose contact load depends on friction iterate (pivoted, pushrod, desmo).
    return raw.get("mechanism", {}).get("type") in ("finger", "rocker", "pushrod", "desmodromic")


def _elastic_camshaft(raw: dict) -> bool:
    return "flexibility" in raw.get("camshaft", {})


def _coupled_camshaft(raw: dict) -> bool:
    """Every lobe's elastic train on the elastic shaft (two-way coupling)."""
    return raw.get("camshaft", {}).get("flexibility", {}).get("coupling") == "two_way"


#: ladders of the coupled camshaft (one rung marches every lobe's train with the shaft; 8
#: stations per span cost twelve times the default, 2 steps per degree leave the contact
#: ringing unresolved)
COUPLED_LADDERS = {"shaft_stations": (0, 1, 2, 4), "steps_per_degree": (6.0, 12.0, 24.0, 48.0)}


def _coupled_ladder(name: str) -> Callable[[dict], tuple | None]:
    return lambda raw: COUPLED_LADDERS[name] if _coupled_camshaft(raw) else None


def _smoothing_spline(raw: dict) -> bool:
    table = raw.get("lift", {}).get("table", {})
    return _lift_form(raw) == "table" and table.get("derivative", "smoothing_spline") == \
        "smoothing_spline"


def _valve_train(raw: dict) -> bool:
    return raw.get("kind", "valve_train") == "valve_train"


def _bearing_section(raw: dict) -> tuple[str, str] | None:
    """(section path, field prefix) of the deck's journal-bearing film options, or None when
    the deck has no bearing with a film (no bearings, or the Petroff method only)."""
    if raw.get("kind") == "journal_bearing":
        where = ("solver", "")
    elif raw.get("camshaft", {}).get("bearings"):
        where = ("camshaft", "bearing_")
    elif raw.get("kind") == "engine":
        where = ("solver", "bearing_")
        if list(raw.get("solver", {}).get("methods", ("dynamic",))) == ["petroff"]:
            return None
    else:
        return None
    node = raw.get(where[0], {})
    return None if node.get("method", "mobility") == "petroff" else where


def _camshaft_orbits(raw: dict) -> bool:
    """The deck marches camshaft-bearing orbits (the mobility method)."""
    cs = raw.get("camshaft", {})
    return bool(cs.get("bearings")) and cs.get("method", "mobility") == "mobility"


def _set_film(raw: dict, **fields) -> dict:
    section, prefix = _bearing_section(raw)
    out = copy.deepcopy(raw)
    out.setdefault(section, {}).update({prefix + k: v for k, v in fields.items()})
    return out


def _mesh_rung(raw: dict, n_theta) -> dict:
    """The finite film at n_theta around and n_theta/12 along a half land (the default 72 x 6)."""
    return _set_film(raw, model="finite", n_theta=int(n_theta), n_z=max(2, round(n_theta / 12)))


#: rungs of the model knob: the short film, the finite film at the deck's mesh, and the finite
#: film at the finest mesh of the bearing_mesh ladder (the reference)
MODEL_RUNGS = ("short", "finite", "finite:288")


def _model_step(value) -> float:
    """Steps of the model rungs: short 1, finite at the deck's mesh 0.5, finite:N 1/N (unequal
    ratios, so no order is read across models)."""
    model, _, n_theta = str(value).partition(":")
    return 1.0 / int(n_theta) if n_theta else (1.0 if model == "short" else 0.5)


def _model_rung(raw: dict, value) -> dict:
    model, _, n_theta = str(value).partition(":")
    return _mesh_rung(raw, int(n_theta)) if n_theta else _set_film(raw, model=model)


def _film_model(raw: dict) -> str:
    return str(raw.get("tribology", {}).get("film_model", "steady"))


def _transient_film(raw: dict) -> bool:
    return _film_model(raw) in ("squeeze", "averaged_reynolds")


def _averaged_reynolds(raw: dict) -> bool:
    return _film_model(raw) == "averaged_reynolds"


def _dynamics(raw: dict) -> bool:
    return "dynamics" in raw


def _spring_chain(raw: dict) -> bool:
    return int(raw.get("dynamics", {}).get("spring_elements", 0)) > 0


def _adaptive(raw: dict) -> bool:
    return raw.get("dynamics", {}).get("integrator") in ("lsoda", "radau")


KNOBS: dict[str, Knob] = {k.name: k for k in (
    Knob("angle_points", "solver.angle_points", (180, 360, 720, 1440, 2880, 5760),
         lambda v: 1.0 / v, _valve_train,
         "cam angles over one revolution (angle step 360 deg / n)", integer=True),
    Knob("friction_tolerance", "solver.friction_tolerance",
         (1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8), lambda v: v, _iterates,
         "relative tolerance of the friction/load iteration"),
    Knob("table_smoothing", "lift.table.smoothing", (4.0, 2.0, 1.0, 0.5, 0.25),
         lambda v: v, _smoothing_spline,
         "smoothing level of the lift-table spline (relative to the data precision)"),
    Knob("shaft_stations", "camshaft.flexibility.nodes_per_span", (0, 1, 2, 4, 8),
         lambda v: 1.0 / (v + 1), _elastic_camshaft,
         "extra stations per span of the elastic camshaft (element length / (n + 1))",
         integer=True, ladder_for=_coupled_ladder("shaft_stations")),
    Knob("bearing_mesh", "solver.n_theta | camshaft.bearing_n_theta (n_z = n_theta / 12)",
         (36, 72, 144, 288), lambda v: 1.0 / v, lambda raw: _bearing_section(raw) is not None,
         "finite journal-bearing film mesh, model = finite (time: the orbit with the map "
         "cached; building a map costs ~200 Reynolds solutions once per b/d and mesh)",
         integer=True, setter=_mesh_rung, warm=True),
    Knob("bearing_model", "solver.model | camshaft.bearing_model | engine solver.bearing_model",
         MODEL_RUNGS,
         _model_step,
         lambda raw: _bearing_section(raw) is not None,
         "journal-bearing film model: short (Ocvirk) and finite at the deck's mesh against "
         "the finite film at 288 x 24", setter=_model_rung, warm=True),
    Knob("orbit_points", "camshaft.orbit_points", (90, 180, 360, 720, 1440), lambda v: 1.0 / v,
         _camshaft_orbits, "load-diagram angles per revolution the camshaft-bearing orbits are "
         "marched on (the run's grid resampled; a rung at or above the run's grid marches on "
         "it)", integer=True),
    Knob("crank_step", "solver.crank_step", (4.0, 2.0, 1.0, 0.5, 0.25), lambda v: v, _engine,
         "crank-angle step of the load diagrams and orbits [deg]"),
    Knob("period_tolerance", "solver.period_tolerance", (1e-3, 1e-4, 1e-5, 1e-6, 1e-7),
         lambda v: v, _engine_orbits,
         "cycle-to-cycle change of eps that counts as a periodic crank-bearing orbit"),
    Knob("step_tolerance", "solver.step_tolerance", (1e-5, 1e-6, 1e-7, 1e-8, 1e-9),
         lambda v: v, _engine_orbits, "error per time step of the crank-bearing orbit march"),
    Knob("pressure_interpolation", "solver.pressure_interpolation",
         ("linear", "periodic_cubic"), _choice_step(("linear", "periodic_cubic")), _engine,
         "cylinder pressure between table angles (model choice; reference: periodic_cubic)"),
    Knob("mobility", "solver.mobility", ("booker", "exact"),
         _choice_step(("booker", "exact")), _engine_orbits,
         "short-bearing mobility (model choice; reference: the exact pi-film inversion)"),
    # transient film (docs/transient_film.md)
    Knob("film_angle_step", "solver.film_angle_step", (2.0, 1.0, 0.5, 0.25, 0.125),
         lambda v: v, _transient_film, "cam-angle step of the transient film march [deg]"),
    Knob("film_nodes", "solver.film_nodes", (51, 101, 201, 401, 801, 1601),
         lambda v: 1.0 / (v - 1), _averaged_reynolds,
         "nodes across the contact zone of the averaged Reynolds film", integer=True),
    Knob("film_zone_width", "solver.film_zone_width", (2.0, 4.0, 8.0, 16.0),
         lambda v: 1.0 / v, _averaged_reynolds,
         "half width of the averaged Reynolds zone in Hertz half widths"),
    Knob("film_tolerance", "solver.film_tolerance", (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8),
         lambda v: v, _averaged_reynolds, "load-balance tolerance of the averaged Reynolds film"),
    Knob("piston_crank_step", "piston.solver.crank_step", (4.0, 2.0, 1.0, 0.5),
         lambda v: v, lambda raw: "piston" in raw,
         "crank-angle step of the inter-ring gas and ring-film marches [deg]"),
    Knob("ring_tolerance", "piston.solver.ring_tolerance", (1e-2, 1e-3, 1e-4, 1e-5, 1e-6),
         lambda v: v, lambda raw: "piston" in raw,
         "cyclic tolerance of the ring-film march"),
    Knob("gas_tolerance", "piston.solver.gas_tolerance", (1e-3, 1e-4, 1e-5, 1e-6, 1e-7),
         lambda v: v, lambda raw: "piston" in raw,
         "iteration and cyclic tolerance of the inter-ring gas march"),
    Knob("steps_per_degree", "dynamics.steps_per_degree", (2.0, 4.0, 8.0, 16.0, 32.0, 64.0),
         lambda v: 1.0 / v, lambda raw: _dynamics(raw) and not _adaptive(raw),
         "time steps per degree of cam of the valve-train dynamics",
         ladder_for=_coupled_ladder("steps_per_degree")),
    Knob("spring_elements", "dynamics.spring_elements", (4, 8, 16, 32), lambda v: 1.0 / v,
         _spring_chain, "elements of the valve-spring chain (surge)", integer=True),
    Knob("dynamics_rtol", "dynamics.rtol", (1e-5, 1e-6, 1e-7, 1e-8, 1e-9), lambda v: v,
         _adaptive, "relative tolerance of the adaptive dynamics integrator"),
)}


# --------------------------------------------------------------------------- numerics

def observed_order(f1: float, f2: float, f3: float, ratio: float) -> float | None:
    """Order p of f(h) = f* + C h^p from three values at h, h/ratio, h/ratio^2.

    None when the differences are zero or change sign (no asymptotic convergence to read).
    """
    d1, d2 = f1 - f2, f2 - f3
    if d1 == 0.0 or d2 == 0.0 or (d1 > 0) != (d2 > 0) or ratio <= 1.0:
        return None
    return math.log(abs(d1 / d2)) / math.log(ratio)


def richardson(f2: float, f3: float, ratio: float, order: float) -> float:
    """Extrapolate the two finest values f2 (h) and f3 (h/ratio) to h -> 0 at the given order."""
    return f3 + (f3 - f2) / (ratio ** order - 1.0)


def relative_error(value: float, reference: float) -> float:
    """|value - reference| / |reference|; absolute when the reference is exactly zero."""
    if not (math.isfinite(value) and math.isfinite(reference)):
        return math.inf
    scale = abs(reference)
    return abs(value - reference) / scale if scale > 0.0 else abs(value - reference)


def analyse(values: Sequence[float | None], steps: Sequence[float]) -> dict:
    """Error, order and reference for one metric over a ladder (values None where a rung failed).

    Returns ``{"reference", "reference_kind", "order", "errors", "orders"}``: ``orders[i]`` is the
    order observed from rungs i-2, i-1, i (None where it cannot be read); ``order`` is the one from
    the three finest successful consecutive rungs.
    """
    n = len(values)
    orders: list[float | None] = [None] * n
    for i in range(2, n):
        triple = values[i - 2:i + 1]
        if any(v is None for v in triple):
            continue
        r1, r2 = steps[i - 2] / steps[i - 1], steps[i - 1] / steps[i]
        if not math.isclose(r1, r2, rel_tol=1e-9):
            continue  # Richardson needs a constant refinement ratio
        orders[i] = observed_order(*triple, r2)
    ok = [i for i, v in enumerate(values) if v is not None]
    if not ok:
        return {"reference": None, "reference_kind": "none", "order": None,
                "errors": [None] * n, "orders": orders}
    finest = ok[-1]
    reference, kind, order = values[finest], "finest", orders[finest]
    lo, hi = PLAUSIBLE_ORDER
    if order is not None and lo <= order <= hi:
        ratio = steps[finest - 1] / steps[finest]
        reference = richardson(values[finest - 1], values[finest], ratio, order)
        kind = "richardson"
    errors = [None if v is None else relative_error(v, reference) for v in values]
    return {"reference": reference, "reference_kind": kind, "order": order, "errors": errors,
            "orders": orders}


def cheapest(rungs: Sequence[dict], errors: Sequence[float | None], tolerance: float) -> int | None:
    """Index of the coarsest rung from which every finer rung stays within ``tolerance``.

    Cost rises along a ladder, so the coarsest such rung is the cheapest; demanding that all finer
    rungs also meet the tolerance keeps a lucky coarse rung (an error crossing zero) from being
    chosen. Failed rungs (error None) break the chain.
    """
    best = None
    for i in range(len(rungs) - 1, -1, -1):
        e = errors[i]
        if e is None or not e <= tolerance:
            break
        best = i
    return best


# --------------------------------------------------------------------------- running

def set_path(raw: dict, path: str, value) -> dict:
    """Deep copy of ``raw`` with the dotted ``path`` set to ``value`` (tables created as needed)."""
    out = copy.deepcopy(raw)
    node = out
    *parents, leaf = path.split(".")
    for key in parents:
        node = node.setdefault(key, {})
    node[leaf] = value
    return out


def parse_tolerance(text: str) -> float:
    """'0.1%' -> 1e-3, '1e-3' -> 1e-3. Raises InputError naming --tolerance."""
    s = str(text).strip()
    try:
        value = float(s[:-1]) / 100.0 if s.endswith("%") else float(s)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and 0.0 < value < 1.0):
        raise InputError(Problem("--tolerance", "is not a relative tolerance", text,
                                 "a number in (0, 1) or a percentage such as 0.1%"))
    return value


def relevant_knobs(raw: dict) -> list[str]:
    """Knobs that change something for this deck (e.g. no friction iteration on a flat tappet)."""
    return [name for name, knob in KNOBS.items() if knob.applies(raw)]


def check_knobs(raw: dict, names: Sequence[str] | None) -> list[str]:
    """Validate requested knob names against the deck; default: every relevant knob."""
    if not names:
        return relevant_knobs(raw)
    out = []
    for name in names:
        if name not in KNOBS:
            raise InputError(Problem("--knob", "is not a resolution knob", name,
                                     "one of " + ", ".join(KNOBS)))
        if not KNOBS[name].applies(raw):
            raise InputError(Problem("--knob", "does not apply to this deck", name,
                                     "one of " + (", ".join(relevant_knobs(raw)) or "none"),
                                     f"it sets the {KNOBS[name].description}, "
                                     "which this deck does not use"))
        if name not in out:
            out.append(name)
    return out


def _run_rung(raw: dict, base_dir, repeat: int) -> dict:
    """Validate and run one rung; its metrics, best-of-``repeat`` wall time, or its error."""
    from camtrain import api
    from camtrain.deck.load import validate

    try:
        model = validate(raw, base_dir=base_dir)
        wall = math.inf
        for _ in range(max(1, repeat)):
            start = time.perf_counter()
            result = api.run(model)
            wall = min(wall, time.perf_counter() - start)
    except CamtrainError as exc:
        return {"status": "error", "message": str(exc), "exit_code": exc.exit_code,
                "wall_time": None, "metrics": {}}
    metrics = {k: {"value": m.value, "unit": m.unit} for k, m in result.metrics.items()}
    return {"status": "ok", "message": "", "exit_code": 0, "wall_time": wall, "metrics": metrics}


def study_knob(raw: dict, name: str, tolerance: float, *, base_dir=None, repeat: int = 1,
               ladder: Sequence[float] | None = None,
               metrics: Sequence[str] = KEY_METRICS) -> dict:
    """Run the ladder of one knob and analyse every key metric it produced."""
    knob = KNOBS[name]
    values = tuple(ladder or knob.ladder_of(raw))
    values = tuple(int(v) for v in values) if knob.integer else values
    setter = knob.setter or (lambda r, v: set_path(r, knob.path, v))
    runs = max(repeat, 2) if knob.warm else repeat
    rungs = [dict(value=v, **_run_rung(setter(raw, v), base_dir, runs)) for v in values]
    steps = [knob.step(v) for v in values]
    found = [m for m in metrics if any(m in r["metrics"] for r in rungs)]
    if metrics is KEY_METRICS:
        names = dict.fromkeys(k for r in rungs for k in r["metrics"])
        found += [k for k in names if k.startswith("bearing_")
                  and k.partition("_")[2].partition("_")[2] in BEARING_METRICS]
    per_metric = {}
    for m in found:
        series = [r["metrics"].get(m, {}).get("value") for r in rungs]
        a = analyse(series, steps)
        unit = next(r["metrics"][m]["unit"] for r in rungs if m in r["metrics"])
        per_metric[m] = dict(unit=unit, values=series, **a)
    worst = [None if r["status"] != "ok" else
             max((per_metric[m]["errors"][i] or 0.0 for m in found), default=0.0)
             for i, r in enumerate(rungs)]
    pick = cheapest(rungs, worst, tolerance)
    return {"knob": name, "path": knob.path, "description": knob.description,
            "values": list(values), "rungs": rungs, "metrics": per_metric,
            "worst_error": worst,
            "cheapest": None if pick is None else {
                "value": values[pick], "wall_time": rungs[pick]["wall_time"],
                "worst_error": worst[pick]}}


def study(deck: str, knobs: Sequence[str] | None = None, tolerance: float = 1e-3, *,
          repeat: int = 1, progress: Callable[[str], None] | None = None) -> dict:
    """The accuracy study of a deck file: every requested knob's ladder, analysed."""
    from pathlib import Path

    from camtrain import api
    from camtrain.deck.load import parse_toml, read_text

    name, text = read_text(deck)
    raw = parse_toml(text, name)
    base_dir = Path(deck).resolve().parent if deck != "-" else Path.cwd()
    names = check_knobs(raw, knobs)
    loaded = api.loads(text, name) if deck == "-" else api.load(deck)
    api.run(loaded)  # warm-up: imports and caches must not be charged to the first rung
    out = {"deck": name, "title": loaded.model.title, "tolerance": tolerance, "knobs": {}}
    for knob in names:
        if progress:
            progress(knob)
        out["knobs"][knob] = study_knob(raw, knob, tolerance, base_dir=base_dir, repeat=repeat)
    return out


# --------------------------------------------------------------------------- tables

CSV_FIELDS = ("knob", "value", "status", "wall_time_s", "metric", "unit", "metric_value",
              "reference", "reference_kind", "relative_error", "observed_order")


def rows(report: dict) -> list[dict]:
    """One flat row per knob, rung and metric (failed rungs get one row with their status)."""
    out = []
    for knob, k in report["knobs"].items():
        for i, rung in enumerate(k["rungs"]):
            base = {"knob": knob, "value": rung["value"], "status": rung["status"],
                    "wall_time_s": rung["wall_time"]}
            if rung["status"] != "ok":
                out.append({**base, "metric": "", "unit": "", "metric_value": None,
                            "reference": None, "reference_kind": "", "relative_error": None,
                            "observed_order": None})
                continue
            for metric, m in k["metrics"].items():
                out.append({**base, "metric": metric, "unit": m["unit"],
                            "metric_value": m["values"][i], "reference": m["reference"],
                            "reference_kind": m["reference_kind"],
                            "relative_error": m["errors"][i], "observed_order": m["orders"][i]})
    return out


def _fmt(x, spec: str = ".4g") -> str:
    return "" if x is None else format(x, spec)


def value_text(v) -> str:
    """A rung's knob value as printed: numbers with %g, names (a model) as they are."""
    return format(v, "g") if isinstance(v, int | float) else str(v)


def render_table(report: dict) -> str:
    """Plain-text tables for the terminal: per knob, the time of each rung, then per metric the
    value, relative error and observed order at each rung (metrics the knob leaves unchanged are
    listed on one line)."""
    tol = report["tolerance"]
    lines = [f"{report['title']}: accuracy study (tolerance {tol:.3g})"]
    for knob, k in report["knobs"].items():
        lines += ["", f"{knob} ({k['path']}): {k['description']}",
                  f"  {'value':>10} {'time ms':>9} {'worst err':>10}  status"]
        for i, rung in enumerate(k["rungs"]):
            t = rung["wall_time"]
            msg = rung["status"] if rung["status"] == "ok" else \
                f"{rung['status']}: {rung['message'].splitlines()[0]}"
            lines.append(f"  {value_text(rung['value']):>10} "
                         f"{_fmt(None if t is None else 1e3 * t, '.1f'):>9}"
                         f" {_fmt(k['worst_error'][i], '.2e'):>10}  {msg}")
        unchanged = []
        for metric, m in k["metrics"].items():
            if not any(m["errors"][i] for i in range(len(m["errors"]))):
                unchanged.append(metric)
                continue
            lines.append(f"  {metric} [{m['unit']}]: reference {_fmt(m['reference'], '.7g')} "
                         f"({m['reference_kind']}), observed order {_fmt(m['order'], '.2f') or '-'}")
            for i, v in enumerate(m["values"]):
                if v is not None:
                    lines.append(f"  {value_text(k['rungs'][i]['value']):>10} {_fmt(v, '.7g'):>14} "
                                 f"err {_fmt(m['errors'][i], '.2e'):>9}  "
                                 f"p {_fmt(m['orders'][i], '.2f') or '-':>5}")
        if unchanged:
            lines.append("  unchanged by this knob: " + ", ".join(unchanged))
        c = k["cheapest"]
        lines.append(f"  no rung meets {tol:.3g} for every metric" if c is None else
                     f"  cheapest meeting {tol:.3g}: {knob} = {value_text(c['value'])} "
                     f"({1e3 * c['wall_time']:.1f} ms, worst error {c['worst_error']:.2e})")
    return "\n".join(lines)


def in_units(report: dict, units: str = "deck") -> dict:
    """The study with every metric value and reference in ``units`` ("deck": mm, µm, MPa, ...
    as the report shows them; "si" as computed), each metric's unit changed to match. Errors
    and orders are relative and unchanged."""
    from camtrain.report.display import output_unit

    out = {**report, "units": units, "knobs": {}}
    for knob, k in report["knobs"].items():
        metrics = {}
        for name, m in k["metrics"].items():
            unit, f = output_unit(name, m["unit"], units)
            metrics[name] = {**m, "unit": unit,
                             "values": [None if v is None else v * f for v in m["values"]],
                             "reference": None if m["reference"] is None else m["reference"] * f}
        rungs = [{**r, "metrics": {n: {"value": x["value"] * output_unit(n, x["unit"], units)[1],
                                       "unit": output_unit(n, x["unit"], units)[0]}
                                   for n, x in r["metrics"].items()}} for r in k["rungs"]]
        out["knobs"][knob] = {**k, "metrics": metrics, "rungs": rungs}
    return out


def write_outputs(report: dict, out_dir, units: str = "deck") -> list:
    """Write accuracy.csv, accuracy.json and accuracy.png into ``out_dir``; return the paths.
    The tables hold the metrics in ``units`` ("deck" or "si"), each with its unit."""
    import csv
    import json
    from pathlib import Path

    from camtrain.study.accuracy_plot import pareto_plot

    report = in_units(report, units)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    csv_path, json_path = out / "accuracy.csv", out / "accuracy.json"
    with csv_path.open("w", newline="", encoding="utf-8") as fh:
        writer = csv.DictWriter(fh, fieldnames=CSV_FIELDS)
        writer.writeheader()
        writer.writerows(rows(report))
    json_path.write_text(json.dumps(_json_safe(report), indent=2) + "\n", encoding="utf-8")
    return [csv_path, json_path, pareto_plot(report, out / "accuracy.png")]


def _json_safe(x):
    """Replace non-finite floats by None so the JSON is strict."""
    if isinstance(x, dict):
        return {k: _json_safe(v) for k, v in x.items()}
    if isinstance(x, list | tuple):
        return [_json_safe(v) for v in x]
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x
