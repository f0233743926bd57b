"""The camshaft product: summed torque and the lobe forces the camshaft bearings carry."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class CamshaftLoads:
    """Summed torque [N m] of this shaft's lobes, each lobe's axial position [m] and force on
    the shaft (x, y) [N] per angle, the signed shaft speed [rad/s] and each lobe's own torque
    [N m] (the torque it takes to turn that lobe, in the sense of rotation)."""

    torque: np.ndarray
    lobe_positions: tuple[float, ...]
    lobe_forces: tuple[tuple[np.ndarray, np.ndarray], ...]
    omega: float
    lobe_torques: tuple[np.ndarray, ...] = ()


@dataclass(frozen=True)
class ElasticCamshaft:
    """The elastic camshaft's periodic response over one revolution (Teodorescu et al. 2005
    §2.6): the load each bearing carries (x, y) [N], shape (n_bearings, n_angles); the
    deflection (x, y) [m] and twist [rad] at every lobe station, shape (n_lobes, n_angles);
    ``split`` = how the bearings shared the loads (elastic, determinate, equal_share)."""

    bearing_x: np.ndarray
    bearing_y: np.ndarray
    deflection_x: np.ndarray
    deflection_y: np.ndarray
    twist: np.ndarray
    split: str
