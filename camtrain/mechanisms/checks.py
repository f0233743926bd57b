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


def convex(rc):
    """Per angle: the cam is convex there (r_c > 0), as a flat face needs (Ball §2.2.1)."""
    return rc > 0.0


def cusped(rc, rf):
    """Per angle: a curved follower cuts a cusp there (-r_f < r_c <= 0)."""
    return (rc <= 0.0) & (rc > -rf)


def too_tight(rc, wheel: float):
    """Per angle: a concave flank tighter than the grinding wheel (0 < -r_c < wheel)."""
    return (rc < 0.0) & (-rc < wheel)


def off_face(eccentricity, face_length: float, face_centre: float = 0.0):
    """Per angle: the contact lies beyond half the face length from the face centre."""
    return np.abs(eccentricity - face_centre) > 0.5 * face_length


def cases_pass(k: Kinematics, *, flat: bool, min_concave_radius: float | None = None,
               face_length: float | None = None) -> np.ndarray:
    """Per case (the leading axes of a batch's (cases, angles) Kinematics): whether
    :func:`check_flat_follower_convex` (``flat``) or :func:`check_curved_follower`, and
    :func:`check_face`, pass. A sweep batch runs a failing case alone, for its error."""
    rc = k.cam_radius
    if flat:
        ok = np.all(convex(rc), axis=-1)
    else:
        ok = ~np.any(cusped(rc, k.follower_radius), axis=-1)
        if min_concave_radius is not None and min_concave_radius > 0.0:
            ok &= ~np.any(too_tight(rc, min_concave_radius), axis=-1)
    if face_length is not None:
        ok &= ~np.any(off_face(k.eccentricity, face_length), axis=-1)
    return ok


def check_flat_follower_convex(k: Kinematics, base_radius: float,
                               field: str = "cam.base_radius") -> None:
    """A flat face needs r_c = r_B + l + l'' > 0 everywhere (Ball §2.2.1, Williams §4)."""
    rc = k.cam_radius
    if np.count_nonzero(convex(rc)) == rc.size:
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
    cusp = cusped(rc, rf)
    if np.any(cusp):
        i = int(np.argmax(np.where(cusp, cusp_index, -np.inf)))
        raise GeometryError(
            f"{radius_field}, {base_field}: the cam would have a cusp (undercut) at "
            f"{angle_text(k.theta[i])}: radius of curvature {mm(rc[i])} with a follower radius "
            f"of {mm(rf[i])}; reduce the follower radius or enlarge the base circle")
    if min_concave_radius is None or min_concave_radius <= 0.0:
        return
    tight = too_tight(rc, min_concave_radius)
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
    off = off_face(k.eccentricity, face_length, face_centre)
    if np.any(off):
        offset = k.eccentricity - face_centre
        beyond = np.where(off, np.abs(offset), -np.inf)
        i = int(np.argmax(beyond))
        needed = 2.0 * float(beyond[i])
        raise GeometryError(
            f"{field}: the contact runs off the follower face at {angle_text(k.theta[i])} "
            f"({mm(offset[i])} from the face centre, face length {mm(face_length)}); "
            f"a face of at least {mm(needed)} is needed")
