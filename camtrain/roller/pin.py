"""Friction torque of the roller's pin: frictionless, locked, needle bearing or plain bushing.

Every model gives T(w_r, F) [N m], odd in the roller's speed w_r relative to the pin (it
opposes the rotation) and zero at w_r = 0 except where the model has a breakaway torque
(:meth:`Pin.breakaway`): the needle bearing's load-independent and load terms at rest.

* ``frictionless``: T = 0.
* ``locked``: infinite friction; the roller does not turn (w_r = 0 at every angle), the limit in
  which a roller is camtrain's non-rotating curved follower.
* ``needle``: the catalogue form of Palmgren's bearing friction, M = M_0 + M_1 [N mm] with
  M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3 for nu n >= 2000 and 160e-7 f_0 d_m^3 below (nu in cSt,
  n in rpm, d_m the pitch diameter in mm) and M_1 = f_1 F d_m (F in N): Palmgren, *Ball and
  Roller Bearing Engineering* (1959), as the bearing makers' catalogues state it (e.g. the
  INA/Schaeffler technical principles "Friction and increases in temperature"; Harris &
  Kotzalas, *Rolling Bearing Analysis*, 2006, ch. 9). The default factors f_0 = 3 and
  f_1 = 0.0005 are typical catalogue values for needle roller and cage assemblies under oil
  that this work could NOT check against a published table: a deck should give its bearing's.
  A cross-check of the order of magnitude: JTEKT/Koyo's technical page "Friction coefficient
  of bearings" (koyousa.com, catalogue section 5) gives the lumped M = mu P d/2 with
  mu = 0.0020-0.0030 for needle roller and cage assemblies, i.e. 0.0010-0.0015 in the form
  f_1 F d_m if all the torque were load-dependent (d ~ d_m).
* ``bushing``: a plain journal bearing between pin and roller bore under the roller's load at the
  roller's speed: the steady eccentricity of the Ocvirk short bearing
  (:func:`camtrain.bearings.steady.steady_eccentricity`, mean speed w_r/2 with the pin at rest)
  or of the finite-length Reynolds film (``model = "finite"``,
  :func:`camtrain.bearings.models.finite_steady_eccentricity`, held at eps 0.99 beyond its
  curve), and its Couette shear power over the complete film
  (:func:`camtrain.bearings.power.shear_power`, Martin 1985, Yang 1992 eq. 1.22), T = P / w_r.
  Hydrodynamic only: no mixed friction at very low speed.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

PIN_KINDS = ("frictionless", "locked", "needle", "bushing")
#: nu n [cSt rpm] below which the catalogue form holds M_0 at its low-speed value
NU_N_LIMIT = 2000.0


@dataclass(frozen=True)
class Pin:
    """The roller's pin (SI): ``kind``; needle: pitch diameter [m], oil kinematic viscosity
    [m^2/s], factors f_0, f_1 [-]; bushing: a :class:`camtrain.bearings.JournalBearing`."""

    kind: str = "frictionless"
    pitch_diameter: float = 0.0
    kinematic_viscosity: float = 0.0
    f0: float = 3.0
    f1: float = 0.0005
    bearing: object = None
    model: str = "short"

    def __post_init__(self):
        if self.kind not in PIN_KINDS:
            raise ValueError(f"pin kind {self.kind!r}: expected one of {PIN_KINDS}")
        if self.kind == "bushing" and self.bearing is None:
            raise ValueError("a bushing pin needs its journal bearing")

    def torque(self, omega_roller, load) -> np.ndarray:
        """T [N m] opposing w_r (signed as w_r) under the pin load ``load`` [N]."""
        w = np.asarray(omega_roller, dtype=float)
        F = np.broadcast_to(np.maximum(np.asarray(load, dtype=float), 0.0), w.shape)
        if self.kind in ("frictionless", "locked"):
            return np.zeros(w.shape)
        if self.kind == "needle":
            return np.sign(w) * needle_torque(np.abs(w), F, self.pitch_diameter,
                                              self.kinematic_viscosity, self.f0, self.f1)
        return bushing_torque(self.bearing, w, F, self.model)

    def breakaway(self, load) -> np.ndarray:
        """Torque [N m] the pin holds at rest (the limit of |T| as w_r -> 0+)."""
        F = np.maximum(np.asarray(load, dtype=float), 0.0)
        if self.kind != "needle":
            return np.zeros(F.shape)
        return needle_torque(np.zeros(F.shape), F, self.pitch_diameter,
                             self.kinematic_viscosity, self.f0, self.f1)


def needle_torque(speed, load, pitch_diameter, kinematic_viscosity, f0, f1):
    """Palmgren's M_0 + M_1 [N m] at |w_r| = ``speed`` [rad/s] (see the module docstring)."""
    n = np.asarray(speed, dtype=float) * 60.0 / (2.0 * math.pi)       # rpm
    nu_n = kinematic_viscosity * 1e6 * n                                # cSt rpm
    dm = pitch_diameter * 1e3                                           # mm
    m0 = np.where(nu_n >= NU_N_LIMIT, 1e-7 * f0 * np.abs(nu_n) ** (2.0 / 3.0) * dm ** 3,
                  160e-7 * f0 * dm ** 3)
    m1 = f1 * np.asarray(load, dtype=float) * dm
    return (m0 + m1) * 1e-3                                             # N mm -> N m


def bushing_torque(bearing, omega_roller, load, model: str = "short") -> np.ndarray:
    """Hydrodynamic friction torque [N m] of a plain bushing (see the module docstring);
    ``model`` short (Ocvirk) or finite (the finite-length Reynolds film's steady curve)."""
    from camtrain.bearings.models import finite_steady_eccentricity
    from camtrain.bearings.power import shear_power
    from camtrain.bearings.steady import steady_eccentricity

    w = np.asarray(omega_roller, dtype=float)
    out = np.zeros(w.shape)
    turning = w != 0.0
    if np.count_nonzero(turning):
        ww = w[turning]
        F = np.asarray(load)[turning]
        if model == "finite":
            eps = np.atleast_1d(finite_steady_eccentricity(bearing, F, 0.5 * ww))
        else:
            eps = np.atleast_1d(steady_eccentricity(bearing, F, 0.5 * ww))
        power = shear_power(bearing, eps, -0.5 * np.pi, ww, film="2pi")
        out[turning] = power / ww
    return out
