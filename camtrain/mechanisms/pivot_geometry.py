"""Pivoted-follower geometry (Dyson's notation, Ball 1988 App A) and Ball's geometry rules.

Fixed frame: cam centre O at the origin, follower pivot U at (D, 0). Angles are counterclockwise.
With gamma = angle OUV and lambda = angle VUQ, the pad centre of curvature Q and the valve-contact
centre V lie at::

    Q = U + A (cos(pi + lambda + gamma), sin(pi + lambda + gamma))
    V = U + B (cos(pi + gamma),          sin(pi + gamma))

and the valve opens along (cos kappa, -sin kappa), so that the valve lift is
l_v = B cos(gamma_B + kappa) - B cos(gamma + kappa) (Ball eq. A.19). End-pivoted (finger) and
centrally pivoted (rocker) followers differ only in the values of kappa, lambda and the branch of
gamma_B: Ball's two contact-point formulas (A.1-A.2 and App A(b)) are algebraically identical.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from camtrain.errors import GeometryError, field_error
from camtrain.mechanisms.base import wrap_angle

KINDS = ("end", "central")


def base_circle_cosine(A, D, follower_radius, base_radius):
    """cos(gamma_B + lambda) = [A^2 + D^2 - (r_f + r_B)^2] / (2 A D), the cosine rule on the base
    circle where |OQ| = r_f + r_B (Ball 1988 App A, after eq. A.21; Williams 2013 eq. 7.3)."""
    return (A * A + D * D - (follower_radius + base_radius) ** 2) / (2.0 * A * D)


@dataclass(frozen=True)
class PivotGeometry:
    """Geometry of a pivoted follower, SI units and radians (deck fields in brackets).

    A: pivot to the pad's centre of curvature Q [m] (mechanism.pivot_to_cam_contact_centre)
    B: pivot to the valve-contact centre of curvature V [m] (mechanism.pivot_to_valve)
    D: cam centre to pivot [m] (mechanism.cam_to_pivot)
    follower_radius: pad radius r_f [m] (mechanism.follower_radius)
    base_radius: cam base-circle radius r_B [m] (cam.base_radius)
    kappa: angle from OU to the valve's direction of motion [rad] (mechanism.kappa, Ball's CHI)
    lam: angle VUQ [rad] (mechanism.lambda)
    branch: +1 or -1, sign of (gamma_B + lambda) from the cosine rule; None picks Ball's branch,
        the one with the larger valve arm |B sin(gamma_B + kappa)| (mechanism.branch)
    kind: 'end' (finger follower) or 'central' (rocker); a label only
    """

    A: float
    B: float
    D: float
    follower_radius: float
    base_radius: float
    kappa: float
    lam: float
    branch: int | None = None
    kind: str = "end"

    def __post_init__(self) -> None:
        names = {"A": "mechanism.pivot_to_cam_contact_centre", "B": "mechanism.pivot_to_valve",
                 "D": "mechanism.cam_to_pivot", "follower_radius": "mechanism.follower_radius",
                 "base_radius": "cam.base_radius"}
        for attr, path in names.items():
            value = getattr(self, attr)
            if not (np.isfinite(value) and value > 0.0):
                raise field_error(path, "must be a positive finite length", value, "> 0 m")
        if self.branch not in (None, 1, -1):
            raise field_error("mechanism.branch", "unknown branch", self.branch, "+1, -1 or auto")
        if self.kind not in KINDS:
            raise field_error("mechanism.kind", "unknown pivoted follower kind", self.kind,
                              " or ".join(KINDS))
        c = base_circle_cosine(self.A, self.D, self.follower_radius, self.base_radius)
        if abs(c) >= 1.0:
            raise GeometryError(
                "mechanism.pivot_to_cam_contact_centre, mechanism.cam_to_pivot, "
                "mechanism.follower_radius, cam.base_radius: the follower cannot touch the base "
                f"circle: |OQ| = r_f + r_B = {(self.follower_radius + self.base_radius) * 1e3:.3f}"
                f" mm is not between |D - A| and D + A "
                f"({abs(self.D - self.A) * 1e3:.3f} .. {(self.D + self.A) * 1e3:.3f} mm)")

    @property
    def base_angle(self) -> float:
        """gamma_B + lambda on the chosen branch [rad]."""
        c = base_circle_cosine(self.A, self.D, self.follower_radius, self.base_radius)
        root = float(np.arccos(c))
        if self.branch is not None:
            return self.branch * root
        arms = [abs(np.sin(s * root - self.lam + self.kappa)) for s in (1, -1)]
        return root if arms[0] >= arms[1] else -root

    @property
    def gamma_b(self) -> float:
        """Dyson's gamma on the base circle [rad]."""
        return self.base_angle - self.lam

    @property
    def lift_sign(self) -> int:
        """+1 if gamma grows with valve lift, else -1 (sign of the valve arm B sin(gamma_B+kappa))."""
        s = np.sin(self.gamma_b + self.kappa)
        if s == 0.0:
            raise GeometryError("mechanism.kappa: the valve arm is parallel to the valve axis on "
                                "the base circle, the follower cannot move the valve")
        return 1 if s > 0.0 else -1

    def points(self, gamma: float | None = None) -> dict[str, np.ndarray]:
        """O, U, Q, V (fixed frame) at follower angle gamma (default: base circle)."""
        g = self.gamma_b if gamma is None else gamma
        U = np.array([self.D, 0.0])
        Q = U + self.A * np.array([np.cos(np.pi + self.lam + g), np.sin(np.pi + self.lam + g)])
        V = U + self.B * np.array([np.cos(np.pi + g), np.sin(np.pi + g)])
        return {"O": np.zeros(2), "U": U, "Q": Q, "V": V}


