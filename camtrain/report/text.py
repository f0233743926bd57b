"""report.txt: the hard copy of a run, in the spirit of Ball's printed output.

Plain fixed-width text an engineer can print or diff: header block, input echo with units, plan,
key results, design limits, warnings and findings, and the cycle table every few degrees.
"""
from __future__ import annotations

import math

import numpy as np

from camtrain import __version__
from camtrain.report.display import LABELS, deg, display_unit, fmt, shown
from camtrain.report.echo import echo_rows
from camtrain.report.engine_report import bearing_table_lines
from camtrain.report.findings import find
from camtrain.report.header import header_rows, report_heading, title_line
from camtrain.result import Result

WIDTH = 100

#: columns of the printed cycle table, in this order, when the run has them
#: the per-angle table's columns, each with the product whose effect writes it (None: the lift
#: law's, in every run): the table holds those of the products the plan made
TABLE_COLUMNS = {"lift": None, "valve_lift": "TrainKinematics", "velocity": None,
                 "acceleration": None, "eccentricity": "TrainKinematics",
                 "cam_radius": "TrainKinematics", "equivalent_radius": "TrainKinematics",
                 "v_cam": "TrainKinematics", "v_follower": "TrainKinematics",
                 "entrainment": "TrainKinematics", "load": "ContactLoad",
                 "hertz_pmax": "ContactHertz", "film_min": "ContactFilm",
                 "film_central": "ContactFilm", "lambda": "ContactFilm",
                 "friction_coefficient": "ContactFriction", "friction_torque": "CamTorque",
                 "power_loss": "CamTorque"}


def _rule(title: str = "", char: str = "=") -> str:
    return f"{char * 3} {title} ".ljust(WIDTH, char) if title else char * WIDTH


def report_text(result: Result, deck=None, *, path: str = "", sha: str = "",
                checks=None, wall_time: float | None = None, step_deg: float = 5.0) -> str:
    """The whole report as text; ``deck`` is the Deck model (SI) or None."""
    lines = [_rule(), f"camtrain {__version__}   {report_heading(deck)}",
             title_line(deck), _rule(), ""]
    if path:
        lines.append(f"deck file : {path}")
    if sha:
        lines.append(f"sha256    : {sha}")
    if wall_time is not None:
        lines.append(f"wall time : {wall_time:.3f} s")
    lines.append("")
    rows = header_rows(deck, result)
    if rows:
        width = max(len(label) for label, _ in rows)
        lines += [f"  {label:<{width}} = {value}" for label, value in rows] + [""]
    if deck is not None:
        lines += [_rule("INPUT DATA (as camtrain read it; deck units)", "-")]
        echo = echo_rows(deck)
        w = max(len(p) for p, *_ in echo)
        for p, doc, value, unit in echo:
            lines.append(f"  {p:<{w}}  {value:>14} {unit:<8} {doc}")
        lines.append("")
    if result.plan is not None:
        lines += [_rule(f"PLAN ({result.plan.mode})", "-")]
        for s in result.plan.steps:
            runs = "runs" if s.chosen else "skipped"
            t = result.timings.get(s.effect)
            when = f"{t * 1e3:8.1f} ms" if t is not None else " " * 11
            lines.append(f"  {s.effect:<12} {runs:<14} {when}  {s.reason}")
        lines.append("")
    lines += [_rule("RESULTS", "-")]
    w = max((len(n) for n in result.metrics), default=8)
    if result.metrics:
        lines.append(f"  {'quantity':<{w}} {'value':>12} {'unit':<8} {'at [deg]':>8}  what it is")
    for name, m in result.metrics.items():
        value, unit = shown(name, m.value, m.unit)
        lines.append(f"  {name:<{w}} {value:>12} {unit:<8} {deg(m.angle):>8}  {m.description}")
    if not result.metrics:
        lines.append("  (no scalar results)")
    lines.append("")
    lines += _summary_lines(result, deck)
    lines += bearing_table_lines(result, WIDTH)
    if checks:
        lines += [_rule("DESIGN LIMITS", "-")]
        lines += [f"  {'ok  ' if c.ok else 'FAIL'}  {c.text()}" for c in checks] + [""]
    findings = find(result).messages(result.warnings)
    if result.warnings or findings:
        lines += [_rule("WARNINGS", "-")]
        lines += [f"  * {w}" for w in result.warnings + findings]
        lines.append("")
    lines += _cycle_table(result, step_deg)
    return "\n".join(lines).rstrip() + "\n"


