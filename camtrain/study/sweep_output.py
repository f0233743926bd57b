"""Sweep outputs: sweep.csv (and reading it back to resume), the trend table, plots, overlays.

sweep.csv has one row per case: ``case``, the parameter values (``name[unit]``), ``status``,
``message``, then every metric (``name[unit]``, in the deck's units as in summary.json, or SI with
``units="si"``). Numbers are written as the shortest text that reads back to the same float, so a
resumed sweep reproduces the table exactly.
"""
from __future__ import annotations

import csv
import functools
import io
import math
import re
from pathlib import Path

from camtrain.metric_rows import case_metric
from camtrain.report.display import display_unit, output_unit
from camtrain.report.tables import atomic_write
from camtrain.study.sweep import Case, Parameter

FIXED_COLUMNS = ("case", "status", "message")
#: Statuses that are final; 'error' (a bug in camtrain) is tried again on --resume.
FINAL = ("ok", "lost_contact", "failed")
_HEADER = re.compile(r"^(.*)\[(.*)\]$")


def _fmt(x: float) -> str:
    return repr(float(x))  # 'nan' and 'inf' stay readable and distinct from a missing value


def in_units(record: dict, units: str = "deck") -> dict:
    """A case record (metrics and curves in SI, as a case returns them) with its metrics and
    curves in ``units``: the deck's units ("deck") or SI ("si"). A record already converted
    (read back from sweep.csv) is unchanged."""
    metrics = {}
    for n, (value, unit) in record["metrics"].items():
        out, factor = _unit(n, unit, units)
        metrics[n] = (value * factor, out)
    curves = record.get("curves")
    if curves:
        curves = {n: (_unit(n, unit, units)[0], [v * _unit(n, unit, units)[1] for v in values])
                  for n, (unit, values) in curves.items()}
    return {**record, "metrics": metrics, "curves": curves}


@functools.lru_cache(maxsize=4096)
def _unit(name: str, unit: str, units: str) -> tuple[str, float]:
    """:func:`output_unit`, looked up once per metric of a sweep (thousands of records)."""
    return output_unit(name, unit, units)


def shown(name: str, value: float, unit: str) -> tuple[float, str]:
    """A metric or curve value in the units a person reads (plots), from SI or deck units."""
    out, factor = display_unit(name, unit)
    return value * factor, out or "-"


def param_column(p: Parameter, units: str = "deck") -> tuple[str, float]:
    """(header, factor from the deck unit) of a parameter's column in sweep.csv."""
    from camtrain.units import UNITS

    if units == "si" and p.unit in UNITS:
        factor, si = UNITS[p.unit]
        return f"{p.name}[{si}]", factor
    return p.label, 1.0


def metric_order(records: list[dict]) -> list[str]:
    """Metric columns: the lowest-index ok case's order, then the rest alphabetically. The rule
    depends only on the set of results, never on the order in which they finished."""
    ordered = sorted(records, key=lambda r: r["index"])
    first = next((r for r in ordered if r["status"] == "ok"), None)
    names = list(first["metrics"]) if first else []
    rest = sorted({n for r in ordered for n in r["metrics"]} - set(names))
    return names + rest


def metric_units(records: list[dict]) -> dict[str, str]:
    units: dict[str, str] = {}
    for r in sorted(records, key=lambda r: r["index"]):
        if r["metrics"].keys() <= units.keys():
            continue   # nothing new in this record (the usual case: every case has one set)
        for n, (_, unit) in r["metrics"].items():
            units.setdefault(n, unit)
    return units


def csv_text(params: list[Parameter], records: list[dict], units: str = "deck") -> str:
    """The text of sweep.csv for these records (sorted by case index; metrics already in
    ``units``, see in_units; parameters in their deck unit, converted here for "si")."""
    names = metric_order(records)
    metric_unit = metric_units(records)
    columns = [param_column(p, units) for p in params]
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["case"] + [label for label, _ in columns] + ["status", "message"]
               + [f"{n}[{metric_unit[n]}]" for n in names])
    for r in sorted(records, key=lambda r: r["index"]):
        row = [str(r["index"])] + [_fmt(r["values"][p.name] * f)
                                   for p, (_, f) in zip(params, columns, strict=True)]
        row += [r["status"], r["message"]]
        cells = [case_metric(r["metrics"], n) for n in names]
        row += ["" if cell is None else _fmt(cell[0]) for cell in cells]
        w.writerow(row)
    return buf.getvalue()


def write_csv(path: Path, params: list[Parameter], records: list[dict],
              units: str = "deck") -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    atomic_write(path, csv_text(params, records, units))
    return path


