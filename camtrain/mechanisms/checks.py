"""Geometry checks that stop a run with a GeometryError naming the cam angle and the deck fields.

Ball (1988) §4.2.2: a flat-faced follower cannot run on a concave cam, and for the other
followers a concave flank must not be tighter than the grinding wheel ("minimum cam concavity").
A curved follower on a convex pitch curve tighter than the follower itself (pitch radius between 0
and r_f, i.e. -r_f < r_c <= 0) generates a cusp: the cam would be undercut.
"""
from __future__ import annotations

import numpy as np

from camtrain.errors import GeometryError
from camtrain.mechanisms.base import Kinematics


def angle_text(theta: float) -> str:
    """Cam angle from the nose in degrees, as quoted in every geometry message."""
    return f"cam angle {np.degrees(theta):+.2f} deg"


def mm(value: float) -> str:
    return f"{value * 1e3:.3f} mm"


def check_flat_follower_convex(k: Kinematics, base_radius: float,
                               field: str = "cam.base_radius") -> None:
    """A flat face needs r_c = r_B + l + l'' > 0 everywhere (Ball §2.2.1, Williams §4)."""
    rc = k.cam_radius
    if np.count_nonzero(rc > 0.0) == rc.size:
        return
    i = int(np.argmin(rc))
    needed = base_radius - float(rc[i])
    raise GeometryError(
        f"{field}: a flat-faced follower needs a convex cam, but the cam radius of curvature "
        f"would be {mm(rc[i])} at {angle_text(k.theta[i])} (concave or cusped flank); "
        f"the base-circle radius must exceed {mm(needed)} (got {mm(base_radius)}), "
        f"or the lift law must be gentler")


def check_curved_follower(k: Kinematics, *, radius_field: str, base_field: str = "cam.base_radius",
                          min_concave_radius: float | None = None) -> None:
    """No cusp (-r_f < r_c <= 0) and no concave flank tighter than the grinding wheel."""
    rc = k.cam_radius
    rf = k.follower_radius
    with np.errstate(divide="ignore", invalid="ignore"):
        # r_f / (r_c + r_f) >= 1 marks the cusp band; it is smooth where r_c passes through inf
        cusp_index = np.where(np.isinf(rc), 0.0, rf / (rc + rf))
    cusp = (rc <= 0.0) & (rc > -rf)
    if np.any(cusp):
        i = int(np.argmax(np.where(cusp, cusp_index, -np.inf)))
        raise GeometryError(
            f"{radius_field}, {base_field}: the cam would have a cusp (undercut) at "
            f"{angle_text(k.theta[i])}: radius of curvature {mm(rc[i])} with a follower radius "
            f"of {mm(rf[i])}; reduce the follower radius or enlarge the base circle")
    if min_concave_radius is None or min_concave_radius <= 0.0:
        return
    tight = (rc < 0.0) & (-rc < min_concave_radius)
    if np.any(tight):
        i = int(np.argmax(np.where(tight, rc, -np.inf)))
        raise GeometryError(
            f"mechanism.min_concave_radius: the cam flank is concave with radius "
            f"{mm(-rc[i])} at {angle_text(k.theta[i])}, tighter than the grinding wheel "
            f"({mm(min_concave_radius)}); use a gentler lift law, a larger follower radius "
            f"({radius_field}) or a smaller wheel")


def check_face(k: Kinematics, face_length: float | None, face_centre: float = 0.0,
               field: str = "mechanism.face_length") -> None:
    """The contact must stay on a face of length ``face_length`` centred at ``face_centre``.

    Positions are the ``eccentricity`` coordinate (arc length on a curved face). For a flat
    bucket the face length is its usable diameter, at least 2 max|l'| (Ball §2.4).
    """
    if face_length is None:
        return
    offset = k.eccentricity - face_centre
    i = int(np.argmax(np.abs(offset)))
    if abs(offset[i]) > 0.5 * face_length:
        needed = 2.0 * float(np.max(np.abs(offset)))
        raise GeometryError(
            f"{field}: the contact runs off the follower face at {angle_text(k.theta[i])} "
            f"({mm(offset[i])} from the face centre, face length {mm(face_length)}); "
            f"a face of at least {mm(needed)} is needed")
