"""The roller effect's product: the roller's motion and losses on the cycle grid."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.components import ByPair


@dataclass(frozen=True)
class RollerField:
    """One pair's roller over the cycle (SI; arrays on the run's cam-angle grid).

    ``omega_roller`` w_r [rad/s] (relative to the pin, positive rolling); ``sliding`` u_s and
    ``entrainment`` u_e [m/s]; ``slip`` and ``slide_roll_ratio`` [-] (NaN where undefined);
    ``rolls`` True where loaded with |slip| <= ``skid_slip``; ``traction`` F_t on the roller [N]
    (signed as u_s), ``rolling_force`` F_R [N]; ``pin_torque`` [N m] (signed as w_r); powers
    [W]: ``sliding_power`` |F_t u_s|, ``rolling_power`` F_R |u_e|, ``pin_power`` T w_r,
    ``kinetic_power`` J w dw/dt; ``solver`` (quasi_static or inertial, its words),
    ``revolutions`` marched and ``periodic_change`` (relative; 0 quasi-static); ``radius`` [m],
    ``inertia`` [kg m^2]."""

    omega_roller: np.ndarray
    sliding: np.ndarray
    entrainment: np.ndarray
    slip: np.ndarray
    slide_roll_ratio: np.ndarray
    rolls: np.ndarray
    traction: np.ndarray
    rolling_force: np.ndarray
    pin_torque: np.ndarray
    sliding_power: np.ndarray
    rolling_power: np.ndarray
    pin_power: np.ndarray
    kinetic_power: np.ndarray
    solver: str
    revolutions: int
    periodic_change: float
    radius: float
    inertia: float
    skid_slip: float


@dataclass(frozen=True)
class RollerMotion(ByPair[RollerField]):
    """The roller of every pair of the train that carries one."""
