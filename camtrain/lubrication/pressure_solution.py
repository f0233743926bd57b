"""The result of a 1-D Reynolds pressure solve across the cam contact, shared by the
semi-analytic solver (`reynolds`) and the finite-difference reference (`reynolds_fd`)."""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = ["CAVITATION_MODELS", "PressureSolution"]

CAVITATION_MODELS = ("reynolds", "half_sommerfeld")


class PressureSolution(NamedTuple):
    pressure: np.ndarray      #: p(x) >= 0 [Pa] (negative pressures dropped)
    load: float               #: integral of p dx [N/m]
    rupture: float            #: film-rupture position x_c [m] (nan: none in the zone)
    flooded: bool             #: True if no rupture point lies inside the zone (Reynolds BC)
    liquid_fraction: np.ndarray  #: 1 in the full film, h_T(x_c)/h_T(x) in the cavitated zone
