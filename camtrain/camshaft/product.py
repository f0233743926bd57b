"""The camshaft product: summed torque and the lobe forces the camshaft bearings carry."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class CamshaftLoads:
    """Summed torque [N m] of this shaft's lobes, each lobe's axial position [m] and force on
    the shaft (x, y) [N] per angle, and the signed shaft speed [rad/s]."""

    torque: np.ndarray
    lobe_positions: tuple[float, ...]
    lobe_forces: tuple[tuple[np.ndarray, np.ndarray], ...]
    omega: float