def _angle(v: np.ndarray) -> float:
    return float(np.arctan2(v[1], v[0]))


def rescale_pivot_geometry(geometry: PivotGeometry, *, base_radius: float | None = None,
                           follower_radius: float | None = None) -> PivotGeometry:
    """New A, D, kappa, lambda after changing r_B and/or r_f with pivot and valve fixed
    (Ball 1988 §5 parametric rules, as reconstructed in the reference extraction §4.6).

    A new follower radius slides Q along OQ (cam centre fixed, the base-circle contact point
    unchanged): B, D, r_B and kappa are kept. A new base radius then slides the cam centre O along
    QO, keeping the follower, pivot and valve: gamma_B + kappa, A and lambda are kept.
    """
    g = geometry
    pts = g.points()
    U, Q, V = pts["U"], pts["Q"], pts["V"]
    valve_dir = _angle(np.array([np.cos(g.kappa), -np.sin(g.kappa)]))
    rf = g.follower_radius if follower_radius is None else float(follower_radius)
    rb = g.base_radius if base_radius is None else float(base_radius)
    if not (rf > 0.0 and rb > 0.0):
        raise field_error("mechanism.follower_radius" if rf <= 0.0 else "cam.base_radius",
                          "must be positive", rf if rf <= 0.0 else rb, "> 0 m")
    radial = Q / np.linalg.norm(Q)
    Q = radial * (g.base_radius + rf)
    O = Q - radial * (rb + rf)
    D = float(np.linalg.norm(U - O))
    A = float(np.linalg.norm(Q - U))
    gamma_b = _angle(V - U) - _angle(O - U)
    lam = float(wrap_angle(_angle(Q - U) - _angle(V - U)))
    kappa = float(wrap_angle(_angle(U - O) - valve_dir))
    base = float(wrap_angle(lam + gamma_b))
    return replace(g, A=A, D=D, follower_radius=rf, base_radius=rb, kappa=kappa, lam=lam,
                   branch=1 if base >= 0.0 else -1)
