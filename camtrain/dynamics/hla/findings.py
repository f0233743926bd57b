"""What an adjuster did over the periodic revolution: plunger travel per event (collapse during
the lift; the oil refilled through the check valve and leaked down through the annulus, as
plunger travel), valve lift lost against the constant-load adjuster, the
valve's opening and closing at a checking height, and pump-up (the valve held off its seat on the
base circle because the adjuster extended after a separation). Plain rows and numbers: the
dynamics effect writes them."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["AdjusterFindings", "adjuster_findings", "crossings", "PUMP_UP_LIFT"]

#: valve lift on the base circle [m] above which the valve counts as held open (pump-up): well
#: above the seat's compression (a few µm), well below any checking height
PUMP_UP_LIFT = 20e-6


@dataclass(frozen=True)
class AdjusterFindings:
    """``collapse`` [m]: the plunger's largest collapse below its extension at the valve's
    opening (leak-down and the chamber's compression together); ``refill`` [m]: the oil drawn
    through the check valve over the revolution, as plunger travel (volume / plunger area);
    ``leakdown`` [m]: the oil pushed out through the annulus over it, alike (in the periodic
    state the two balance: the chamber's mass balance); ``lift_loss``
    [m] per angle (constant-load adjuster's valve lift minus this one's); ``opening``,
    ``closing`` [rad] at the checking height (NaN when not crossed), and the constant-load
    adjuster's; ``held_open`` [m]: the valve's lowest lift on the base circle (pump-up when
    above :data:`PUMP_UP_LIFT`), ``extension_gain`` [m] of the plunger there above its rest."""

    collapse: float
    refill: float
    leakdown: float
    lift_loss: np.ndarray
    opening: float
    closing: float
    opening_rigid: float
    closing_rigid: float
    held_open: float
    extension_gain: float

    @property
    def pumped_up(self) -> bool:
        return self.held_open > PUMP_UP_LIFT


def crossings(theta: np.ndarray, lift: np.ndarray, height: float) -> tuple[float, float]:
    """The first upward and the last downward crossing [rad] of ``height`` by ``lift`` around
    its maximum (linear between grid angles; NaN when the lift never reaches it)."""
    peak = int(np.argmax(lift))
    rolled = np.roll(lift, lift.size // 2 - peak)
    angles = np.roll(theta, lift.size // 2 - peak)
    above = rolled >= height
    if not above.any() or above.all():
        return math.nan, math.nan
    mid = lift.size // 2
    i = mid
    while i > 0 and above[i - 1]:
        i -= 1
    j = mid
    while j < lift.size - 1 and above[j + 1]:
        j += 1
    return (_between(angles, rolled, i - 1, i, height) if i > 0 else math.nan,
            _between(angles, rolled, j, j + 1, height) if j < lift.size - 1 else math.nan)


def _between(angles, lift, a, b, height):
    step = (angles[b] - angles[a] + math.pi) % (2 * math.pi) - math.pi
    s = (height - lift[a]) / (lift[b] - lift[a])
    return float((angles[a] + s * step + math.pi) % (2 * math.pi) - math.pi)


def adjuster_findings(resp, rigid, model, height: float) -> AdjusterFindings:
    """Findings of the response ``resp`` (a TrainResponse with ``hydraulic``) against
    ``rigid``, the same train with the constant-load adjuster; ``height`` [m] the checking
    height of the valve lift."""
    v = model.valve
    x = resp.hydraulic[3]
    lift = resp.u[v]
    open_ = ~(resp.contact_force[1] > 0.0)
    collapse = 0.0
    if open_.any() and not open_.all():
        # from the valve's first opening (a seated -> open sample) to the lowest extension
        first = int(np.flatnonzero(open_ & ~np.roll(open_, 1))[0])
        collapse = float(x[first] - np.min(np.where(open_, x, np.inf)))
    # the refill is a volume, summed over the march's steps (resp.hydraulic rows 4, 5): it comes
    # through the check valve in the pressure dips of the valve's landing, often while the
    # valve bounces, not only while it rests closed
    area = model.series.adjuster.area
    refill = float(np.sum(resp.hydraulic[4])) / area
    leakdown = float(np.sum(resp.hydraulic[5])) / area
    base = np.asarray(resp.cam[0]) <= 1e-9 * max(float(np.max(resp.cam[0])), 1e-300)
    held = float(np.min(lift[base])) if base.any() else 0.0
    gain = float(np.min(x[base]) - model.series.adjuster.rest_extension) if base.any() else 0.0
    opening, closing = crossings(resp.theta, lift, height)
    opening_r, closing_r = crossings(rigid.theta, rigid.u[v], height)
    return AdjusterFindings(collapse, refill, leakdown, rigid.u[v] - lift, opening, closing,
                            opening_r, closing_r, held, gain)


def adjuster_rows(resp, found: AdjusterFindings, model, height: float):
    """Columns (name, values, unit, description) and metrics (name, value, unit, description)
    of the adjuster, and its warnings (text)."""
    h = resp.hydraulic
    cols = (
        ("hla_pressure", h[0], "Pa", "adjuster chamber pressure (gauge)"),
        ("hla_check_flow", h[1], "m^3/s", "flow through the adjuster's check valve into the "
         "chamber (negative: back out past a check ball not yet seated)"),
        ("hla_check_open", (h[1] > 0.0).astype(float) if model.series.adjuster.check_valve ==
         "quasi_static" else (h[6] > 0.0).astype(float), "-", "1 while the check valve is open"),
        ("hla_leak_flow", h[2], "m^3/s", "leak-down flow out of the chamber through the "
         "plunger annulus (negative: drawn in)"),
        ("hla_extension", h[3], "m", "plunger extension from full collapse"),
        ("valve_lift_loss", found.lift_loss, "m", "valve lift of the train with the "
         "constant-load adjuster minus this one's (lost to the adjuster)"),
    )
    if model.series.adjuster.check_valve == "ball":
        cols += (("hla_check_lift", h[6], "m", "check ball's lift off its seat"),)
    i = int(np.argmax(resp.u[model.valve]))
    mets = [
        ("hla_pressure_max", float(np.max(h[0])), "Pa", "highest chamber pressure (gauge)"),
        ("hla_collapse", found.collapse, "m", "plunger collapse per event (below its extension "
         "at the valve's opening)"),
        ("hla_refill", found.refill, "m", "oil drawn through the check valve per revolution "
         "(net), as plunger travel (volume / plunger area)"),
        ("hla_leakdown", found.leakdown, "m", "oil pushed out through the plunger annulus per "
         "revolution, as plunger travel (balances the refill in the periodic state)"),
        ("valve_lift_loss_at_max_lift", float(found.lift_loss[i]), "m", "valve lift lost to the "
         "adjuster at maximum lift"),
        ("valve_lift_loss_max", float(np.max(found.lift_loss)), "m", "largest valve lift lost "
         "to the adjuster"),
        ("hla_held_open", found.held_open, "m", "lowest valve lift on the base circle (pump-up "
         "when the valve stays open)"),
    ]
    if model.series.adjuster.check_valve == "ball":
        from camtrain.dynamics.hla.element import ball_cracking_pressure

        mets.append(("hla_check_cracking_pressure", ball_cracking_pressure(model.series.adjuster), "Pa",
                     "check ball's cracking pressure (spring preload over seat area)"))
        mets.append(("hla_check_frequency", model.series.adjuster.ball_frequency() / (2.0 * math.pi), "Hz",
                     "check ball's natural frequency on its spring, sqrt(k/m)/(2 pi)"))
        mets.append(("hla_check_lift_max", float(np.max(h[6])), "m", "check ball's largest "
                     "lift (at its stop: the valve fully open)"))
    for name, value, rigid in (("valve_opening_check", found.opening, found.opening_rigid),
                               ("valve_closing_check", found.closing, found.closing_rigid)):
        mets.append((name, value, "rad", f"valve at the checking height {height * 1e3:g} mm"))
        mets.append((name + "_shift", value - rigid, "rad", "against the constant-load "
                     "adjuster (positive: later)"))
    warns = []
    if found.pumped_up:
        warns.append(f"lash adjuster pump-up: the valve stays {found.held_open * 1e3:.3g} mm "
                     f"open on the base circle (the plunger extended "
                     f"{found.extension_gain * 1e3:.3g} mm beyond its rest); the cam lost the "
                     "follower and the adjuster took up the gap")
    return cols, mets, warns
