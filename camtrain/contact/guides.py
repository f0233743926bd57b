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

from dataclasses import dataclass

import numpy as np

from camtrain.formulas import couette_guide_power


@dataclass(frozen=True)
class GuideLosses:
    """Per-angle dissipation [W] of each guide of one valve train (follower guide only for a
    translating follower)."""

    valve_guide: np.ndarray
    follower_guide: np.ndarray | None = None


def guide_losses(deck, kin) -> GuideLosses:
    """The guide losses of the deck's ``[guides]`` with the main pair's kinematics."""
    g, eta, w = deck.guides, deck.lubricant.viscosity, kin.omega
    valve = np.asarray(couette_guide_power(w * kin.valve_d1, eta, g.valve_stem_diameter,
                                           g.valve_guide_length, g.valve_guide_clearance),
                       dtype=float)
    follower = None
    if g.follower_diameter is not None and deck.mechanism.type in ("flat", "domed"):
        follower = np.asarray(couette_guide_power(
            w * kin.cam_d1, eta, g.follower_diameter, g.follower_guide_length,
            g.follower_guide_clearance), dtype=float)
    return GuideLosses(valve_guide=valve, follower_guide=follower)
