"""The FLAME table of a sweep over engine speed: friction by component, total and fmep per
speed, the shares of the components, and a stacked plot (Yang 1992 Table 7.1).

Written by a sweep whose cases carry the ``flame_*`` metrics of an engine deck: flame.csv,
flame.md and plots/flame_stacked.png.
"""
from __future__ import annotations

import csv
import io
import math
from pathlib import Path

from camtrain.report.tables import atomic_write

#: (metric, column label) of the table, in Yang's order; powers in kW, fmep in kPa
COLUMNS = (("flame_bearings", "bearings"), ("flame_valve_train", "valve train"),
           ("flame_piston", "piston assemblies"), ("flame_accessories", "accessories"),
           ("flame_total", "total"))
COMPONENTS = COLUMNS[:3]


def _si(metric) -> float:
    """A record's metric, (value, unit) in the deck's units, in SI."""
    from camtrain.units import to_si

    value, unit = metric[0], metric[1]
    return to_si(float(value), unit)


def flame_rows(params: list, records: list[dict]) -> list[dict]:
    """One row per finished case with a FLAME total, ordered by the first swept parameter:
    {'x': value, metric: W ..., 'fmep': Pa, 'shares': {metric: share of the components}}."""
    if not params:
        return []
    p = params[0]
    rows = []
    for r in records:
        m = r.get("metrics", {})
        if r.get("status") != "ok" or "flame_total" not in m:
            continue
        row = {"x": r["values"][p.name]}
        # records carry (value, unit) in the deck's units: the table works in W and Pa
        row.update({k: _si(m[k]) for k, _ in COLUMNS if k in m})
        row["fmep"] = _si(m["fmep"]) if "fmep" in m else math.nan
        parts = sum(row.get(k, 0.0) for k, _ in COMPONENTS)
        row["shares"] = {k: row.get(k, 0.0) / parts if parts > 0 else math.nan
                         for k, _ in COMPONENTS}
        rows.append(row)
    return sorted(rows, key=lambda row: row["x"])


def flame_csv(param, rows: list[dict]) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow([param.label] + [f"{label} [kW]" for _, label in COLUMNS] + ["fmep [kPa]"]
               + [f"{label} share [%]" for _, label in COMPONENTS])
    for row in rows:
        w.writerow([f"{row['x']:g}"] + [f"{row.get(k, math.nan) / 1e3:.4f}" for k, _ in COLUMNS]
                   + [f"{row['fmep'] / 1e3:.2f}"]
                   + [f"{100 * row['shares'][k]:.1f}" for k, _ in COMPONENTS])
    return buf.getvalue()


def flame_markdown(param, rows: list[dict], title: str = "") -> str:
    """Yang's Table 7.1 layout: kW per component and speed, then fmep and the shares of the
    components without accessories."""
    head = [param.label] + [f"{label} kW" for _, label in COLUMNS] + ["fmep kPa",
                                                                     "shares B / VT / P %"]
    lines = [f"# FLAME friction by component{': ' + title if title else ''}", "",
             "| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for row in rows:
        cells = [f"{row['x']:g}"] + [f"{row.get(k, math.nan) / 1e3:.3f}" for k, _ in COLUMNS]
        cells.append(f"{row['fmep'] / 1e3:.1f}")
        cells.append(" / ".join(f"{100 * row['shares'][k]:.0f}" for k, _ in COMPONENTS))
        lines.append("| " + " | ".join(cells) + " |")
    lines += ["", "Accessories are a share of the components (FLAME: 25 %, i.e. 20 % of the "
              "total); shares are of the components without accessories.", ""]
    return "\n".join(lines)


def flame_plot(param, rows: list[dict], path: Path) -> Path:
    """Stacked friction power by component over the swept parameter."""
    from camtrain.report.plots import _pyplot

    plt = _pyplot()
    x = [row["x"] for row in rows]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    stacks = [[row.get(k, 0.0) / 1e3 for row in rows] for k, _ in COLUMNS[:4]]
    ax.stackplot(x, *stacks, labels=[label for _, label in COLUMNS[:4]], alpha=0.85)
    ax.plot(x, [row.get("flame_total", math.nan) / 1e3 for row in rows], "k.-", lw=1,
            label="total")
    ax.set_xlabel(param.label)
    ax.set_ylabel("friction power [kW]")
    ax.set_title("Engine friction by component (FLAME)")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def write_flame(out_dir: Path, params: list, records: list[dict], *, plots: bool = True,
                title: str = "") -> list[Path]:
    """flame.csv, flame.md and (with ``plots``) plots/flame_stacked.png, when the cases carry a
    FLAME total; nothing otherwise."""
    rows = flame_rows(params, records)
    if not rows:
        return []
    p = params[0]
    atomic_write(out_dir / "flame.csv", flame_csv(p, rows))
    atomic_write(out_dir / "flame.md", flame_markdown(p, rows, title))
    written = [out_dir / "flame.csv", out_dir / "flame.md"]
    if plots:
        written.append(flame_plot(p, rows, out_dir / "plots" / "flame_stacked.png"))
    return written
