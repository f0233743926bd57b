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
import re
import time
from collections.abc import Callable, Sequence

from camtrain.errors import CamtrainError, InputError, Problem
from camtrain.study.accuracy_knobs import KNOBS

#: Observed orders outside this range are treated as noise, not as asymptotic convergence.
PLAUSIBLE_ORDER = (0.5, 8.0)

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


def plan_of(raw: dict, base_dir=None):
    """The plan of the deck ``raw`` (validated, not run)."""
    from camtrain import api
    from camtrain.deck.load import validate

    return api.plan(validate(raw, base_dir=base_dir))


def relevant_knobs(raw: dict, plan=None, base_dir=None) -> list[str]:
    """Knobs that change something for this deck: those the effects of its plan declare
    (EffectSpec.knobs), narrowed by each knob's test on the deck's options (e.g. no friction
    iteration on a flat tappet). ``plan``: the deck's plan when already resolved."""
    from camtrain.catalogue import declared_effects

    plan = plan_of(raw, base_dir) if plan is None else plan
    declared = {n for spec in declared_effects(plan) for n in spec.knobs}
    return [name for name, knob in KNOBS.items() if name in declared and knob.applies(raw)]


def check_knobs(raw: dict, names: Sequence[str] | None, plan=None, base_dir=None) -> list[str]:
    """Validate requested knob names against the deck; default: every relevant knob."""
    relevant = relevant_knobs(raw, plan, base_dir)
    if not names:
        return relevant
    out = []
    for name in names:
        if name not in KNOBS:
            raise InputError(Problem("--knob", "is not a resolution knob", name,
                                     "one of " + ", ".join(KNOBS)))
        if name not in relevant:
            raise InputError(Problem("--knob", "does not apply to this deck", name,
                                     "one of " + (", ".join(relevant) or "none"),
                                     f"it sets the {KNOBS[name].description}, "
                                     "which this deck does not use"))
        if name not in out:
            out.append(name)
    return out


#: a rung's time is stable when its two fastest runs agree within this fraction
STABLE_SPREAD = 0.1


def timing_spread(times: Sequence[float]) -> float:
    """(second fastest - fastest) / fastest of a rung's timed runs; inf for a single run."""
    if len(times) < 2:
        return math.inf
    first, second = sorted(times)[:2]
    return (second - first) / first if first > 0 else math.inf


def _run_rung(raw: dict, base_dir, repeat: int, least: int = 1) -> dict:
    """Validate and run one rung; its metrics and wall time, or its error.

    The rung is timed again (at least ``least`` runs, at most ``repeat``) until its two fastest
    runs agree within STABLE_SPREAD: a single run of a few milliseconds is noise. The fastest
    time is kept, with the spread of the two fastest and the number of runs."""
    from camtrain import api
    from camtrain.deck.load import validate

    times: list[float] = []
    try:
        model = validate(raw, base_dir=base_dir)
        while len(times) < max(1, repeat):
            start = time.perf_counter()
            result = api.run(model)
            times.append(time.perf_counter() - start)
            if len(times) >= least and timing_spread(times) <= STABLE_SPREAD:
                break
    except CamtrainError as exc:
        return {"status": "error", "message": str(exc), "exit_code": exc.exit_code,
                "wall_time": None, "wall_spread": None, "timed_runs": len(times), "metrics": {},
                "declared": ()}
    metrics = {k: {"value": m.value, "unit": m.unit} for k, m in result.metrics.items()}
    spread = timing_spread(times)
    return {"status": "ok", "message": "", "exit_code": 0, "wall_time": min(times),
            "wall_spread": spread if math.isfinite(spread) else None,
            "timed_runs": len(times), "metrics": metrics,
            "declared": declared_metrics(result.plan)}


def declared_metrics(plan) -> tuple[str, ...]:
    """The metric names (``{k}``: any component number) the effects of ``plan`` declare for
    the accuracy study (EffectSpec.accuracy_metrics), in plan order."""
    from camtrain.catalogue import declared_effects

    return tuple(dict.fromkeys(n for spec in declared_effects(plan)
                               for n in spec.accuracy_metrics))


def studied_metrics(runs, plan=None, metrics: Sequence[str] | None = None) -> list[str]:
    """The metrics studied over rungs whose metrics are ``runs`` (one mapping per rung): those
    the rungs produced that match a name declared by the plan's effects (or given in
    ``metrics``), in the order declared."""
    wanted = declared_metrics(plan) if metrics is None else metrics
    produced = dict.fromkeys(k for r in runs for k in r)
    found: dict[str, None] = {}
    for name in wanted:
        pattern = re.compile(re.escape(name).replace(re.escape("{k}"), "[^_]+"))
        found.update(dict.fromkeys(k for k in produced if pattern.fullmatch(k)))
    return list(found)


