"""Friction of a solved steady EHL line contact (:class:`.ehl_line.EHLSolution`).

Shear stress on the surfaces (isothermal; the Couette and Poiseuille parts of the film flow;
Hamrock, Schmid & Jacobson 2004, *Fundamentals of Fluid Film Lubrication*, shear stress of a
1-D film)::

    tau = tau_couette(eta (u2 - u1)/h) -/+ (h/2) dp/dx

with tau_couette = eta gamma_dot (``newtonian``, default) or the Eyring law
tau_0 asinh(eta gamma_dot / tau_0) (``eyring``; Johnson & Tevaarwerk 1977, Proc. R. Soc. A 356:215)
with the Eyring stress tau_0 [Pa]. The integral runs over the full film, from the inlet to the
cavitation point (the first node after the pressure maximum where p returns to 0): in the
cavitated outlet the film is ruptured into streamers and carries no shear in this model.
With the ``half_sommerfeld`` exit condition the pressure here is the solution's ``p``, the
solved one's positive part, so the film ends where the full-Sommerfeld pressure turns negative.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

SHEAR_LAWS = ("newtonian", "eyring")


@dataclass(frozen=True)
class EHLFriction:
    """Friction per unit length [N/m]: the sliding (Couette) part, the rolling (Poiseuille)
    part (its sign differs on the two surfaces), the coefficient mu = |sliding| / w, the law."""

    sliding: float
    rolling: float
    coefficient: float
    law: str


def _film_end(p: np.ndarray) -> int:
    after = np.flatnonzero(p[int(np.argmax(p)):] <= 0.0)
    return p.size if after.size == 0 else int(np.argmax(p)) + int(after[0]) + 1


def ehl_friction(solution, law: str = "newtonian", eyring_stress: float | None = None
                 ) -> EHLFriction:
    """Friction of ``solution``; ``eyring_stress`` [Pa] is required with ``law = "eyring"``."""
    if law not in SHEAR_LAWS:
        raise ValueError(f"shear law {law!r}: expected one of {SHEAR_LAWS}")
    if law == "eyring" and not (eyring_stress and eyring_stress > 0):
        raise ValueError("the Eyring law needs eyring_stress > 0 [Pa]")
    c = solution.contact
    end = _film_end(solution.p)
    x, h, eta = solution.x[:end], solution.h[:end], solution.eta[:end]
    rate = (c.u2 - c.u1) / h
    tau = eta * rate
    if law == "eyring":
        tau = eyring_stress * np.arcsinh(tau / eyring_stress)
    sliding = float(np.trapezoid(tau, x))
    rolling = float(np.trapezoid(0.5 * h * np.gradient(solution.p[:end], x), x))
    return EHLFriction(sliding, rolling, abs(sliding) / c.w, law)