def _summary_lines(result: Result, deck) -> list[str]:
    """The summary tables the effects that ran declare, as the terminal prints them."""
    from camtrain.report.boxes import table
    from camtrain.report.console import summary_tables

    lines = []
    for t in summary_tables(result, deck):
        rows = [[text for text, _ in row] for row in t.rows]
        lines += table(t.title, [(name, justify) for name, justify, _ in t.columns], rows,
                       WIDTH) + [""]
    return lines


def _cycle_table(result: Result, step_deg: float) -> list[str]:
    """The per-angle table of report.txt, when an effect that ran declares it
    (EffectSpec.sections: "cycle_table"); its columns are those of TABLE_COLUMNS of the
    products the plan made, the central film where the film has one."""
    from camtrain.catalogue import declared_effects, planned_products
    from camtrain.report.findings import central_film

    declared = any("cycle_table" in spec.sections for spec in declared_effects(result.plan))
    if not declared or not result.axes:   # an empty result (no plan, no grid): no table
        return []
    theta = np.degrees(result["cam_angle"])
    made = planned_products(result.plan)
    names = [n for n, product in TABLE_COLUMNS.items() if product is None or product in made
             and (n != "film_central" or central_film(result))]
    targets = np.arange(-180.0, 180.0 + 1e-9, step_deg)
    idx = sorted({int(np.argmin(np.abs(theta - t))) for t in targets})
    heads, units, cols = ["angle"], ["[deg]"], [theta]
    for n in names:
        unit, factor = display_unit(n, result.columns[n].unit)
        heads.append(_short(n))
        units.append(f"[{unit or '-'}]")
        cols.append(result[n] * factor)
    cells = [[_cell(c[i]) for i in idx] for c in cols]
    # every number whole: the column is as wide as its longest entry (never cut to fit)
    w = max(10, 1 + max(len(t) for t in heads + units + [x for c in cells for x in c]))
    out = [_rule(f"CYCLE TABLE (every {step_deg:g} deg; cycle.csv has every angle)", "-")]
    chunk = max(1, (WIDTH - w) // w)          # columns per block so lines stay printable
    for start in range(1, len(heads), chunk):
        sel = [0] + list(range(start, min(start + chunk, len(heads))))
        out.append("".join(f"{heads[j]:>{w}}" for j in sel))
        out.append("".join(f"{units[j]:>{w}}" for j in sel))
        for k in range(len(idx)):
            out.append("".join(f"{cells[j][k]:>{w}}" for j in sel))
        out.append("")
    key = "; ".join(f"{SHORT[n]} = {LABELS.get(n, n)}" for n in names if SHORT[n] != LABELS.get(n))
    out.append("  key: " + key)
    return out


#: short headings of the printed table (the key below the table spells them out)
SHORT = {"lift": "lift", "valve_lift": "l_valve", "velocity": "dl/dθ", "acceleration": "d²l/dθ²",
         "eccentricity": "e", "cam_radius": "r_c", "equivalent_radius": "R", "v_cam": "V_c",
         "v_follower": "V_f", "entrainment": "u_e", "load": "W", "hertz_pmax": "p_max",
         "film_min": "h_min", "film_central": "h_cen", "lambda": "λ",
         "friction_coefficient": "μ", "friction_torque": "T_f", "power_loss": "P_f"}


def _short(name: str) -> str:
    return SHORT.get(name, name[:9])


def _cell(x: float) -> str:
    if not math.isfinite(x):
        return str(x)
    return fmt(float(x), 4)
