"""What `camtrain optimize` writes: the optimum deck, the gain by part, the active constraints,
the path, and a sheet comparing datum and optimum (docs/design.md)."""
from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

from camtrain.report.tables import atomic_write
from camtrain.study.optimize import OptimizeOutcome


def optimum_raw(outcome: OptimizeOutcome) -> dict:
    """The datum deck (raw TOML dictionary) with the optimum's values written in."""
    from camtrain.study.sweep import Case, case_raw

    p = outcome.problem
    case = Case(0, tuple((v.name, x) for v, x in zip(p.variables, outcome.optimum.x,
                                                     strict=True)))
    raw = case_raw(p.raw, [v.param for v in p.variables], case)
    if outcome.optimum.designed_lift is not None:     # the lift designed from its events
        measured = raw.get("lift", {}).get("measured_at", "valve")
        raw["lift"] = {"form": "spline", "measured_at": measured,
                       "spline": outcome.optimum.designed_lift}
    return raw


def summary(outcome: OptimizeOutcome) -> dict:
    """The search as plain data (optimize.json)."""
    p = outcome.problem
    return {
        "deck": p.name, "method": outcome.method, "status": outcome.status,
        "message": outcome.message, "evaluations": outcome.evaluations,
        "route": p.route.as_dict(), "objective": p.objective,
        "variables": [{"name": v.name, "path": v.param.path, "unit": v.param.unit,
                       "lower": v.lower, "upper": v.upper, "datum": xd, "optimum": xo}
                      for v, xd, xo in zip(p.variables, outcome.datum.x, outcome.optimum.x,
                                           strict=True)],
        "constraints": [{"constraint": c.text, "metric": c.metric, "unit": c.unit,
                         "bound": c.bound, "datum_margin": gd, "optimum_margin": go,
                         "met": go >= -1e-9, "active": c.text in outcome.active()}
                        for c, gd, go in zip(p.constraints, outcome.datum.margins,
                                             outcome.optimum.margins, strict=True)],
        "active": outcome.active(),
        "gain": [{"metric": n, "unit": u, "datum": d, "optimum": o, "change": c,
                  "change_percent": pct} for n, u, d, o, c, pct in outcome.gains()],
    }


def _path_csv(outcome: OptimizeOutcome) -> str:
    p = outcome.problem
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["evaluation", "iteration", "role"] + [v.param.label for v in p.variables]
               + ["status", f"{p.objective}"] + [f"margin {c.text}" for c in p.constraints]
               + ["feasible", "message"])
    for i, q in enumerate(p.path):
        w.writerow([i, q.iteration, q.role, *(repr(x) for x in q.x), q.status,
                    repr(q.objective), *(repr(g) for g in q.margins), q.feasible, q.message])
    return buf.getvalue()


def comparison_rows(outcome: OptimizeOutcome) -> list[list[str]]:
    """Every metric of the datum and the optimum, with the change (deck units)."""
    rows = [["metric", "unit", "datum", "optimum", "change", "change %"]]
    for name, (d, unit) in outcome.datum.metrics.items():
        o = outcome.optimum.metrics.get(name, (math.nan, unit))[0]
        change = o - d
        pct = f"{100.0 * change / d:+.3g}" if d and math.isfinite(change) else ""
        rows.append([name, unit, f"{d:.6g}", f"{o:.6g}", f"{change:+.4g}", pct])
    return rows


