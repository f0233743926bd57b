"""Plot panels of the elastic camshaft: bearing reactions over the cycle and their orders, each
lobe's contact load when the trains are coupled to the shaft, lobe deflection and twist. Same
contract as :mod:`camtrain.report.panels` (False when the result lacks the columns)."""
from __future__ import annotations

import re

import numpy as np

from camtrain.report.display import display_unit, typeset
from camtrain.report.panels import _finite, _fit_y
from camtrain.report.style import COLORS, angle_axis, finish_axes

_PALETTE = [COLORS["main"], COLORS["second"], COLORS["third"], COLORS["fourth"], COLORS["grey"],
            "#d08c00", "#00838f", "#ad1457"]


def _numbered(r, pattern: str) -> list[tuple[int, str]]:
    """(k, column) of every column matching ``pattern`` with one number group, sorted by k."""
    out = []
    for name in r.columns:
        m = re.fullmatch(pattern, name)
        if m:
            out.append((int(m.group(1)), name))
    return sorted(out)


def _curves(ax, ctx, r, columns, label: str, ylabel: str, values=None) -> bool:
    if not columns:
        return False
    data = []
    for i, (k, name) in enumerate(columns):
        y = values(name) if values else r.columns[name].values
        unit, factor = display_unit(name, r.columns[name].unit)
        y = _finite(np.asarray(y) * factor)
        ax.plot(ctx.theta, y, color=_PALETTE[i % len(_PALETTE)], label=f"{label} {k}")
        data.append(y)
    _fit_y(ax, data)
    ax.set_ylabel(f"{ylabel} [{typeset(unit) or '-'}]")
    angle_axis(ax)
    finish_axes(ax, legend=True)
    return True


def _magnitude(r):
    """Magnitude of an (x, y) column pair, given the x column's name."""
    def of(name):
        return np.hypot(r.columns[name].values, r.columns[name[:-1] + "y"].values)

    return of


def reactions(ax, r, ctx):
    """Magnitude of the load the shaft puts on each bearing."""
    return _curves(ax, ctx, r, _numbered(r, r"bearing_(\d+)_reaction_x"), "bearing",
                   "bearing load from the shaft", _magnitude(r))


def reaction_orders(ax, r, ctx):
    """Order amplitudes of every bearing's load vector, bars side by side per order."""
    found = {}
    for name, metric in r.metrics.items():
        m = re.fullmatch(r"bearing_(\d+)_reaction_order_(\d+)", name)
        if m:
            found.setdefault(int(m.group(1)), {})[int(m.group(2))] = metric.value
    if not found:
        return False
    bearings = sorted(found)
    orders = sorted({n for v in found.values() for n in v})
    width = 0.8 / len(bearings)
    for i, k in enumerate(bearings):
        x = np.array(orders) - 0.4 + (i + 0.5) * width
        ax.bar(x, [found[k].get(n, 0.0) for n in orders], width,
               color=_PALETTE[i % len(_PALETTE)], label=f"bearing {k}")
    ax.set_xticks(orders)
    ax.set_xlabel("order (per camshaft revolution)")
    ax.set_ylabel("amplitude [N]")
    finish_axes(ax, legend=True)
    return True


def _few(r, pattern: str) -> list[tuple[int, str]]:
    """The lobe columns to overlay on one panel: none past OVERLAID_LOBES (small multiples on
    the lobe sheet show them)."""
    columns = _numbered(r, pattern)
    return columns if len(columns) <= OVERLAID_LOBES else []


def lobe_loads(ax, r, ctx):
    """Each lobe's contact load when its elastic train is coupled to the shaft."""
    return _curves(ax, ctx, r, _few(r, r"lobe_(\d+)_load"), "lobe", "contact load")


def lobe_motion(ax, r, ctx):
    """Each lobe's shaft deflection (magnitude) over the cycle."""
    return _curves(ax, ctx, r, _few(r, r"lobe_(\d+)_deflection_x"), "lobe",
                   "shaft deflection", _magnitude(r))


def lobe_twist(ax, r, ctx):
    return _curves(ax, ctx, r, _few(r, r"lobe_(\d+)_twist"), "lobe",
                   "twist against the drive")


SHAFT_PANELS = {
    "shaft_reactions": ("Bearing loads from the elastic shaft", reactions),
    "shaft_orders": ("Orders of the bearing loads", reaction_orders),
    "lobe_loads": ("Contact load of every lobe's train", lobe_loads),
    "lobe_motion": ("Shaft deflection at the lobes", lobe_motion),
    "lobe_twist": ("Twist of the lobes", lobe_twist),
}


#: more lobes than this and their curves go to small multiples (``lobe_sheet``), not overlaid
OVERLAID_LOBES = 4

#: the small multiples of every lobe: (column pattern, label, magnitude of an x/y pair)
LOBE_ROWS = ((r"lobe_(\d+)_load", "contact load", False),
             (r"lobe_(\d+)_deflection_x", "shaft deflection", True),
             (r"lobe_(\d+)_twist", "twist against the drive", False))


def lobe_sheet(result, out_dir, *, deck=None, sha=None, formats=("png",)) -> list:
    """``sheet_lobes.<fmt>``: one row of small plots per lobe (contact load, shaft deflection,
    twist) when the shaft has more than OVERLAID_LOBES lobes, each on its own scale and the
    angle axis shared; empty otherwise."""
    from pathlib import Path

    from camtrain.report.canvas import save_sheet
    from camtrain.report.house import grid, house_page

    found = [(pattern, label, pair, _numbered(result, pattern))
             for pattern, label, pair in LOBE_ROWS]
    found = [f for f in found if f[3]]
    lobes = sorted({k for *_, cols in found for k, _ in cols})
    if len(lobes) <= OVERLAID_LOBES:
        return []
    theta = np.degrees(result["cam_angle"])
    with house_page(deck, result, "Every lobe: contact load, shaft deflection, twist", sha) as fig:
        spec = grid(fig, len(lobes), len(found), hspace=0.25, wspace=0.38)
        for row, k in enumerate(lobes):
            for col, (_, label, pair, columns) in enumerate(found):
                name = dict(columns).get(k)
                ax = fig.add_subplot(spec[row, col])
                if name is None:
                    ax.set_visible(False)
                    continue
                y = _magnitude(result)(name) if pair else result.columns[name].values
                unit, factor = display_unit(name, result.columns[name].unit)
                ax.plot(theta, _finite(np.asarray(y) * factor), color=COLORS["main"], lw=0.9)
                ax.set_xlim(-180.0, 180.0)
                ax.set_xticks(range(-180, 181, 90))
                ax.tick_params(labelsize=6.5)
                if row == 0:
                    ax.set_title(f"{label} [{typeset(unit) or '-'}]", fontsize=8.5)
                if col == 0:
                    ax.set_ylabel(f"lobe {k}", fontsize=8.5)
                if row == len(lobes) - 1:
                    ax.set_xlabel("cam angle from max. lift [deg]", fontsize=7.5)
                else:
                    ax.tick_params(labelbottom=False)
        Path(out_dir).mkdir(parents=True, exist_ok=True)
        return save_sheet(fig, Path(out_dir) / "sheet_lobes", formats)
