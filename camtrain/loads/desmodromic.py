"""Contact loads of a desmodromic valve train: which cam controls the valve, and where it hands over.

Ball (1988) App D, Table D.1, with the corrections of the reference extraction (§2.3): rocker
inertia, gravity and friction are ignored in the load balance, and the closing spring is a
constant force S = k delta (App F: a high fitted load at a very low rate over a tiny travel,
10 kN/m x 5 mm = 50 N). With the valve-side inertia force M x'' (x'' = omega^2 l_v''):

* valve on its seat (base circle): the opening load is zero (its clearance is open) and the
  closing spring presses the closing follower on its cam, W_c = RR_c S                (D.1)
* lifted, M x'' + S > 0: the opening cam drives, W_o = RR_o (M x'' + S) (D.2, D.3); the closing
  follower is still held on its cam by the spring, W_c = RR_c S                      (D.4)
* lifted, M x'' + S < 0: the opening follower leaves the valve and the closing follower drives it
  through the top-hat, W_o = 0 and W_c = RR_c |M x''|                          (D.7-D.9, D.9
  read as a magnitude since x'' < 0 there)
* control hands over where M x'' + S = 0, i.e. |M x''| = S                  (D.5, D.6, D.10 corrected)

So W_c = RR_c max(S, -M x'') everywhere. RR is each pair's instantaneous load ratio
(``Kinematics.rocker_ratio`` = arm_valve / arm_normal, friction and inertia free, as App D).
A pair whose ratio is not positive where it must carry load cannot transmit it: the train jams.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.loads.forces import contact_mask

__all__ = ["DesmodromicLoads", "desmodromic_loads", "handover_angles"]


@dataclass(frozen=True)
class DesmodromicLoads:
    """Per-angle loads [N] of both pairs, the valve force and which cam controls the valve."""

    opening: np.ndarray      # W_o, opening cam/follower load
    closing: np.ndarray      # W_c, closing cam/follower load
    valve_force: np.ndarray  # M x'' + S while lifted, 0 on the seat
    in_control: np.ndarray   # +1 opening cam drives the valve, -1 closing cam (or seat) holds it
    handovers: tuple[float, ...]   # cam angles [rad] where M x'' + S = 0 while lifted
    closing_spring: float    # S [N]
    jammed: np.ndarray       # True where a pair must carry load but its load ratio is <= 0


def handover_angles(theta, valve_force, lifted) -> tuple[float, ...]:
    """Angles [rad] inside the lift event where the valve force changes sign (linear
    interpolation between grid points); the ends of the lift event are not handovers."""
    theta, f = np.asarray(theta, dtype=float), np.asarray(valve_force, dtype=float)
    lifted = np.asarray(lifted, dtype=bool)
    i = np.flatnonzero(lifted[:-1] & lifted[1:] & (np.sign(f[:-1]) * np.sign(f[1:]) < 0.0))
    frac = f[i] / (f[i] - f[i + 1])
    return tuple(float(a) for a in theta[i] + frac * (theta[i + 1] - theta[i]))


def desmodromic_loads(opening, closing, *, closing_spring: float, valve_mass: float,
                      clearance: float = 0.0, omega: float | None = None) -> DesmodromicLoads:
    """Ball App D loads of the opening and closing pairs.

    Args:
        opening, closing: Kinematics of the opening pair and of the closing pair (closing lift
            negated, Ball §3.2.3) on the same cam-angle grid.
        closing_spring: S = k delta [N], constant (App F).
        valve_mass: M, equivalent reciprocating mass at the valve [kg].
        clearance: valve lift [m] up to which the valve counts as seated.
        omega: camshaft speed [rad/s]; default ``opening.omega``.
    """
    w = opening.omega if omega is None else float(omega)
    lifted = contact_mask(opening.valve_lift, clearance)   # same base-circle rule as other trains
    inertia = valve_mass * w * w * np.asarray(opening.valve_d2, dtype=float)
    force = np.where(lifted, inertia + closing_spring, 0.0)
    opening_drives = lifted & (force > 0.0)
    rr_o = np.asarray(opening.rocker_ratio, dtype=float)
    rr_c = np.asarray(closing.rocker_ratio, dtype=float)
    w_o = np.where(opening_drives, rr_o * force, 0.0)
    # closing follower: the spring always, the whole inertia force when it drives (D.7-D.9)
    w_c = rr_c * np.maximum(closing_spring, np.where(lifted, -inertia, 0.0))
    jammed = (opening_drives & ~(rr_o > 0.0)) | ~(rr_c > 0.0)
    return DesmodromicLoads(opening=w_o, closing=w_c, valve_force=force,
                            in_control=np.where(opening_drives, 1, -1).astype(int),
                            handovers=handover_angles(opening.theta, force, lifted),
                            closing_spring=float(closing_spring), jammed=jammed)
