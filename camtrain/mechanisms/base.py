"""Per-angle contact kinematics shared by every follower family, and the one rotation rule.

Frames and signs (the same for every mechanism; see docs/mechanisms.md for sketches):

* **Fixed frame** of the mechanism: origin at the cam centre O. Translating followers move along
  +y (offset ``e`` along +x); pivoted followers have their pivot U on the +x axis at (D, 0).
* **Cam frame**: fixed to the cam, coincides with the fixed frame at theta = 0 (the nose of the
  lift law). Contact points and the cam profile are given in this frame.
* The analysis kernels work for **clockwise** cam rotation in the fixed frame (Dyson 1980,
  Lim et al. 1983, Ball 1988 App A). Anticlockwise rotation is obtained in :func:`analyse` only,
  by time reversal (Ball 1988 §4.2.1): the mechanism turning anticlockwise at angle theta is the
  clockwise mechanism at -theta, so the lift law is reversed, odd derivatives are negated, the
  clockwise analysis is run and its arrays are reversed back with the odd quantities negated.
* ``v_cam`` (V_c) is the speed of the contact point along the cam surface, positive opposite to the
  cam surface motion (Ball's convention, positive on a convex cam). ``v_follower`` (V_f) is the
  speed of the contact point along the follower face, positive in the same direction as V_c.
  Both are therefore invariant under the rotation rule; so are the entrainment and sliding.
* ``eccentricity`` is the position of the contact on the follower face (arc length for a curved
  face), positive in the direction of positive V_f, so that V_f = omega * d(eccentricity)/dtheta.
  For a flat follower it equals dl/dtheta (+ offset), Ball's "eccentricity".
* ``pressure_angle``: angle from the direction of motion of the follower (its material point at
  the pad centre, for increasing lift) to the contact normal, positive when the normal leans the
  way the cam surface moves.

Load arms (virtual work on the follower that touches the cam, generalised coordinate q: follower
translation [m] for translating followers and tappets, follower rotation [rad] for pivoted ones,
oriented so that q grows with lift)::

    W * (arm_normal + mu * arm_friction) = F_valve * arm_valve
                                           + omega**2 * sum_b J_b * inertia[b]

with W the normal contact load, mu*W the friction force (any friction magnitude F may replace
mu*W), F_valve = spring + valve-side inertia force acting along the valve axis, and J_b the mass
[kg] or moment of inertia [kg m^2] named by each ``inertia`` key. ``arm_friction`` already carries
the direction of friction (sign of the sliding speed). Without friction and body inertia,
W = rocker_ratio * F_valve. The camshaft torque resisting rotation is
T = W * torque_arm_normal + F * friction_arm. Identities (tested): torque_arm_normal =
arm_normal * q', valve_d1 = arm_valve * q', |V_s| = omega * (friction_arm - arm_friction * q').
"""
from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, fields, replace
from functools import cached_property

import numpy as np

from camtrain.components import ByPair
from camtrain.errors import field_error
from camtrain.lift.base import LiftCurve

CLOCKWISE = "clockwise"
ANTICLOCKWISE = "anticlockwise"
_ROTATION_NAMES = {
    "clockwise": CLOCKWISE, "cw": CLOCKWISE, "1": CLOCKWISE, "+1": CLOCKWISE,
    "anticlockwise": ANTICLOCKWISE, "counterclockwise": ANTICLOCKWISE, "acw": ANTICLOCKWISE,
    "ccw": ANTICLOCKWISE, "-1": ANTICLOCKWISE,
}

_ODD = {"odd": True}


def _frozen(values: np.ndarray) -> np.ndarray:
    """A derived array made read-only: it is kept and shared like the fields it comes from."""
    values.flags.writeable = False
    return values


def kept(values: np.ndarray) -> np.ndarray:
    """An input array a Kinematics keeps: itself when already read-only (a lift curve cached
    and shared between runs), else a copy, which the Kinematics freezes without touching the
    caller's array."""
    return values if not values.flags.writeable else values.copy()


def check_speed(omega: float) -> None:
    """The camshaft speed must be a positive number of rad/s."""
    if not (omega > 0.0 and math.isfinite(omega)):
        raise field_error("speed.camshaft", "camshaft speed must be positive",
                          f"{omega * 60.0 / (2.0 * np.pi):g} rpm", "> 0 rpm")


