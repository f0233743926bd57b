"""Events an engineer looks for on a cycle, found from the products the run's effects made.

Zero-entrainment points, loss of contact (bounce), boundary-lubrication regions and concave flanks.
Each finder runs when the plan made its product (``catalogue.planned_products``: the contact
kinematics, the contact load, the film), so partial runs report what they can.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from camtrain.result import Result


@dataclass
class Findings:
    zero_entrainment: list[float] = field(default_factory=list)     # cam angles [rad]
    loss_of_contact: list[tuple[float, float]] = field(default_factory=list)  # [rad] ranges
    clearance: list[tuple[float, float]] = field(default_factory=list)  # no load on base circle
    boundary: list[tuple[float, float]] = field(default_factory=list)
    concave: list[tuple[float, float]] = field(default_factory=list)

    def messages(self, already: list[str] | None = None) -> list[str]:
        """Warnings for the findings, leaving out those the physics already warned about."""
        said = " ".join(already or []).lower()
        out = []
        if self.loss_of_contact:
            out.append("valve bounce: the contact load is zero or negative at "
                       + ranges_text(self.loss_of_contact))
        if self.concave:
            out.append("concave cam flank (negative cam radius) at " + ranges_text(self.concave)
                       + "; check the grinding-wheel radius")
        if self.zero_entrainment:
            out.append("zero entrainment (quasi-static film collapses) at "
                       + ", ".join(f"{math.degrees(a):+.1f}°" for a in self.zero_entrainment))
        if self.boundary:
            out.append("boundary lubrication (λ < 1) at " + ranges_text(self.boundary)
                       + " (λ = film / lubricant.roughness; lubricant.viscosity raises the film)")
        topics = {"valve bounce": ("bounce", "loses contact", "loss of contact"),
                   "concave": ("concave",), "zero entrainment": ("entrainment",),
                   "boundary": ("boundary lubrication",)}
        return [m for m in out
                if not any(m.startswith(t) and any(k in said for k in keys)
                           for t, keys in topics.items())]

    def as_dict(self) -> dict:
        def rng(r):
            return [[round(math.degrees(a), 3), round(math.degrees(b), 3)] for a, b in r]

        return {"zero_entrainment_deg": [round(math.degrees(a), 3) for a in self.zero_entrainment],
                "loss_of_contact_deg": rng(self.loss_of_contact),
                "no_contact_base_circle_deg": rng(self.clearance),
                "boundary_lubrication_deg": rng(self.boundary),
                "concave_deg": rng(self.concave)}


def ranges_text(ranges: list[tuple[float, float]]) -> str:
    return ", ".join(f"{math.degrees(a):+.1f}° … {math.degrees(b):+.1f}°" for a, b in ranges)


def _made(result: Result) -> frozenset[str]:
    """The products the run's effects made (the plan's declarations)."""
    from camtrain.catalogue import planned_products

    return planned_products(result.plan)


def entrainment(result: Result) -> np.ndarray | None:
    """The entrainment velocity, when the run formed the contact kinematics."""
    return result["entrainment"] if "TrainKinematics" in _made(result) else None


def in_contact(result: Result) -> np.ndarray | None:
    """Where the cam carries a load, when the run computed the contact load."""
    return result["load"] > 0.0 if "ContactLoad" in _made(result) else None


def central_film(result: Result) -> bool:
    """Whether the run's film has a central thickness beside its minimum (the film of a
    ContactFilm with a formula or a transient law that gives one). What the contact found, not
    a deck option the plan reads: without cam.width a loaded line contact has the load-free
    Blok film, which has none, and a point contact the EHL film, which has one; the contact's
    geometry decides once the kinematics ran."""
    return "ContactFilm" in _made(result) and "film_central" in result.columns


def find(result: Result) -> Findings:
    """The findings of the effects that ran: zero entrainment and concave flanks from the
    contact kinematics, loss of contact from the contact load, the boundary regime from the
    film (each read from the columns the effect producing it writes)."""
    f = Findings()
    made = _made(result)
    if "TrainKinematics" not in made:
        return f
    theta = result["cam_angle"]
    f.zero_entrainment = zero_crossings(theta, result["entrainment"])
    f.concave = true_ranges(theta, result["cam_radius"] < 0.0)
    if "ContactLoad" in made:
        # Unloaded stretches that reach the base circle are valve clearance (by design); those
        # wholly inside the lift event are the follower leaving the cam: bounce.
        lift = result["lift"]
        for a, b in true_ranges(theta, result["load"] <= 0.0):
            span = (theta >= a) & (theta <= b)
            on_base = bool(np.any(lift[span] <= 1e-9))
            (f.clearance if on_base else f.loss_of_contact).append((a, b))
    if "ContactFilm" in made:
        thin = result["lambda"] < 1.0
        contact = in_contact(result)
        f.boundary = true_ranges(theta, thin if contact is None else thin & contact)
    return f


def zero_crossings(theta: np.ndarray, y: np.ndarray) -> list[float]:
    """Angles where y changes sign, linearly interpolated (touching zero counts once)."""
    y = np.asarray(y, dtype=float)
    ok = np.isfinite(y)
    out = []
    for i in range(len(y) - 1):
        a, b = y[i], y[i + 1]
        if not (ok[i] and ok[i + 1]) or a == b:
            continue
        if a == 0.0 and i > 0 and y[i - 1] * b < 0:
            out.append(float(theta[i]))
        elif a * b < 0:
            out.append(float(theta[i] + (theta[i + 1] - theta[i]) * a / (a - b)))
    return out


def true_ranges(theta: np.ndarray, mask: np.ndarray) -> list[tuple[float, float]]:
    """Contiguous runs of mask as (first angle, last angle) pairs."""
    mask = np.asarray(mask, dtype=bool)
    out, start = [], None
    for i, m in enumerate(mask):
        if m and start is None:
            start = i
        if not m and start is not None:
            out.append((float(theta[start]), float(theta[i - 1])))
            start = None
    if start is not None:
        out.append((float(theta[start]), float(theta[-1])))
    return out
