"""Friction effect: cam/follower friction force and coefficient around the cycle.

Isothermal Newtonian shear of a Barus fluid over the Hertz zone with the sliding speed and the
central film (Ball 1988 eqs. 4.4-4.7, exact integral; Yang 1992 eq. 3.24 for an ellipse), limited
by boundary friction mu_b W (Ball §4.2.3.4; ``tribology.friction_model``: cap, lambda or
lambda_cap). Where the central film is not available (Blok film) the minimum film is used.
"""
from __future__ import annotations

import numpy as np

from camtrain.effects.film import contact_film
from camtrain.effects.hertz import contact_hertz
from camtrain.formulas import ball_1988_friction, yang_1992_friction


def contact_friction(deck, kin, load) -> dict:
    """Hertz, film and friction force [N] for a per-angle load (used by the load iteration)."""
    load = np.maximum(np.asarray(load, dtype=float), 0.0)
    hz = contact_hertz(deck, kin, load)
    film = contact_film(deck, kin, load)
    h = film["central"] if film["central"] is not None else film["min"]
    lub, trib = deck.lubricant, deck.tribology
    use = (load > 0.0) & np.isfinite(h) & np.isfinite(hz["pmax"])
    force = np.zeros_like(load)
    if np.any(use):
        common = dict(u_s=np.abs(kin.sliding[use]), h=h[use], eta0=lub.viscosity,
                      alpha=lub.pressure_viscosity, p_max=hz["pmax"][use], W=load[use],
                      mu=trib.boundary_friction, model=trib.friction_model,
                      sigma=lub.roughness)
        if hz["line"]:
            force[use] = ball_1988_friction(b=hz["half_width"][use], L=deck.cam.width, **common)
        else:
            force[use] = yang_1992_friction(a_x=hz["half_width"][use],
                                            a_y=hz["half_length"][use], **common)
    return {"friction": force, "hertz": hz, "film": film, "used": use}


def run(deck, state) -> None:
    kin, load = state.objects["kinematics"], np.maximum(state.objects["load"], 0.0)
    res = state.result
    out = contact_friction(deck, kin, load)
    force = out["friction"]
    pos = load > 0.0
    mu = np.zeros_like(load)
    mu[pos] = force[pos] / load[pos]
    res.add_column("friction_force", force, "N",
                   f"cam/follower friction force ({deck.tribology.friction_model} model)")
    res.add_column("friction_coefficient", mu, "-", "friction coefficient F/W (0 unloaded)")
    capped = pos & (force >= deck.tribology.boundary_friction * load * (1.0 - 1e-12))
    res.add_metric("boundary_fraction", capped.sum() / max(int(pos.sum()), 1), "-",
                   "share of loaded angles at the boundary friction limit")
    if not np.all(np.isfinite(force)):
        res.warn("friction force not finite at some angles (uncapped lambda model)")
    state.objects["friction"] = force
