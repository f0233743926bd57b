"""Guide friction: follower/guide and valve/guide shear losses (Yang 1992 §3.3.2, eq. 3.29).

Full-film Couette model of a concentric oil-filled clearance: F = (eta V / c) pi d L, power F V,
averaged over the cam cycle (Yang: integrate over the cam angle, divide by 2 pi). V is the
reciprocating speed, omega dl/dtheta: the follower's own lift for a translating (bucket or domed)
follower, the valve lift for the stem. Yang expects full film for the Zeta follower (oil groove
and pressure feed); his boundary model of a tilted follower (eqs. 3.26-3.28) needs the lateral
force on the follower and is not wired here. Values are per valve train (one follower, one
valve); multiply by the number of valves for an engine (Yang's totals are for 8).
"""
from __future__ import annotations

import numpy as np

from camtrain.formulas import couette_guide_power, cycle_mean


def guide_powers(deck, kin) -> dict[str, np.ndarray]:
    """Per-angle dissipation [W] of each guide the deck describes."""
    g, eta, w = deck.guides, deck.lubricant.viscosity, kin.omega
    out = {"valve_guide": np.asarray(couette_guide_power(
        w * kin.valve_d1, eta, g.valve_stem_diameter, g.valve_guide_length,
        g.valve_guide_clearance), dtype=float)}
    if g.follower_diameter is not None and deck.mechanism.type in ("flat", "domed"):
        out["follower_guide"] = np.asarray(couette_guide_power(
            w * kin.cam_d1, eta, g.follower_diameter, g.follower_guide_length,
            g.follower_guide_clearance), dtype=float)
    return out


def run(deck, state) -> None:
    kin, res = state.objects["kinematics"], state.result
    powers = guide_powers(deck, kin)
    total = 0.0
    for name in ("follower_guide", "valve_guide"):
        if name not in powers:
            continue
        what = name.replace("_", "/")
        res.add_column(f"{name}_power", powers[name], "W",
                       f"{what} Couette shear power (Yang 1992 eq. 3.29)")
        mean = float(cycle_mean(powers[name]))
        total += mean
        res.add_metric(f"{name}_power_mean", mean, "W",
                       f"cycle-mean {what} friction power, one valve train (Yang 1992 §3.3.2)")
    res.add_metric("guide_power_mean", total, "W", "cycle-mean guide friction power, one "
                   "valve train (not included in power_loss_mean)")
    if deck.guides.follower_diameter is not None and "follower_guide" not in powers:
        res.warn("guides.follower_*: a pivoted follower has no guide; follower/guide friction "
                 "skipped")
