"""Plot panels of the elastic camshaft: bearing reactions over the cycle and their orders, each
lobe's contact load when the trains are coupled to the shaft, lobe deflection and twist. Same
contract as :mod:`camtrain.report.panels` (False when the result lacks the columns)."""
from __future__ import annotations

import re

import numpy as np

from camtrain.report.display import display_unit
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
    ax.set_ylabel(f"{ylabel} [{unit or '-'}]")
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


def lobe_loads(ax, r, ctx):
    """Each lobe's contact load when its elastic train is coupled to the shaft."""
    return _curves(ax, ctx, r, _numbered(r, r"lobe_(\d+)_load"), "lobe", "contact load")


def lobe_motion(ax, r, ctx):
    """Each lobe's shaft deflection (magnitude) over the cycle."""
    return _curves(ax, ctx, r, _numbered(r, r"lobe_(\d+)_deflection_x"), "lobe",
                   "shaft deflection", _magnitude(r))


def lobe_twist(ax, r, ctx):
    return _curves(ax, ctx, r, _numbered(r, r"lobe_(\d+)_twist"), "lobe",
                   "twist against the drive")


SHAFT_PANELS = {
    "shaft_reactions": ("Bearing loads from the elastic shaft", reactions),
    "shaft_orders": ("Orders of the bearing loads", reaction_orders),
    "lobe_loads": ("Contact load of every lobe's train", lobe_loads),
    "lobe_motion": ("Shaft deflection at the lobes", lobe_motion),
    "lobe_twist": ("Twist of the lobes", lobe_twist),
}
