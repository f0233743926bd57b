"""The cam contact's own stiffness: the Hertz line contact's load-approach relation.

Two elastic cylinders with parallel axes, radii R1 and R2, pressed together by a load P per unit
length, approach each other (the distance between their axes shrinks) by

    delta = P/pi [ c1 (2 ln(4 R1 / b) - 1) + c2 (2 ln(4 R2 / b) - 1) ],      c_i = (1 - nu_i^2) / E_i

with b the Hertz half-width, b = sqrt(4 P R / (pi E*)), 1/R = 1/R1 + 1/R2, 1/E* = c1 + c2
(Johnson 1985, Contact Mechanics, Hertz theory of two-dimensional contact, the compression of
cylinders in line contact; the reference notes name this relation for the ``hertz_line`` contact,
wave2 §1.1 A-M2, as an external source: no seed prints it). The half-width is Ball's (1988) eq.
3.9 with E' = 2 E*. The relation is nearly linear: the stiffness dW/d delta grows only with
the logarithm of the load (about 2e8 N/m for the Zeta cam, 11 mm wide, at 500 N), and it is zero
at zero load, so the contact is softest where it opens and closes.

For the valve train, R1 is the cam's radius of curvature at the contact (it changes with the
cam angle), R2 the follower's radius in the rolling direction (a domed, crowned or roller
follower; a flat face has no radius and the relation has no meaning there), and the load W = P L
acts over the cam width L. A linear spring ``k_series`` [N/m] (a follower or lash-adjuster
stiffness, or the whole train when there is no follower node) can sit in series with the
contact: its deflection W / k_series adds to the approach.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["HertzLineLaw", "line_contact_approach", "line_contact_compliance"]


def line_contact_approach(w: float, r1: float, r2: float, c1: float, c2: float) -> float:
    """Approach [m] of two cylinders' axes under a load ``w`` [N/m] per unit length (Johnson
    1985, two-dimensional Hertz contact of cylinders); radii r1, r2 [m] > 0, compliances
    c_i = (1 - nu_i^2)/E_i [1/Pa]."""
    if w <= 0.0:
        return 0.0
    r = r1 * r2 / (r1 + r2)
    b = math.sqrt(4.0 * w * r / (math.pi / (c1 + c2)))
    return w / math.pi * (c1 * (2.0 * math.log(4.0 * r1 / b) - 1.0)
                          + c2 * (2.0 * math.log(4.0 * r2 / b) - 1.0))


def line_contact_compliance(w: float, r1: float, r2: float, c1: float, c2: float) -> float:
    """d(approach)/dw [m^2/N] of ``line_contact_approach`` (the log's derivative included:
    b grows as sqrt(w)): 2/pi [c1 (ln(4 R1/b) - 1) + c2 (ln(4 R2/b) - 1)]."""
    r = r1 * r2 / (r1 + r2)
    b = math.sqrt(4.0 * max(w, 1e-300) * r / (math.pi / (c1 + c2)))
    return 2.0 / math.pi * (c1 * (math.log(4.0 * r1 / b) - 1.0)
                            + c2 * (math.log(4.0 * r2 / b) - 1.0))


@dataclass(frozen=True)
class HertzLineLaw:
    """The cam contact as a Hertz line contact, referred to the valve. ``c1``/``c2`` the cam's
    and follower's compliances (1 - nu^2)/E [1/Pa], ``length`` the cam width [m],
    ``follower_radius`` R2 [m], ``k_series`` [N/m] a valve-referred linear spring in series
    (inf: none). Per cam angle come the cam's radius of curvature R1 [m] and the load ratio
    ``ratio`` = W / F_valve (1 for a direct-acting follower): the valve-referred force F puts
    the load W = ratio F on the contact, whose approach moves the valve by ratio x delta."""

    c1: float
    c2: float
    length: float
    follower_radius: float
    k_series: float = math.inf
    base_radius: float = math.inf   #: the cam's radius on the base circle [m] (rest state)
    base_ratio: float = 1.0         #: load ratio on the base circle

    def deflection(self, force: float, cam_radius: float, ratio: float = 1.0) -> float:
        """Valve-referred deflection [m] of contact and series spring under a valve-referred
        force [N]."""
        delta = line_contact_approach(force * ratio / self.length, cam_radius,
                                      self.follower_radius, self.c1, self.c2)
        series = force / self.k_series if math.isfinite(self.k_series) else 0.0
        return delta * ratio + series

    def compliance(self, force: float, cam_radius: float, ratio: float = 1.0) -> float:
        """Valve-referred tangent compliance d delta_v / dF [m/N] at a valve-referred force."""
        comp = line_contact_compliance(force * ratio / self.length, cam_radius,
                                       self.follower_radius, self.c1, self.c2)
        comp *= ratio * ratio / self.length
        if math.isfinite(self.k_series):
            comp += 1.0 / self.k_series
        return comp

    def stiffness(self, force: float, cam_radius: float, ratio: float = 1.0) -> float:
        """Valve-referred tangent stiffness dF / d delta_v [N/m] at a valve-referred force."""
        return 1.0 / self.compliance(force, cam_radius, ratio)

    def force(self, deflection: float, cam_radius: float, ratio: float = 1.0) -> float:
        """Valve-referred force [N] at a valve-referred deflection [m] (Newton on the force;
        the relation is nearly linear, so a few iterations reach round-off)."""
        if deflection <= 0.0:
            return 0.0
        f = deflection * self.stiffness(100.0, cam_radius, ratio)
        for _ in range(60):
            g = self.deflection(f, cam_radius, ratio) - deflection
            f_new = f - g / self.compliance(f, cam_radius, ratio)
            if f_new <= 0.0:
                f_new = 0.5 * f
            if abs(f_new - f) <= 1e-13 * f_new:
                return f_new
            f = f_new
        return f

    def at_rest(self, force: float) -> float:
        """Valve-referred deflection [m] on the base circle under a valve-referred force."""
        return self.deflection(force, self.base_radius, self.base_ratio) if force > 0 else 0.0

    def as_array(self):
        """(c1, c2, length, follower_radius, k_series) for the compiled kernel (k_series 0:
        none)."""
        import numpy as np

        k = self.k_series if math.isfinite(self.k_series) else 0.0
        return np.array([self.c1, self.c2, self.length, self.follower_radius, k])