def report_text(outcome: OptimizeOutcome) -> str:
    """The Markdown report: status, variables, gain by part, constraints, cost."""
    s = summary(outcome)
    lines = [f"# Optimisation: {s['deck']}", "",
             f"{s['method']}: {s['status']} ({s['message']}). {s['evaluations']} chain "
             f"evaluations; {outcome.problem.route.describe()}.", "",
             "| variable | unit | lower | upper | datum | optimum |", "|---|---|---|---|---|---|"]
    lines += [f"| {v['name']} | {v['unit']} | {v['lower']:g} | {v['upper']:g} | "
              f"{v['datum']:.6g} | {v['optimum']:.6g} |" for v in s["variables"]]
    lines += ["", "Gain over the datum by part:", "",
              "| metric | unit | datum | optimum | change | change % |", "|---|---|---|---|---|---|"]
    lines += [f"| {g['metric']} | {g['unit']} | {g['datum']:.6g} | {g['optimum']:.6g} | "
              f"{g['change']:+.4g} | {g['change_percent']:+.3g} |" for g in s["gain"]]
    if s["constraints"]:
        lines += ["", "| constraint | datum margin | optimum margin | met | active |",
                  "|---|---|---|---|---|"]
        lines += [f"| {c['constraint']} | {c['datum_margin']:+.4g} | {c['optimum_margin']:+.4g}"
                  f" | {'yes' if c['met'] else 'NO'} | {'yes' if c['active'] else ''} |"
                  for c in s["constraints"]]
        lines += ["", "Margins are scaled: the difference from the bound divided by the bound "
                  "(millimetres for no_concave_flank; the fraction of the tolerance for "
                  "open_area)."]
    lines += ["", "Active at the optimum: " + (", ".join(s["active"]) or "nothing") + ".", ""]
    return "\n".join(lines)


def write_optimize(outcome: OptimizeOutcome, out_dir: str | Path, plots: bool = True) -> list[Path]:
    """optimum.toml, optimize.json, optimize.md, path.csv, comparison.csv (and .png)."""
    import tomli_w

    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    s = summary(outcome)
    values = ", ".join(f"{v['name']} = {v['optimum']:.6g} {v['unit']}" for v in s["variables"])
    head = (f"# optimum of {Path(s['deck']).name} by camtrain optimize ({s['method']}, "
            f"{s['status']}): {values}\n\n")
    written = {"optimum.toml": head + tomli_w.dumps(optimum_raw(outcome)),
               "optimize.json": json.dumps(s, indent=2, default=float) + "\n",
               "optimize.md": report_text(outcome), "path.csv": _path_csv(outcome)}
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerows(comparison_rows(outcome))
    written["comparison.csv"] = buf.getvalue()
    paths = []
    for name, text in written.items():
        atomic_write(out_dir / name, text)
        paths.append(out_dir / name)
    if plots:
        paths.append(_sheet(outcome, out_dir / "comparison.png"))
    return paths


def _sheet(outcome: OptimizeOutcome, path: Path) -> Path:
    """Datum against optimum: the gain by part (bars) and the path of the objective."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(10.0, 4.5), constrained_layout=True)
    FigureCanvasAgg(fig)
    left, right = fig.subplots(1, 2)
    gains = outcome.gains()
    names = [g[0] for g in gains]
    x = range(len(names))
    left.bar([i - 0.2 for i in x], [g[2] for g in gains], 0.4, label="datum")
    left.bar([i + 0.2 for i in x], [g[3] for g in gains], 0.4, label="optimum")
    left.set_xticks(list(x), names, rotation=20, ha="right")
    left.set_ylabel(f"[{gains[0][1]}]" if gains else "")
    left.set_title("gain by part")
    left.legend()
    path_pts = [q for q in outcome.problem.path if math.isfinite(q.objective)]
    right.plot(range(len(path_pts)), [q.objective for q in path_pts], ".", color="0.6",
               label="every evaluation")
    feas = [(i, q.objective) for i, q in enumerate(path_pts) if q.feasible]
    if feas:
        right.plot(*zip(*feas, strict=True), "o", ms=4, label="feasible")
    right.set_xlabel("chain evaluation")
    right.set_ylabel(outcome.problem.objective)
    right.set_title(f"path ({outcome.method}, {outcome.status})")
    right.legend()
    fig.suptitle(f"{Path(outcome.problem.name).name}: datum and optimum")
    fig.savefig(path, dpi=110)
    return path
