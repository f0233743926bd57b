"""Build the follower kinematics a deck describes (deck model -> camtrain.mechanisms calls)."""
from __future__ import annotations

from camtrain import mechanisms as M
from camtrain.deck import schema as S
from camtrain.errors import field_error
from camtrain.lift import LiftCurve


def pivot_geometry(mech: S.Mechanism, base_radius: float, kind: str) -> M.PivotGeometry:
    """Dyson's pivot geometry of a finger (end-pivoted) or rocker (centrally pivoted) follower."""
    return M.PivotGeometry(A=mech.A, B=mech.B, D=mech.D, follower_radius=mech.follower_radius,
                           base_radius=base_radius, kappa=mech.kappa, lam=mech.lambda_,
                           kind=kind)


def closing_geometry(closing: S.ClosingPair) -> M.PivotGeometry:
    return M.PivotGeometry(A=closing.A, B=closing.B, D=closing.D,
                           follower_radius=closing.follower_radius,
                           base_radius=closing.base_radius, kappa=closing.kappa,
                           lam=closing.lambda_, kind="end")


def valve_lift(lift: S.Lift, mech: S.Mechanism, base_radius: float,
               curve: LiftCurve) -> LiftCurve:
    """The valve lift: the law itself, or converted from cam lift read by an inspection roller."""
    if lift.measured_at == "valve":
        return curve
    if mech.type not in S.PIVOTED:
        raise field_error("lift.measured_at", "cam lift is converted to valve lift for pivoted "
                          "followers only", "cam", "\"valve\" for a "
                          f"{mech.type} follower (its cam lift is the valve lift)")
    kind = "end" if mech.type == "finger" else "central"
    return M.valve_lift_from_cam_lift(curve, pivot_geometry(mech, base_radius, kind),
                                      lift.inspection_radius, rotation=mech.rotation)


def _rocker(p: S.Pushrod) -> M.RockerGeometry:
    return M.RockerGeometry(D1=p.rocker_pushrod_arm, D2=p.rocker_valve_arm,
                            alpha0=p.rocker_arm_angle, valve_angle=p.valve_axis_angle,
                            perpendicular_fraction=p.perpendicular_lift_fraction,
                            pushrod_length=p.pushrod_length,
                            pushrod_cg_fraction=p.pushrod_cg_fraction)


def kinematics(deck: S.Deck, lift: LiftCurve) -> tuple[M.Kinematics, M.Kinematics | None]:
    """Contact kinematics of the deck's mechanism from the valve lift; the second item is the
    closing pair of a desmodromic train (None otherwise)."""
    return train_kinematics(deck.mechanism, deck.cam, deck.speed, lift)


def train_kinematics(mech: S.Mechanism, cam: S.Cam, speed: S.Speed,
                     lift: LiftCurve) -> tuple[M.Kinematics, M.Kinematics | None]:
    """:func:`kinematics` from the deck models it reads: [mechanism], [cam] and [speed]."""
    common = {"omega": speed.omega, "rotation": mech.rotation}
    wheel = mech.grinding_wheel_radius
    if mech.type == "flat":
        return M.flat_faced(lift, base_radius=cam.base_radius, face_length=mech.face_length,
                            **common), None
    if mech.type == "domed":
        if cam.taper_angle > 0.0:
            return M.tapered_domed(lift, base_radius=cam.base_radius,
                                   follower_radius=mech.follower_radius,
                                   taper_angle=cam.taper_angle, min_concave_radius=wheel,
                                   face_length=mech.face_length, **common), None
        return M.domed(lift, base_radius=cam.base_radius, follower_radius=mech.follower_radius,
                       offset=mech.offset, shape=mech.follower_shape, min_concave_radius=wheel,
                       face_length=mech.face_length, **common), None
    if mech.type in S.PIVOTED:
        kind = "end" if mech.type == "finger" else "central"
        geometry = pivot_geometry(mech, cam.base_radius, kind)
        return M.pivoted(lift, geometry, min_concave_radius=wheel, face_length=mech.face_length,
                         **common), None
    if mech.type == "pushrod":
        p = mech.pushrod
        if p.layout == "simple":
            tappet = mech.follower_radius if mech.follower_radius is not None else float("inf")
            return M.pushrod_simple(lift, _rocker(p), tappet_axis_distance=p.tappet_axis_distance,
                                    base_radius=cam.base_radius, tappet_radius=tappet,
                                    min_concave_radius=wheel, face_length=mech.face_length,
                                    **common), None
        follower = M.FourBarGeometry(a=p.rocker_pivot_x, b=p.rocker_pivot_y,
                                     e=p.follower_pushrod_arm, A=mech.A, D=mech.D,
                                     follower_radius=mech.follower_radius,
                                     base_radius=cam.base_radius, branch=p.branch,
                                     closure=p.closure)
        return M.pushrod_four_bar(lift, _rocker(p), follower, min_concave_radius=wheel,
                                  face_length=mech.face_length, **common), None
    if mech.type == "desmodromic":
        pair = M.desmodromic(lift, _negated(lift), pivot_geometry(mech, cam.base_radius,
                                                                   "central"),
                             closing_geometry(mech.closing), min_concave_radius=wheel, **common)
        return pair.opening, pair.closing
    raise AssertionError(mech.type)  # pragma: no cover - the schema admits only these


def _negated(lift: LiftCurve) -> LiftCurve:
    """Ball's closing cam lift is the valve lift with its sign reversed (App F)."""
    return LiftCurve(lift.theta, -lift.lift, -lift.d1, -lift.d2, -lift.d3)
