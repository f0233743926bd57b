"""Hertz effect: contact half-width and maximum pressure from the contact load.

Line contact (flat and pivoted followers, cylindrical pads; radius_y = inf): Ball (1988) eqs.
3.8-3.10 over the cam width. Point contact (spherical domed follower): exact Hertz ellipse
(Hamrock & Dowson 1981 ch. 3) or Ball's eq. 3.7 (``tribology.hertz = "ball_1988"``).
Angles without load give zero size and pressure; angles where the contact is not Hertzian
(equivalent radius <= 0 or infinite) give NaN with a warning.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from camtrain.formulas import hertz_line, hertz_point, hertz_point_max_pressure, reduced_modulus


def modulus(deck) -> float:
    m = deck.materials
    return float(reduced_modulus(m.cam_modulus, m.cam_poisson, m.follower_modulus,
                                 m.follower_poisson))


def is_line(kin) -> bool:
    return bool(np.all(np.isinf(kin.radius_y)))


def contact_hertz(deck, kin, load) -> dict:
    """Per-angle Hertz fields: ``pmax`` [Pa], ``half_width`` [m] (along the rolling direction),
    ``half_length`` [m] (transverse: half the cam width for a line contact), ``bad`` mask."""
    load = np.asarray(load, dtype=float)
    E_r = modulus(deck)
    R, Ry = kin.radius_x, kin.radius_y
    line = is_line(kin)
    good_r = (R > 0.0) & np.isfinite(R) & (line | ((Ry > 0.0) & np.isfinite(Ry)))
    use = good_r & (load > 0.0)
    pmax, bx = np.zeros_like(load), np.zeros_like(load)
    by = np.zeros_like(load)
    if np.any(use):
        if line:
            h = hertz_line(load[use], R[use], E_r, L=deck.cam.width)
            pmax[use], bx[use] = h.max_pressure, h.half_width
            by[use] = 0.5 * deck.cam.width
        else:
            h = hertz_point(load[use], R[use], Ry[use], E_r)
            bx[use], by[use], pmax[use] = h.a_x, h.a_y, h.max_pressure
            if deck.tribology.hertz == "ball_1988":
                pmax[use] = hertz_point_max_pressure(load[use], R[use], Ry[use], E_r,
                                                     method="ball_1988")
    bad = ~good_r & (load > 0.0)
    pmax[bad] = bx[bad] = by[bad] = np.nan
    return {"pmax": pmax, "half_width": bx, "half_length": by, "bad": bad, "line": line}


def closing_deck(deck):
    """The deck as seen by the closing pair of a desmodromic train: its own cam width."""
    c = deck.mechanism.closing
    if c is None or c.width is None:
        return deck
    return replace(deck, cam=replace(deck.cam, width=c.width))


def pairs(deck, state) -> list[tuple[str, object, object, object]]:
    """(column prefix, deck, kinematics, load) of each loaded cam/follower pair: the only pair,
    or the opening pair and then the closing pair ("closing_") of a desmodromic train."""
    out = [("", deck, state.objects["kinematics"], state.objects.get("load"))]
    closing, load = state.objects.get("kinematics_closing"), state.objects.get("closing_load")
    if closing is not None and load is not None:
        out.append(("closing_", closing_deck(deck), closing, load))
    return out


def label(prefix: str) -> str:
    return " (closing pair)" if prefix else ""


def run(deck, state) -> None:
    for prefix, pdeck, kin, load in pairs(deck, state):
        state.objects[prefix + "hertz"] = run_pair(pdeck, kin, load, state.result, prefix)


def run_pair(deck, kin, load, res, prefix: str = "") -> dict:
    hz = contact_hertz(deck, kin, np.maximum(load, 0.0))
    tag = label(prefix)
    res.add_column(prefix + "hertz_pmax", hz["pmax"], "Pa", "maximum Hertz contact pressure" + tag)
    res.add_column(prefix + "hertz_half_width", hz["half_width"], "m",
                   "Hertz half-width along the rolling direction" + tag)
    if not hz["line"]:
        res.add_column(prefix + "hertz_half_length", hz["half_length"], "m",
                       "Hertz semi-axis across the rolling direction" + tag)
    if np.any(hz["bad"]):
        res.warn(f"Hertz contact undefined{tag} (equivalent radius <= 0 or infinite) at "
                 f"{int(hz['bad'].sum())} loaded angles; NaN there")
    p = np.where(np.isnan(hz["pmax"]), -np.inf, hz["pmax"])
    i = int(np.argmax(p))
    res.add_metric(prefix + "hertz_max", hz["pmax"][i], "Pa",
                   "largest Hertz pressure over the cycle" + tag, kin.theta[i])
    k = int(np.argmax(kin.valve_lift))
    res.add_metric(prefix + "hertz_at_max_lift", hz["pmax"][k], "Pa",
                   "Hertz pressure at the maximum-lift position (Ball Tables 5.1-5.3)" + tag,
                   kin.theta[k])
    return hz
