"""The dynamics effect's product of the roller's spin: its speed marched with the elastic train."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class RollerSpin:
    """The roller's speed on its pin marched with the elastic train, on the run's cam-angle
    grid (SI), which the roller effect takes as the run's roller speed.

    ``speed`` w_r [rad/s] per angle, None when the train marched no roller (no [roller], a
    locked pin, or ``dynamics.roller = "after"``: the roller effect then solves its own speed);
    ``traction`` [N] per angle the traction the march balanced that speed with (its tables at
    the marched load, signed as the sliding u_s; None with the speed); ``inertia`` J
    [kg m^2] the spin inertia marched (0 without a marched roller)."""

    speed: np.ndarray | None = None
    traction: np.ndarray | None = None
    inertia: float = 0.0

    @property
    def marched(self) -> bool:
        """The train marched the roller's speed."""
        return self.speed is not None
