"""Oil-control ring and piston skirt (Yang 1992 §5.5), and cycle-mean power of a piston part.

The oil-control ring runs in boundary lubrication under its own elastic tension only:
F_ocr = mu T_ocr b_ocr pi D with mu = 0.08. The skirt is a rigid, concentric, flooded Couette
film (eq. 5.37): F_s = pi D int_0^L_s eta U / C_s(x) dx. The source gives neither the skirt height
nor its clearance profile: both are inputs with no default.
"""
from __future__ import annotations

import numpy as np

from camtrain.piston.ring import RING_BOUNDARY_FRICTION


def oil_control_ring_friction(U, tension: float, height: float, bore: float,
                              mu: float = RING_BOUNDARY_FRICTION):
    """Friction force [N] on the oil-control ring, along the liner's motion (Yang §5.5)."""
    return mu * tension * height * np.pi * bore * np.sign(np.asarray(U, dtype=float))


def skirt_friction(U, eta, bore: float, height: float, clearance_x, clearance):
    """Couette friction force [N] of the skirt (Yang eq. 5.37).

    ``clearance_x`` [m] along the skirt (0 ... ``height``) and ``clearance`` [m] the radial
    clearance there (taper or barrel); ``eta`` [Pa s] per angle or scalar; ``U`` [m/s].
    """
    from scipy.integrate import trapezoid

    x = np.asarray(clearance_x, dtype=float)
    c = np.asarray(clearance, dtype=float)
    if x[0] != 0.0 or not np.isclose(x[-1], height) or np.any(np.diff(x) <= 0) or np.any(c <= 0):
        raise ValueError("skirt clearance profile must run from 0 to the skirt height with "
                         "positive clearances")
    return np.pi * bore * np.asarray(eta) * np.asarray(U, dtype=float) * trapezoid(1.0 / c, x)


def cycle_mean_power(force, U) -> float:
    """Time-mean friction power [W] over a uniform crank-angle grid of one whole cycle.

    Yang's eq. 5.32 divides the integral over a 4-stroke cycle by 2 pi; the time mean divides by
    the cycle, 4 pi (camtrain's default). Pass ``force`` on the ring along the liner's motion.
    """
    return float(np.mean(np.asarray(force, dtype=float) * np.asarray(U, dtype=float)))