def read_finished(path: Path, params: list[Parameter], cases: list[Case],
                  units: str = "deck") -> dict[int, dict]:
    """Records of sweep.csv whose case index *and* parameter values match a case of this sweep
    and whose status is final. Anything else (other values, a torn last line) is run again.
    Metrics stay as written (in ``units``); parameter values are the case's own."""
    if not path.is_file():
        return {}
    wanted = {c.index: c.as_dict() for c in cases}
    out: dict[int, dict] = {}
    with path.open(newline="", encoding="utf-8") as fh:
        reader = csv.reader(fh)
        header = next(reader, None)
        if not header or header[0] != "case":
            return {}
        for row in reader:
            if len(row) != len(header):
                continue
            rec = _parse_row(header, row, params, units)
            if rec is None or rec["status"] not in FINAL or rec["index"] not in wanted:
                continue
            want = wanted[rec["index"]]
            if set(rec["values"]) != set(want) or not all(
                    math.isclose(rec["values"][k], want[k], rel_tol=1e-12, abs_tol=1e-300)
                    for k in want):
                continue
            out[rec["index"]] = {**rec, "values": want}
    return out


def _parse_row(header: list[str], row: list[str], params: list[Parameter],
               units: str = "deck") -> dict | None:
    labels = {param_column(p, units)[0]: (p.name, param_column(p, units)[1]) for p in params}
    rec = {"index": None, "values": {}, "status": "", "message": "", "metrics": {}, "curves": None}
    try:
        for col, text in zip(header, row, strict=True):
            if col == "case":
                rec["index"] = int(text)
            elif col in ("status", "message"):
                rec[col] = text
            elif col in labels:
                name, factor = labels[col]
                rec["values"][name] = float(text) / factor
            elif text != "":
                m = _HEADER.match(col)
                if m is None:
                    return None
                rec["metrics"][m.group(1)] = (float(text), m.group(2))
    except ValueError:
        return None
    if len(rec["values"]) != len(params):
        return None
    return rec


# --------------------------------------------------------------------------- curves for overlays

def curve_path(out_dir: Path, index: int) -> Path:
    return out_dir / "curves" / f"case_{index:05d}.csv"


def write_curves(out_dir: Path, record: dict) -> None:
    """Per-angle curves of one case (kept for the overlays, and across --resume)."""
    curves = record.get("curves")
    if not curves:
        return
    names = list(curves)
    lines = [",".join(f"{n}[{curves[n][0]}]" for n in names)]
    for row in zip(*(curves[n][1] for n in names), strict=True):
        lines.append(",".join(f"{v:.10g}" for v in row))
    path = curve_path(out_dir, record["index"])
    path.parent.mkdir(parents=True, exist_ok=True)
    atomic_write(path, "\n".join(lines) + "\n")


def read_curves(out_dir: Path, index: int) -> dict | None:
    path = curve_path(out_dir, index)
    if not path.is_file():
        return None
    rows = list(csv.reader(path.open(encoding="utf-8")))
    curves = {}
    for j, col in enumerate(rows[0]):
        m = _HEADER.match(col)
        curves[m.group(1)] = (m.group(2), [float(r[j]) for r in rows[1:]])
    return curves


# --------------------------------------------------------------------------- plots

#: Column name -> label of its overlay panel (values shown in display units, see ``shown``)
CURVE_DISPLAY = {"film_min": "minimum film", "load": "contact load",
                 "hertz_pmax": "Hertz stress", "lift": "lift"}
#: Ball's three outputs of every parametric study (Figs 5.x)
BALL_METRICS = ("film_min_at_max_lift", "hertz_at_max_lift", "power_loss_mean")


def _pyplot():
    from camtrain.report.plots import _pyplot

    return _pyplot()


def _case_label(values: dict, params: list[Parameter]) -> str:
    return ", ".join(f"{p.name} {values[p.name]:g}" for p in params)


def metric_plots(out_dir: Path, params: list[Parameter], records: list[dict],
                 trends: list | None = None, title: str = "") -> list[Path]:
    """One sheet per parameter: every metric against it (one line per setting of the others),
    in display units whatever the tables' units, under a title naming the sweep.

    Metrics the trend table found constant for a parameter are left off its sheet: they say
    nothing, and each panel costs drawing time.
    """
    plt = _pyplot()
    ok = sorted((r for r in records if r["status"] == "ok"), key=lambda r: r["index"])
    units = metric_units(records)
    flat = {(t.metric, t.parameter) for t in trends or () if t.trend in ("constant", "n/a")}
    written = []
    for p in params:
        names = [n for n in metric_order(records) if (n, p.name) not in flat]
        if not ok or not names:
            continue
        others = [q for q in params if q is not p]
        ncol = min(4, len(names))
        nrow = math.ceil(len(names) / ncol)
        fig, axes = plt.subplots(nrow, ncol, figsize=(3.2 * ncol, 2.4 * nrow), squeeze=False)
        groups: dict[tuple, list[dict]] = {}
        for r in ok:
            groups.setdefault(tuple(r["values"][q.name] for q in others), []).append(r)
        if len(groups) > 1 and all(len(g) == 1 for g in groups.values()):
            groups, others = {(): ok}, []  # zipped parameters: one line through all cases
        for ax, n in zip(axes.flat, names, strict=False):
            for key, line in groups.items():
                got = [(r["values"][p.name], case_metric(r["metrics"], n)) for r in line]
                pts = sorted((x, shown(n, *m)[0]) for x, m in got
                             if m is not None and math.isfinite(m[0]))
                if pts:
                    label = ", ".join(f"{q.name} {v:g}" for q, v in zip(others, key, strict=True))
                    ax.plot(*zip(*pts, strict=True), marker="o", ms=3, lw=1, label=label or None)
            ax.set_title(n, fontsize=8)
            ax.set_ylabel(shown(n, 1.0, units[n])[1], fontsize=7)
            ax.yaxis.set_major_formatter(_plain_formatter())
            ax.tick_params(labelsize=7)
            ax.grid(True, alpha=0.3)
        for ax in list(axes.flat)[len(names):]:
            ax.set_visible(False)
        for ax in axes[-1]:
            ax.set_xlabel(p.label, fontsize=7)
        if others and len(groups) <= 8:
            axes.flat[0].legend(fontsize=6)
        # fixed spacing: tight_layout on dozens of panels costs seconds per sheet
        head = f"{title}: " if title else ""
        fig.suptitle(f"{head}metrics against {p.label} (ok cases)", fontsize=9)
        fig.subplots_adjust(left=0.07, right=0.98, bottom=0.5 / nrow, top=1 - 0.45 / nrow,
                            hspace=0.55, wspace=0.4)
        written.append(_save(plt, fig, out_dir / "plots" / f"metrics_vs_{p.name}.png"))
    for p in params:
        ball = _ball_sheet(plt, p, ok, units) if ok else None
        if ball is not None:
            written.append(_save(plt, ball, out_dir / "plots" / f"ball_{p.name}.png"))
    return written