def normalise_rotation(rotation: str | int) -> str:
    """Return ``"clockwise"`` or ``"anticlockwise"``; Ball's template flags 1 / -1 are accepted."""
    key = str(rotation).strip().lower()
    if key not in _ROTATION_NAMES:
        raise field_error("mechanism.rotation", "unknown cam rotation direction", rotation,
                          "'clockwise' (1, as Dyson or Lim) or 'anticlockwise' (-1)")
    return _ROTATION_NAMES[key]


@dataclass(frozen=True)
class Kinematics:
    """Contact kinematics of one cam/follower pair on a cam-angle grid (SI units throughout).

    Arrays share the shape of ``theta``. Fields marked "odd" change sign under the rotation rule
    (they are derivatives with respect to the cam angle or are signed against the cam motion).
    ``gamma``, ``gamma_d1``, ``gamma_d2`` and ``nu`` are None for translating followers.
    """

    mechanism: str
    rotation: str
    omega: float                       # camshaft speed [rad/s]
    theta: np.ndarray                  # cam angle from the nose [rad]
    valve_lift: np.ndarray             # l_v [m]
    valve_d1: np.ndarray = field(metadata=_ODD)   # dl_v/dtheta [m/rad]
    valve_d2: np.ndarray = field()                # [m/rad^2]
    valve_d3: np.ndarray = field(metadata=_ODD)   # [m/rad^3]
    cam_lift: np.ndarray = field()     # lift of the follower that touches the cam [m]
    cam_d1: np.ndarray = field(metadata=_ODD)
    cam_d2: np.ndarray = field()
    contact_x: np.ndarray = field()    # contact point = cam profile point, cam frame [m]
    contact_y: np.ndarray = field()
    eccentricity: np.ndarray = field(metadata=_ODD)   # contact position on the follower face [m]
    cam_radius: np.ndarray = field()   # r_c [m], negative when concave, +-inf on a flat spot
    follower_radius: np.ndarray = field()          # r_f [m], inf for a flat face
    equivalent_radius: np.ndarray = field()        # R, 1/R = 1/r_c + 1/r_f [m]
    radius_x: np.ndarray = field()     # principal radius along the rolling direction [m]
    radius_y: np.ndarray = field()     # transverse principal radius [m] (inf: line contact)
    v_cam: np.ndarray = field()        # V_c [m/s]
    v_follower: np.ndarray = field()   # V_f [m/s]
    rocker_ratio: np.ndarray = field()  # load ratio W / F_valve without friction and inertia
    pressure_angle: np.ndarray = field(metadata=_ODD)   # [rad]
    friction_arm: np.ndarray = field()       # cam-axis arm of the friction force [m]
    torque_arm_normal: np.ndarray = field(metadata=_ODD)  # cam-axis arm of the normal load [m]
    arm_normal: np.ndarray = field()   # virtual-work arms, see module docstring
    arm_friction: np.ndarray = field(metadata=_ODD)
    arm_valve: np.ndarray = field()
    q: np.ndarray = field()            # generalised follower coordinate (m or rad), 0 on base
    q_d1: np.ndarray = field(metadata=_ODD)
    q_d2: np.ndarray = field()
    inertia: Mapping[str, np.ndarray] = field(default_factory=dict)
    gamma: np.ndarray | None = None    # Dyson's angle OUV [rad] (pivoted followers)
    gamma_d1: np.ndarray | None = field(default=None, metadata=_ODD)
    gamma_d2: np.ndarray | None = None
    nu: np.ndarray | None = None       # angle from line UQ to the contact normal [rad]

    def __post_init__(self) -> None:
        shape = np.shape(self.theta)
        ndarray = np.ndarray
        for name, value in self.__dict__.items():   # the fields (nothing else is set yet)
            if isinstance(value, ndarray):
                if value.shape != shape:
                    raise ValueError(f"Kinematics.{name} has shape {value.shape}, "
                                     f"theta has {shape}")
                value.setflags(write=False)   # (cheaper than reading the flags first)
        for name, value in self.inertia.items():
            if np.shape(value) != shape:
                raise ValueError(f"Kinematics.inertia[{name!r}] has the wrong shape")
            value.flags.writeable = False

    # Derived quantities are computed from the (read-only) surface speeds on first use, so they
    # can never disagree with them; each is computed once per Kinematics and read-only.
    @cached_property
    def entrainment(self) -> np.ndarray:
        """Mean entrainment velocity u_e = (V_c + V_f)/2 [m/s] (Ball's nomenclature, Yang 3.4)."""
        return _frozen(0.5 * (self.v_cam + self.v_follower))

    @cached_property
    def entrainment_sum(self) -> np.ndarray:
        """V_c + V_f [m/s], the "entraining velocity" of Ball ch. 3/5 and Williams eq. 1.12."""
        return _frozen(self.v_cam + self.v_follower)

    @cached_property
    def sliding(self) -> np.ndarray:
        """Sliding velocity V_s = V_c - V_f [m/s]."""
        return _frozen(self.v_cam - self.v_follower)

    @cached_property
    def line_contact(self) -> bool:
        """No finite transverse radius anywhere: a line contact (flat or cylindrical faces)."""
        return np.count_nonzero(np.isinf(self.radius_y)) == self.radius_y.size

    @cached_property
    def nose(self) -> int:
        """Index of the largest valve lift (the first, if it repeats)."""
        return int(self.valve_lift.argmax())

    @property
    def profile_x(self) -> np.ndarray:
        return self.contact_x

    @property
    def profile_y(self) -> np.ndarray:
        return self.contact_y

    @cached_property
    def profile_r(self) -> np.ndarray:
        """Polar radius of the cam profile point touched at each angle [m]."""
        return _frozen(np.hypot(self.contact_x, self.contact_y))

    @cached_property
    def profile_angle(self) -> np.ndarray:
        """Polar angle of the profile point in the cam frame, from +x, counterclockwise [rad]."""
        return _frozen(np.arctan2(self.contact_y, self.contact_x))

    def time_reversed(self, theta: np.ndarray, rotation: str) -> Kinematics:
        """Arrays reversed in angle, odd fields negated, ``theta`` replaced (rotation rule)."""
        changes: dict[str, object] = {"theta": np.array(theta, dtype=float), "rotation": rotation}
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name != "theta" and isinstance(value, np.ndarray):
                flipped = value[::-1].copy()
                changes[f.name] = -flipped if f.metadata.get("odd") else flipped
        changes["inertia"] = {k: v[::-1].copy() for k, v in self.inertia.items()}
        return replace(self, **changes)


