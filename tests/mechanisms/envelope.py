"""Independent numerical construction of the cam as the envelope of follower positions.

Only positions are used: for each cam angle the follower face (a circle or a line) is placed in
the cam frame from its pose, the contact point is the intersection of the faces at theta +- h
(the characteristic point of the family), the cam radius is the circumradius of three contact
points, and the surface velocities are finite differences of the contact position in the cam
frame and in the follower's body frame. No derivative formula of the package is used.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

H_CHAR = 2e-5     # rad, for the characteristic point
H_DIFF = 1e-3     # rad, for curvature and velocities


def rot(a: float) -> np.ndarray:
    return np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])


@dataclass
class Pose:
    """Follower body pose in the fixed frame: origin and angle; face in body coordinates."""

    origin: np.ndarray
    angle: float


class Follower:
    """A follower face in body coordinates: a circle (centre, radius) or a line y_b = level."""

    def __init__(self, pose_fn, *, centre=None, radius=None, level=None, rotation=+1):
        self.pose_fn = pose_fn            # theta -> Pose (fixed frame)
        self.centre = None if centre is None else np.asarray(centre, float)
        self.radius = radius
        self.level = level
        self.sign = rotation              # +1 clockwise cam, -1 anticlockwise

    def to_cam(self, theta: float, p_fixed: np.ndarray) -> np.ndarray:
        # A clockwise cam turned by theta sees fixed points turned counterclockwise by theta.
        return rot(self.sign * theta) @ p_fixed

    def body_to_cam(self, theta, p_body):
        pose = self.pose_fn(theta)
        return self.to_cam(theta, pose.origin + rot(pose.angle) @ p_body)

    def cam_to_body(self, theta, p_cam):
        pose = self.pose_fn(theta)
        p_fixed = rot(-self.sign * theta) @ p_cam
        return rot(-pose.angle) @ (p_fixed - pose.origin)

    def _line(self, theta):
        point = self.body_to_cam(theta, np.array([0.0, self.level]))
        direction = self.body_to_cam(theta, np.array([1.0, self.level])) - point
        return point, direction

    def contact(self, theta: float) -> np.ndarray:
        a, b = theta - H_CHAR, theta + H_CHAR
        if self.centre is None:
            p1, d1 = self._line(a)
            p2, d2 = self._line(b)
            t = np.linalg.solve(np.column_stack([d1, -d2]), p2 - p1)
            return p1 + t[0] * d1
        c1 = self.body_to_cam(a, self.centre)
        c2 = self.body_to_cam(b, self.centre)
        mid, chord = 0.5 * (c1 + c2), c2 - c1
        half = np.linalg.norm(chord) / 2.0
        perp = np.array([-chord[1], chord[0]]) / (2.0 * half)
        h = np.sqrt(self.radius ** 2 - half ** 2)
        candidates = [mid + h * perp, mid - h * perp]
        return min(candidates, key=np.linalg.norm)       # the cam side

    def normal(self, theta: float, p: np.ndarray) -> np.ndarray:
        """Unit normal at the contact, from the cam into the follower."""
        if self.centre is None:
            point, direction = self._line(theta)
            n = np.array([-direction[1], direction[0]])
            n /= np.linalg.norm(n)
            return n if np.dot(n, point) > 0 else -n
        c = self.body_to_cam(theta, self.centre)
        return (c - p) / np.linalg.norm(c - p)

    def _measure(self, theta: float, omega: float, h: float) -> tuple[float, float, float]:
        p0, pm, pp = self.contact(theta), self.contact(theta - h), self.contact(theta + h)
        n = self.normal(theta, p0)
        # direction of positive V_c: counterclockwise along the cam for a clockwise cam
        t = self.sign * np.array([-n[1], n[0]])
        u, v = p0 - pm, pp - p0
        area2 = u[0] * v[1] - u[1] * v[0]
        curvature = 2.0 * area2 / (np.linalg.norm(u) * np.linalg.norm(v) * np.linalg.norm(pp - pm))
        vc = omega * np.dot((pp - pm) / (2 * h), t)
        bp, bm = self.cam_to_body(theta + h, pp), self.cam_to_body(theta - h, pm)
        pose = self.pose_fn(theta)
        v_body = self.to_cam(theta, rot(pose.angle) @ ((bp - bm) / (2 * h)))
        return self.sign * curvature, vc, omega * np.dot(v_body, t)

    def measure(self, theta: float, omega: float) -> dict[str, float]:
        """Contact point, cam radius and surface velocities at one cam angle (central differences
        with one Richardson step, error O(h^4))."""
        fine = np.array(self._measure(theta, omega, H_DIFF))
        coarse = np.array(self._measure(theta, omega, 2 * H_DIFF))
        curvature, vc, vf = (4 * fine - coarse) / 3
        p0 = self.contact(theta)
        with np.errstate(divide="ignore"):
            rc = 1.0 / curvature
        return {"x": p0[0], "y": p0[1], "rc": rc, "vc": vc, "vf": vf}
