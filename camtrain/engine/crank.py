"""Slider-crank kinematics and the loads of one cylinder (Yang 1992 §1.2.1, eqs 1.1-1.5, 2.1).

Frames and signs (SI, radians). Block axes: ``y`` along the cylinder axis from the crank centre
towards the piston, ``x`` normal to it; the crank turns counter-clockwise (+z) at ``omega > 0``.
The crank angle ``theta`` of a cylinder is measured from its firing TDC in the sense of
rotation, so the throw points along ``rhat = (-sin theta, cos theta)``. The rod obliquity
``psi`` has ``sin psi = (R/L) sin theta`` and the rod axis (big end -> small end) is
``u = (sin psi, cos psi)``. Rod axes: ``y_r`` along ``u``, ``x_r`` normal to it; a block vector
turns into rod axes by a rotation of ``+psi``.

Two-mass rod (Yang §1.2.1): ``m_c/3`` reciprocates with the piston, ``2 m_c/3`` rotates with
the pin. The piston acceleration ``a`` is positive towards the crank (so ``a(0) = R omega^2
(1 + R/L)``); the net axial force on the rod, positive in compression, is
``F_ax = F_G - (m_p + m_c/3) a``.
"""
from __future__ import annotations

import numpy as np

from camtrain.errors import field_error

__all__ = ["rod_obliquity", "piston_acceleration_yang", "slider_crank_exact", "gas_force",
           "reciprocating_force", "rotating_force", "side_thrust", "big_end_load_rod_frame",
           "rod_frame_journal_speed", "ROD_SPEEDS"]

#: Journal speed relative to the rod: Yang's small-angle eq. 2.1 or the exact rod swing.
ROD_SPEEDS = ("small_angle", "exact")


def _ratio(crank_radius: float, rod_length: float) -> float:
    lam = crank_radius / rod_length
    if not (0.0 < lam < 1.0):
        raise field_error("engine.rod_length", "must be longer than the crank radius",
                          rod_length, f"> {crank_radius} m")
    return lam


def rod_obliquity(theta, crank_radius: float, rod_length: float):
    """Rod angle psi [rad] from sin psi = (R/L) sin theta (Yang §1.2.1; Williams A5.7)."""
    return np.arcsin(_ratio(crank_radius, rod_length) * np.sin(theta))


def piston_acceleration_yang(theta, crank_radius: float, rod_length: float, omega: float):
    """Piston acceleration towards the crank [m/s^2], Yang (1992) eq. 1.2 (Shaw & Macks 1949).

    a = R omega^2 {cos theta + [((L/R)^2 - 1) cos 2 theta + cos^4 theta] /
    [(L/R)^2 - sin^2 theta]^(3/2)}, exact for constant omega.
    """
    n2 = _ratio(crank_radius, rod_length) ** -2  # (L/R)^2
    s2 = np.sin(theta) ** 2
    c = np.cos(theta)
    return crank_radius * omega ** 2 * (c + ((n2 - 1.0) * np.cos(2.0 * theta) + c ** 4)
                                        / (n2 - s2) ** 1.5)


def slider_crank_exact(theta, crank_radius: float, rod_length: float, omega: float):
    """Exact slider crank at constant speed, Williams (2013) App. A5 (eqs A5.1-A5.10).

    Returns (x, x_dot, x_ddot, psi, psi_dot): piston-pin distance from the crank centre [m],
    its rate [m/s] and acceleration [m/s^2] (positive away from the crank), the rod angle
    [rad] and its rate [rad/s] (A5.8).
    """
    r, ell = crank_radius, rod_length
    _ratio(r, ell)
    th = np.asarray(theta, dtype=float)
    phi = np.arcsin(r * np.sin(th) / ell)                                       # A5.7
    phid = r * np.cos(th) * omega / (ell * np.cos(phi))                        # A5.8
    phidd = (-r * np.sin(th) * omega ** 2 + ell * np.sin(phi) * phid ** 2) / (ell * np.cos(phi))
    x = r * np.cos(th) + ell * np.cos(phi)                                      # A5.1
    xd = -r * np.sin(th) * omega - ell * np.sin(phi) * phid                     # A5.3
    xdd = (-r * np.cos(th) * omega ** 2 - ell * np.sin(phi) * phidd
           - ell * np.cos(phi) * phid ** 2)                                     # A5.4, A5.10
    return x, xd, xdd, phi, phid


def gas_force(pressure, bore: float):
    """Gas force on the piston [N], Yang eq. 1.1: F_G = (pi/4) P D^2 (P gauge [Pa])."""
    return 0.25 * np.pi * bore ** 2 * np.asarray(pressure, dtype=float)


def reciprocating_force(piston_mass: float, rod_mass: float, acceleration):
    """Reciprocating inertia magnitude (m_p + m_c/3) a [N], Yang eq. 1.3 (a towards the crank)."""
    return (piston_mass + rod_mass / 3.0) * np.asarray(acceleration, dtype=float)


def rotating_force(rod_mass: float, crank_radius: float, omega: float) -> float:
    """Rotating inertia of the big end, (2/3) m_c R omega^2 [N], Yang eq. 1.4 (outward)."""
    return 2.0 / 3.0 * rod_mass * crank_radius * omega ** 2


def side_thrust(axial_force, psi):
    """Side thrust of the piston on the liner [N], Yang eq. 1.5: F_T = F_ax tan psi.

    Positive along +x (block axes) for a rod in compression tilted with psi > 0.
    """
    return np.asarray(axial_force, dtype=float) * np.tan(psi)


def big_end_load_rod_frame(axial_force, psi, theta, rotating: float):
    """Load of the crank pin on the big-end bush, in rod axes [N] (Yang §1.2.1, Fig. 1.1).

    F_B = (F_ax / cos psi) u - (2/3) m_c R omega^2 rhat; in rod axes u = (0, 1) and rhat is at
    theta + psi from y_r. Returns (F_x_r, F_y_r). The journal moves towards F_B in the bush.
    """
    rod = np.asarray(axial_force, dtype=float) / np.cos(psi)
    ang = np.asarray(theta, dtype=float) + psi
    return rotating * np.sin(ang), rod - rotating * np.cos(ang)


def rod_frame_journal_speed(theta, crank_radius: float, rod_length: float, omega: float,
                            form: str = "small_angle"):
    """Crank-pin speed relative to the rod [rad/s] (the bush is the rod: omega_b = 0).

    ``small_angle``: omega (1 + (R/L) cos theta), Yang eq. 2.1 (his wbar is half of it).
    ``exact``: omega (1 + (R/L) cos theta / cos psi) = omega + psi_dot (Williams A5.8).
    """
    lam = _ratio(crank_radius, rod_length)
    th = np.asarray(theta, dtype=float)
    if form == "small_angle":
        return omega * (1.0 + lam * np.cos(th))
    if form == "exact":
        return omega * (1.0 + lam * np.cos(th) / np.cos(np.arcsin(lam * np.sin(th))))
    raise field_error("engine.solver.rod_speed", "unknown rod-frame speed", form,
                      " or ".join(ROD_SPEEDS))