def _plain_formatter():
    """Tick labels written in full with just enough digits to tell them apart: no offset or
    multiplier ('1e-8', '+4.17e2') for the reader to apply."""
    from matplotlib.ticker import Formatter

    class Plain(Formatter):
        def __call__(self, x, pos=None):
            return f"{x:.6g}"

        def format_ticks(self, values):
            labels = [f"{v:.6g}" for v in values]
            for digits in range(3, 13):
                labels = [f"{v:.{digits}g}" for v in values]
                if len(set(labels)) == len(labels):
                    break
            return labels

    return Plain()


def _ball_sheet(plt, p: Parameter, ok: list[dict], units: dict):
    """Ball's Fig 5.x layout: nose film, nose Hertz stress and power loss against % change of
    the parameter from the deck's datum, each as % change from its datum value."""
    present = [n for n in BALL_METRICS if n in units]
    if not present or not p.datum:
        return None
    datum_case = min(ok, key=lambda r: abs(r["values"][p.name] - p.datum))
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for n in present:
        ref = datum_case["metrics"].get(n, (math.nan,))[0]
        got = [(r["values"][p.name], case_metric(r["metrics"], n)) for r in ok]
        pts = sorted(((x / p.datum - 1) * 100, (m[0] / ref - 1) * 100 if ref else math.nan)
                     for x, m in got if m is not None)
        ax.plot(*zip(*pts, strict=True), marker="o", ms=3, label=n)
    ax.set_xlabel(f"change of {p.name} from {p.datum:g} {p.unit} [%]")
    ax.set_ylabel("change from the datum case [%]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def overlay_plots(out_dir: Path, params: list[Parameter], records: list[dict],
                  title: str = "") -> list[Path]:
    """Film, load and stress (or lift) against cam angle, one line per kept case."""
    plt = _pyplot()
    kept = []
    for r in sorted(records, key=lambda r: r["index"]):
        if r["status"] in ("ok", "lost_contact"):
            curves = r.get("curves") or read_curves(out_dir, r["index"])
            if curves:
                kept.append((r, curves))
    if not kept:
        return []
    panels = [n for n in CURVE_DISPLAY if n != "lift" and n in kept[0][1]] or ["lift"]
    panels = [n for n in panels if n in kept[0][1]]
    if not panels:
        return []
    fig, axes = plt.subplots(len(panels), 1, figsize=(8.0, 2.8 * len(panels)), sharex=True,
                             squeeze=False)
    cmap = plt.get_cmap("viridis")
    for i, (r, curves) in enumerate(kept):
        color = cmap(i / max(1, len(kept) - 1))
        for ax, n in zip(axes[:, 0], panels, strict=True):
            unit = shown(n, 1.0, curves[n][0])[1]
            theta = [shown("cam_angle", v, curves["cam_angle"][0])[0]
                     for v in curves["cam_angle"][1]]
            ax.plot(theta, [shown(n, v, curves[n][0])[0] for v in curves[n][1]], lw=0.9,
                    color=color, label=_case_label(r["values"], params))
            ax.set_ylabel(f"{CURVE_DISPLAY[n]} [{unit}]")
            ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("cam angle from maximum lift [deg]")
    axes[-1, 0].set_xlim(-180, 180)
    axes[0, 0].legend(fontsize=6, ncol=2)
    axes[0, 0].set_title((f"{title}: " if title else "") + "per-angle curves of "
                         f"{len(kept)} cases", fontsize=9)
    fig.tight_layout()
    return [_save(plt, fig, out_dir / "plots" / "overlay_curves.png")]


def _save(plt, fig, path: Path) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
