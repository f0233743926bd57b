"""Build the follower kinematics a deck describes (deck model -> camtrain.mechanisms calls)."""
from __future__ import annotations

from camtrain import mechanisms as M
from camtrain.deck import schema as S
from camtrain.errors import field_error
from camtrain.lift import LiftCurve


def pivot_geometry(mech: S.Mechanism, base_radius: float, kind: str) -> M.PivotGeometry:
    """Dyson's pivot geometry of a finger (end-pivoted) or rocker (centrally pivoted) follower,
    from A, B, D, kappa, lambda or from the drawn positions of [mechanism.layout]."""
    d = mech.dyson()
    return M.PivotGeometry(A=d.A, B=d.B, D=d.D, follower_radius=mech.follower_radius,
                           base_radius=base_radius, kappa=d.kappa, lam=d.lam, branch=d.branch,
                           kind=kind)


def pivot_kind(mech: S.Mechanism) -> str:
    """'end' for a finger follower, 'central' for a rocker."""
    return "end" if mech.type == "finger" else "central"


def roller_inertia(mech: S.Mechanism) -> float:
    """The roller's moment of inertia about the pivot of a roller finger follower or rocker,
    m_r A^2 [kg m^2] (a point mass at the roller centre; its spin inertia about its own axis
    belongs to its rotation), 0 for any other follower."""
    if mech.follower != "roller" or mech.roller is None or mech.type not in S.PIVOTED:
        return 0.0
    return mech.roller.mass * mech.dyson().A ** 2


def valve_arm_length(mech: S.Mechanism) -> float:
    """B, pivot to the valve-pad centre, of a finger follower, rocker or desmodromic opener
    [m] (from the fields or the drawn layout); 0 for a follower without one."""
    d = mech.dyson()
    return d.B if d is not None else (mech.B or 0.0)


def body_inertia(deck: S.Deck) -> dict[str, float]:
    """J_b for the inertia keys of the mechanisms, from the deck's masses (Ball Table 3.1): the
    follower's equivalent mass at B and its moment of inertia about the pivot, plus the roller
    of a roller finger follower or rocker as a point mass at its centre."""
    m = deck.masses
    B = valve_arm_length(deck.mechanism)
    return {"follower_mass": m.follower,
            "follower_inertia": m.rocker_inertia + m.follower * B * B
            + roller_inertia(deck.mechanism),
            "rocker_inertia": m.rocker_inertia}


def _as_roller(mech: S.Mechanism, k: M.Kinematics) -> M.Kinematics:
    """The follower's kinematics declared a roller when the deck's follower is one."""
    if mech.follower != "roller":
        return k
    from camtrain.mechanisms.roller import roller

    crown = mech.roller.crown_radius if mech.roller is not None else None
    return roller(k, crown_radius=crown)


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
    kind = pivot_kind(mech)
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
    """:func:`kinematics` from the deck models it reads: [mechanism], [cam] and [speed]; a
    roller follower is its curved follower of the roller's radius (camtrain.mechanisms.roller)."""
    main, closing = _train_kinematics(mech, cam, speed, lift)
    return _as_roller(mech, main), closing


def _train_kinematics(mech: S.Mechanism, cam: S.Cam, speed: S.Speed,
                      lift: LiftCurve) -> tuple[M.Kinematics, M.Kinematics | None]:
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
        shape = "cylindrical" if mech.follower == "roller" else mech.follower_shape
        return M.domed(lift, base_radius=cam.base_radius, follower_radius=mech.follower_radius,
                       offset=mech.offset, shape=shape, min_concave_radius=wheel,
                       face_length=mech.face_length, **common), None
    if mech.type in S.PIVOTED:
        geometry = pivot_geometry(mech, cam.base_radius, pivot_kind(mech))
        return M.pivoted(lift, geometry, min_concave_radius=wheel, face_length=mech.face_length,
                         **common), None
    if mech.type == "pushrod":
        p = mech.pushrod
        if p.layout == "simple":
            tappet = mech.follower_radius if mech.follower_radius is not None else float("inf")
            return M.pushrod_simple(lift, _rocker(p), tappet_axis_distance=p.tappet_axis_distance,
                                    base_radius=cam.base_radius, tappet_radius=tappet,
                                    min_concave_radius=wheel, face_length=mech.face_length,
                                    tappet_shape="cylindrical" if mech.follower == "roller"
                                    else "spherical", **common), None
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
