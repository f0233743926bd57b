"""The roller's tables and the march's record of them (:data:`camtrain.dynamics.records.Spin`)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.dynamics.records import Spin


@dataclass(frozen=True)
class RollerTables:
    """The roller's data on the run's cam-angle grid (SI), plain arrays.

    ``theta`` the grid angles [rad] (uniform, one revolution); ``grid`` normalised abscissae in
    [-1, 1] (clustered at 0); ``loads`` [N] the load levels from 0, uniform in W^(1/3), of the traction and
    pin tables; ``traction`` [N] (angles, loads, grid) at sliding speeds
    ``sliding_scale[angle] * grid`` [m/s]; ``pin`` [N m] (loads, grid) at roller speeds
    ``speed_scale * grid`` [rad/s]; ``v_s0`` [m/s] the non-rotating follower's sliding speed
    and ``ratio`` [-] the normal load per valve-referred cam force, per angle; ``radius`` [m],
    ``inertia`` J [kg m^2]."""

    theta: np.ndarray
    grid: np.ndarray
    loads: np.ndarray
    traction: np.ndarray
    sliding_scale: np.ndarray
    pin: np.ndarray
    speed_scale: float
    v_s0: np.ndarray
    ratio: np.ndarray
    radius: float
    inertia: float

    @property
    def load_cap(self) -> float:
        """The largest load of the tables [N]: above it the traction and pin torque are held."""
        return float(self.loads[-1])


def step_positions(theta: np.ndarray, angles: np.ndarray) -> np.ndarray:
    """Fractional grid positions of the step angles [rad] (unwrapped: the kernel takes the
    position modulo the grid's size), for a uniform grid ``theta`` over one revolution."""
    step = 2.0 * np.pi / theta.size
    return (np.asarray(angles, dtype=float) - float(theta[0])) / step


def spin_record(tables: RollerTables, angles: np.ndarray) -> Spin:
    """The march's record of ``tables`` at the step angles [rad] of a batch."""
    pos = step_positions(tables.theta, angles)
    n = tables.theta.size
    wrapped = np.mod(pos, n)
    ratio = np.interp(wrapped, np.arange(n + 1), np.append(tables.ratio, tables.ratio[0]))
    return Spin(1, float(tables.radius), float(tables.inertia), _plain(tables.grid),
                _plain(tables.loads), _plain(tables.traction), _plain(tables.sliding_scale),
                _plain(tables.pin), float(tables.speed_scale), _plain(tables.v_s0), _plain(pos),
                _plain(ratio))


def spin_start(record: Spin) -> tuple[float, float, float]:
    """The roller's state ``wr`` (speed, sliding speed, traction) at the start of a march:
    pure rolling at the record's first step angle's grid angle, no traction."""
    pos = int(np.floor(record.pos[0])) % record.v_s0.size
    return record.v_s0[pos] / record.radius, 0.0, 0.0


def _plain(values) -> np.ndarray:
    """A writable C-contiguous float64 copy: one compiled specialization of the march for every
    train (a read-only or strided array would compile another)."""
    return np.array(values, dtype=np.float64, order="C", copy=True)


def no_roller() -> Spin:
    """The record of a train without a marched roller (``on`` 0)."""
    one = np.zeros(1)
    return Spin(0, 1.0, 0.0, np.array([-1.0, 1.0]), np.array([0.0, 1.0]),
                np.zeros((1, 2, 2)), one, np.zeros((2, 2)), 1.0, one, one, one)