Kernel = Callable[[LiftCurve, np.ndarray], Kinematics]


def reverse_lift(lift: LiftCurve) -> LiftCurve:
    """The lift law seen by the clockwise analysis of an anticlockwise cam: l(-theta)."""
    return LiftCurve(theta=-lift.theta[::-1].copy(), lift=lift.lift[::-1].copy(),
                     d1=-lift.d1[::-1].copy(), d2=lift.d2[::-1].copy(), d3=-lift.d3[::-1].copy())


def analyse(lift: LiftCurve, rotation: str | int, kernel: Kernel) -> Kinematics:
    """Run a clockwise ``kernel`` for either rotation direction (the only place rotation acts).

    ``kernel(lift, user_theta)`` receives the lift law to analyse for clockwise rotation and, for
    error messages, the user's cam angle at each grid point. Ball (1988) §4.2.1: for anticlockwise
    rotation reverse the lift arrays, negate the velocity, analyse, reverse the results back.
    """
    direction = normalise_rotation(rotation)
    if direction == CLOCKWISE:
        result = kernel(lift, lift.theta)
        return result if result.rotation == CLOCKWISE else replace(result, rotation=CLOCKWISE)
    result = kernel(reverse_lift(lift), lift.theta[::-1])
    return result.time_reversed(lift.theta, ANTICLOCKWISE)


def equivalent_radius(cam_radius: np.ndarray, follower_radius: float) -> np.ndarray:
    """R from 1/R = 1/r_c + 1/r_f (Ball eq. A.14 form; eq. 3.6 for a flat face, r_f = inf).

    Singular cases are legitimate and handled without warnings: a flat spot (r_c = +-inf) gives
    R = r_f, a cusp (r_c = 0) gives R = 0 and a conformal contact (r_c = -r_f) gives R = inf.
    """
    rc = np.asarray(cam_radius, dtype=float)
    if np.all(np.isinf(follower_radius)):   # (one radius, or one per sweep case)
        return rc.copy()
    with np.errstate(divide="ignore"):
        return 1.0 / (1.0 / rc + 1.0 / follower_radius)


def cross(ax, ay, bx, by):
    """z-component of the 2-D cross product."""
    return ax * by - ay * bx


def wrap_angle(a: np.ndarray) -> np.ndarray:
    """Wrap angles to (-pi, pi]."""
    return np.pi - np.mod(np.pi - a, 2.0 * np.pi)



@dataclass(frozen=True)
class TrainKinematics(ByPair[Kinematics]):
    """Contact kinematics of every cam/follower pair of a valve train (the kinematics effect's
    product): the only pair, or the opening (``main``) and ``closing`` pair of a desmodromic
    train."""
