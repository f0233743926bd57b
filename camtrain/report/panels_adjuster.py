"""Panels of the hydraulic lash adjuster's sheet (docs/lash_adjusters.md): chamber pressure,
plunger extension, valve lift lost, the check-valve and leak-down flows and, with the dynamic
check ball, its lift. The plan declares them when the dynamics effect marched a train with an
adjuster (EffectSpec.model_panels, from the model its step records)."""
from __future__ import annotations

import numpy as np

from camtrain.report.panels import _cycle, shown


def adjuster_pressure(ax, r, ctx):
    """The lash adjuster's chamber pressure (gauge)."""
    return _cycle(ax, r, ctx, ["hla_pressure"], ylabel="chamber pressure")


def adjuster_extension(ax, r, ctx):
    """The adjuster's plunger extension from full collapse, its axis on the curve's own range
    (micrometres of travel on a rest extension of a fraction of a millimetre)."""
    if not _cycle(ax, r, ctx, ["hla_extension"], ylabel="plunger extension"):
        return False
    y = shown(r, "hla_extension")[0]
    lo, hi = float(np.nanmin(y)), float(np.nanmax(y))
    pad = 0.05 * (hi - lo) if hi > lo else max(abs(hi), 1.0) * 1e-3
    ax.set_ylim(lo - pad, hi + pad)
    return True


def adjuster_lift_loss(ax, r, ctx):
    """Valve lift lost to the adjuster against the constant-load adjuster."""
    return _cycle(ax, r, ctx, ["valve_lift_loss"], ylabel="valve lift lost", zero=True)


def check_flow(ax, r, ctx):
    """Flows into the chamber through the check valve and out through the annulus."""
    return _cycle(ax, r, ctx, ["hla_check_flow", "hla_leak_flow"], ylabel="flow", zero=True,
                  legend=True, labels={"hla_check_flow": "check valve, in",
                                       "hla_leak_flow": "annulus, out"})


def check_lift(ax, r, ctx):
    """The check ball's lift off its seat (check_valve = "ball")."""
    return _cycle(ax, r, ctx, ["hla_check_lift"], ylabel="check ball lift")


ADJUSTER_PANELS = {
    "adjuster_pressure": ("Lash adjuster chamber pressure", adjuster_pressure),
    "adjuster_extension": ("Lash adjuster plunger extension", adjuster_extension),
    "adjuster_lift_loss": ("Valve lift lost to the adjuster", adjuster_lift_loss),
    "check_flow": ("Check valve and leak-down flows", check_flow),
    "check_lift": ("Check ball lift", check_lift),
}
