"""Valve events read off a shipped cam's lift law, as a [design] section (deck units)."""
from __future__ import annotations

import numpy as np

import camtrain.api as ct
from camtrain.assemble.lift_law import build_lift_law
from camtrain.lift.base import DEG, MM
from tests.conftest import DECKS


def read_events(deck: str, heights: tuple[float, ...], ramp: bool, headroom: float = 1.05):
    """(design section dict, lift law) of ``deck``: max lift, the angles where each flank
    passes each checking height, the ramp (height and duration, when the law has ramps) and
    acceleration, deceleration and jerk limits ``headroom`` times the cam's own peaks."""
    model = ct.load(DECKS / deck).model
    law = build_lift_law(model.lift)
    theta = np.arange(-180.0, 180.0, 0.005)
    c = law.evaluate(theta * DEG)
    lift, d2, d3 = c.lift / MM, c.d2 / MM * DEG ** 2, c.d3 / MM * DEG ** 3
    opening = [float(-theta[np.nonzero(lift >= h)[0][0]]) for h in heights]
    closing = [float(theta[np.nonzero(lift >= h)[0][-1]]) for h in heights]
    section = {"max_lift": float(lift.max()), "checking_heights": list(heights),
               "opening_angles": opening, "closing_angles": closing,
               "max_acceleration": headroom * float(d2.max()),
               "max_deceleration": headroom * float(-d2.min()),
               "max_jerk": headroom * float(np.abs(d3).max())}
    if ramp:
        r = model.lift.ramps
        section.update(ramp_height=r.opening_height / MM, ramp_length=r.opening_length / DEG)
    return section, law