def study_knob(raw: dict, name: str, tolerance: float, *, base_dir=None, repeat: int = 5,
               ladder: Sequence[float] | None = None,
               metrics: Sequence[str] | None = None) -> dict:
    """Run the ladder of one knob and analyse every metric it produced that the effects of
    the rungs' plans declare for the study (or that ``metrics`` names)."""
    knob = KNOBS[name]
    values = tuple(ladder or knob.ladder_of(raw))
    values = tuple(int(v) for v in values) if knob.integer else values
    setter = knob.setter or (lambda r, v: set_path(r, knob.path, v))
    least = 2 if knob.warm else 1      # a warm knob's first run builds a table: time another
    rungs = [dict(value=v, **_run_rung(setter(raw, v), base_dir, max(repeat, least), least))
             for v in values]
    steps = [knob.step(v) for v in values]
    declared = tuple(dict.fromkeys(n for r in rungs for n in r.pop("declared")))
    found = studied_metrics([r["metrics"] for r in rungs], None,
                            declared if metrics is None else metrics)
    per_metric = {}
    for m in found:
        series = [r["metrics"].get(m, {}).get("value") for r in rungs]
        a = analyse(series, steps)
        unit = next(u for r in rungs if (u := r["metrics"].get(m, {}).get("unit")) is not None)
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
          repeat: int = 5, progress: Callable[[str], None] | None = None) -> dict:
    """The accuracy study of a deck file: every requested knob's ladder, analysed."""
    from pathlib import Path

    from camtrain import api
    from camtrain.deck.load import parse_toml, read_text

    name, text = read_text(deck)
    raw = parse_toml(text, name)
    base_dir = Path(deck).resolve().parent if deck != "-" else Path.cwd()
    loaded = api.loads(text, name) if deck == "-" else api.load(deck)
    names = check_knobs(raw, knobs, api.plan(loaded))
    api.run(loaded)  # warm-up: imports and caches must not be charged to the first rung
    out = {"deck": name, "title": loaded.model.title, "tolerance": tolerance, "knobs": {}}
    for knob in names:
        if progress:
            progress(knob)
        out["knobs"][knob] = study_knob(raw, knob, tolerance, base_dir=base_dir, repeat=repeat)
    return out


# --------------------------------------------------------------------------- tables

CSV_FIELDS = ("knob", "value", "status", "wall_time_s", "wall_spread", "metric", "unit", "metric_value",
              "reference", "reference_kind", "relative_error", "observed_order")


def rows(report: dict) -> list[dict]:
    """One flat row per knob, rung and metric (failed rungs get one row with their status)."""
    out = []
    for knob, k in report["knobs"].items():
        for i, rung in enumerate(k["rungs"]):
            base = {"knob": knob, "value": rung["value"], "status": rung["status"],
                    "wall_time_s": rung["wall_time"], "wall_spread": rung.get("wall_spread")}
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


def _verdict(rung: dict, worst: float | None, tolerance: float) -> str:
    """met / not met against the tolerance, or why the rung did not run."""
    if rung["status"] != "ok":
        return f"{rung['status']}: {rung['message'].splitlines()[0]}"
    if worst is None:
        return "-"
    return "met" if worst <= tolerance else "not met"


def _spread_text(spread: float | None, runs: int | None) -> str:
    """The spread of a rung's two fastest times, '-' for a rung timed once."""
    if spread is None:
        return "-"
    return f"{100 * spread:.0f}%" + ("" if spread <= STABLE_SPREAD else "!")


def render_table(report: dict) -> str:
    """Plain-text tables for the terminal: per knob, the time of each rung, then per metric the
    value, relative error and observed order at each rung (metrics the knob leaves unchanged are
    listed on one line)."""
    tol = report["tolerance"]
    lines = [f"{report['title']}: accuracy study (tolerance {tol:.3g})"]
    for knob, k in report["knobs"].items():
        lines += ["", f"{knob} ({k['path']}): {k['description']}",
                  f"  {'value':>10} {'time ms':>9} {'spread':>7} {'worst err':>10}  "
                  f"tolerance {tol:.3g}"]
        for i, rung in enumerate(k["rungs"]):
            t, spread = rung["wall_time"], rung.get("wall_spread")
            lines.append(f"  {value_text(rung['value']):>10} "
                         f"{_fmt(None if t is None else 1e3 * t, '.1f'):>9}"
                         f" {_spread_text(spread, rung.get('timed_runs')):>7}"
                         f" {_fmt(k['worst_error'][i], '.2e'):>10}  "
                         f"{_verdict(rung, k['worst_error'][i], tol)}")
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
