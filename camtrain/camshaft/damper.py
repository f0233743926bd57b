"""Centrifugal pendulum (bifilar) dampers tuned to camshaft torque orders (Williams 2013 ch 10).

Symbols (SI): R radius of the pendulum pivot from the shaft axis [m]; r effective pendulum
length [m]; m pendulum mass [kg]; n order (cycles per shaft revolution); Omega0 mean shaft
speed [rad/s]; Lambda amplitude of the shaft angle fluctuation [rad].
Small-angle, undamped theory as in the source.
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.errors import field_error

from .harmonics import harmonic_orders, order_curve

__all__ = ["absorber_mass_ratio", "tuned_order", "pendulum_amplitude_ratio",
           "pendulum_effective_inertia", "bifilar_length", "damper_motion", "idler_order",
           "optimum_damper"]


def _pos(name, v):
    v = float(v)
    if not (v > 0 and math.isfinite(v)):
        raise field_error(name, "must be a finite number > 0", v)
    return v


def absorber_mass_ratio(omega, omega0):
    """Effective-mass ratio of a dynamic absorber, m_E/m = 1/(1 - (omega/omega0)^2).

    Williams (2013) eq. 10.30; infinite at tuning, negative above it (the absorber then makes
    the vibration worse).
    """
    r2 = (np.asarray(omega, dtype=float) / _pos("omega0", omega0)) ** 2
    with np.errstate(divide="ignore"):
        return 1.0 / (1.0 - r2)


def tuned_order(R, r):
    """Order to which a pendulum is tuned, n = sqrt(R/r) (Williams eq. 10.59)."""
    return math.sqrt(_pos("R", R) / _pos("r", r))


def pendulum_amplitude_ratio(R, r, n):
    """Pendulum swing per unit shaft angle fluctuation, beta/Lambda = (R + r) n^2/(R - r n^2).

    Williams eq. 10.52. Diverges at n^2 = R/r.
    """
    R, r = _pos("R", R), _pos("r", r)
    d = R - r * n * n
    if d == 0:
        raise field_error("r", "pendulum exactly tuned: amplitude ratio is infinite", r)
    return (R + r) * n * n / d


def pendulum_effective_inertia(m, R, r, n):
    """Effective inertia of one pendulum at order n, I_E = m (R + r)^2 / (1 - (r/R) n^2) [kg m^2].

    Williams eq. 10.57 (corrected 10.55: R - r n^2, and sin n Omega0 t). Design with R/r
    slightly above n^2 so that I_E is large and positive; wear lengthens r and can make it
    negative.
    """
    m, R, r = _pos("m", m), _pos("R", R), _pos("r", r)
    d = 1.0 - (r / R) * n * n
    if d == 0:
        raise field_error("r", "pendulum exactly tuned: effective inertia is infinite", r)
    return m * (R + r) ** 2 / d


def bifilar_length(hole_diameter, pin_diameter):
    """Effective pendulum length of a bifilar (Sarazin/Chilton) damper, r = D1 - D2 [m].

    Williams eq. 10.60 (D1 hole diameter in weight and carrier, D2 pin diameter).
    """
    d1, d2 = _pos("hole_diameter", hole_diameter), _pos("pin_diameter", pin_diameter)
    if d2 >= d1:
        raise field_error("pin_diameter", "pin must be smaller than the hole", d2, f"< {d1}")
    return d1 - d2


def damper_motion(torque_amplitude, count, n, omega0, m, R, r):
    """Shaft angle fluctuation and pendulum swing when N pendulums of order n cancel a torque.

    Williams eqs 10.64, 10.65: Lambda = T / (N n^2 Omega0^2 I_E), beta = Lambda (R + r) n^2 /
    (R - r n^2). Returns (Lambda, beta) in rad; beta must stay small for linear behaviour.
    (Combined: beta = T / (N m Omega0^2 R (R + r)), independent of detuning.)
    """
    T = abs(float(torque_amplitude))
    count = int(count)
    if count < 1:
        raise field_error("count", "need at least one pendulum", count)
    om = _pos("omega0", omega0)
    ie = pendulum_effective_inertia(m, R, r, n)
    lam = T / (count * n * n * om * om * ie)
    return lam, lam * pendulum_amplitude_ratio(R, r, n)


def idler_order(n, teeth_idler, teeth_cam):
    """Order for a damper on an idler gear driving the camshaft: n~ = (N1/N2) n (Williams 10.66-68).

    N1 idler teeth, N2 camshaft-gear teeth; generally not an integer, and tuned at all speeds.
    """
    return float(n) * _pos("teeth_idler", teeth_idler) / _pos("teeth_cam", teeth_cam)


def optimum_damper(torque, orders):
    """Ideal damper that removes exactly the chosen orders (Williams Tables 9.9, 9.10).

    Returns (damper_torque, damped_torque): damper = sum of the selected order components,
    damped = torque - damper [N m], on the input grid.
    """
    y = np.asarray(torque, dtype=float)
    damper = order_curve(harmonic_orders(y), orders, y.size)
    return damper, y - damper
