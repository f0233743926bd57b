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
  Roller Bearing Engineering* (1959), as the bearing makers' catalogues state it (Harris &
  Kotzalas, *Rolling Bearing Analysis*, 2006, ch. 9). The Schaeffler (INA) technical
  principles "Rolling bearings - Friction and increases in temperature" (medias.ina.de) give
  this form with f_0 and f_1 read from a table by bearing series and lubrication; a search of
  the public material available to this work (2026) found that page's introduction but neither
  its formula text nor its table, so the default factors f_0 = 3 and f_1 = 0.0005 (typical of
  needle roller and cage assemblies under oil) remain UNCHECKED: a deck should give its
  bearing's. Cross-checks of the order of magnitude, both lumping the whole torque into one
  coefficient: JTEKT/Koyo's technical page "Friction coefficient of bearings" (catalogue
  section 5, Table 4-1) gives M = mu P d/2 with mu = 0.0020-0.0030 for needle roller and cage
  assemblies (d the bore), and RoyMech's table of rolling-bearing friction mu_m = 0.003 on the
  mean diameter for caged needle roller bearings. With a 10 mm pitch diameter, 1 kN and
  60 cSt at 7600 rpm (the roller deck's nose) the defaults give 1.8 + 5.0 = 6.8 N mm, the
  lumped coefficients 8-15 N mm (8 mm bore).
* ``bushing``: a plain journal bearing between pin and roller bore under the roller's load at the
  roller's speed: the steady eccentricity of the Ocvirk short bearing
  (:func:`camtrain.bearings.steady.steady_eccentricity`, mean speed w_r/2 with the pin at rest)
  or of the finite-length Reynolds film (``model = "finite"``,
  :func:`camtrain.bearings.models.finite_steady_eccentricity`, held at eps 0.99 beyond its
  curve), and its Couette shear power over the complete film
  (:func:`camtrain.bearings.power.shear_power`, Martin 1985, Yang 1992 eq. 1.22), T = P / w_r,
  plus the pressure term below (``terms``).
  Hydrodynamic by default. With ``asperities`` (the deck's ``roller.pin_friction = "mixed"``)
  the Greenwood-Tripp asperity friction of the bushing is added where the minimum film
  h_min = c (1 - eps) falls below lambda = 3 composite roughnesses: F_b = tau_0 A_a + m W_a
  (Greenwood & Tripp 1970 asperity load and area, Teodorescu et al. 2005 eqs. 8-15, as the
  cam-roller traction takes them, :func:`camtrain.formulas.teodorescu_2005_friction`) at the
  pin radius, T_b = F_b d/2, with the nominal area the bushing's projected area d L (a named
  choice: the asperities of a conformal bearing touch over its loaded arc, of the order of its
  projection), W_a capped at the pin load. The Couette torque is kept whole (the film's share
  of the area is not taken off: an upper bound of the viscous part). At rest no film carries
  load and the asperities carry all of it: the breakaway torque (tau_0 A_a(0) + m W) d/2.

  ``terms`` (the deck's ``roller.pin_terms``): the friction torque of a loaded journal bearing
  on its turning member is the Couette shear **plus the pressure (Poiseuille) term**
  W e sin(phi) / 2, e = c eps, phi the attitude angle: Yang (1992) eq. 1.20 with no
  translation, power wbar W e sin(phi) at the mean speed wbar = w_r / 2, which is the standard
  friction coefficient of a journal bearing, mu r/c = 2 pi^2 S / sqrt(1 - eps^2)
  + eps sin(phi) / 2 (Raimondi & Boyd 1958; Hamrock, *Fundamentals of Fluid Film
  Lubrication*, 2004, ch. 10-11). ``all`` (default) keeps both; ``shear`` the Couette term
  alone (camtrain's earlier bushing, and the bearings' ``terms = "shear"``). Under a heavy load
  the pressure term dominates (for the short bearing near eps -> 1 it is about
  L^2 / (16 R^2 (1 - eps^2)) times the Couette term), so leaving it out underrates the pin's
  loss exactly where Alakhramsing et al. (2018) find the pin the largest loss. phi is Ocvirk's
  atan[pi sqrt(1 - eps^2) / (4 eps)] for ``model = "short"`` and the finite film's steady
  attitude for ``"finite"``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

PIN_KINDS = ("frictionless", "locked", "needle", "bushing")
#: bushing torque terms: Couette shear and pressure (standard), or the shear alone
PIN_TERMS = ("all", "shear")
#: nu n [cSt rpm] below which the catalogue form holds M_0 at its low-speed value
NU_N_LIMIT = 2000.0


@dataclass(frozen=True)
class Asperities:
    """Greenwood-Tripp asperities of a plain bushing (SI): composite roughness sigma [m],
    asperity radius beta [m], density zeta [1/m^2], reduced modulus E' [Pa], boundary shear
    strength tau_0 [Pa] and its pressure coefficient m [-], film-parameter limit of mixed
    lubrication (Teodorescu et al. 2005: 3)."""

    sigma: float
    beta: float
    zeta: float
    reduced_modulus: float
    tau0: float
    m: float
    lambda_limit: float = 3.0


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
    asperities: Asperities | None = None
    terms: str = "all"

    def __post_init__(self):
        if self.kind not in PIN_KINDS:
            raise ValueError(f"pin kind {self.kind!r}: expected one of {PIN_KINDS}")
        if self.kind == "bushing" and self.bearing is None:
            raise ValueError("a bushing pin needs its journal bearing")
        if self.terms not in PIN_TERMS:
            raise ValueError(f"pin torque terms {self.terms!r}: expected one of {PIN_TERMS}")

    def torque(self, omega_roller, load) -> np.ndarray:
        """T [N m] opposing w_r (signed as w_r) under the pin load ``load`` [N]."""
        w = np.asarray(omega_roller, dtype=float)
        F = np.broadcast_to(np.maximum(np.asarray(load, dtype=float), 0.0), w.shape)
        if self.kind in ("frictionless", "locked"):
            return np.zeros(w.shape)
        if self.kind == "needle":
            return np.sign(w) * needle_torque(np.abs(w), F, self.pitch_diameter,
                                              self.kinematic_viscosity, self.f0, self.f1)
        return bushing_torque(self.bearing, w, F, self.model, self.asperities, self.terms)

    def free_at(self, omega_roller, load) -> np.ndarray:
        """Where the pin holds no torque at ``omega_roller`` (``torque(...) == 0``). A needle
        bearing with f_0 > 0 holds torque at every nonzero speed (its M_0 > 0), so there it
        is w_r = 0 alone, without evaluating the torque."""
        w = np.asarray(omega_roller, dtype=float)
        if self.kind == "needle" and self.f0 > 0.0 and self.pitch_diameter > 0.0:
            return w == 0.0
        return self.torque(w, load) == 0.0

    def breakaway(self, load) -> np.ndarray:
        """Torque [N m] the pin holds at rest (the limit of |T| as w_r -> 0+)."""
        F = np.maximum(np.asarray(load, dtype=float), 0.0)
        if self.kind == "bushing" and self.asperities is not None:
            return rest_torque(self.bearing, self.asperities, F)
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


def bushing_torque(bearing, omega_roller, load, model: str = "short",
                   asperities: Asperities | None = None, terms: str = "all") -> np.ndarray:
    """Friction torque [N m] of a plain bushing (see the module docstring), signed as w_r;
    ``model`` short (Ocvirk) or finite (the finite-length Reynolds film's steady curve);
    ``asperities`` adds the Greenwood-Tripp asperity friction of a mixed film; ``terms`` all
    (Couette shear and the pressure term) or shear."""
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
        if terms == "all":
            out[turning] += np.sign(ww) * pressure_torque(bearing, eps, F, model)
        if asperities is not None:
            out[turning] += np.sign(ww) * asperity_torque(
                bearing, asperities, np.minimum(eps, 1.0), F)
    return out


def pressure_torque(bearing, eccentricity, load, model: str = "short") -> np.ndarray:
    """Pressure (Poiseuille) part of a journal bearing's friction torque on its turning member
    [N m], W c eps sin(phi) / 2 (Yang 1992 eq. 1.20 with no translation, over the speed; the
    eps sin(phi) / 2 term of the friction coefficient mu r/c of Raimondi & Boyd 1958), with
    the attitude phi of the short (Ocvirk) or the finite film (see the module docstring)."""
    from camtrain.bearings.models import finite_steady_attitude
    from camtrain.formulas.bearings import ocvirk_attitude_angle

    eps = np.minimum(np.asarray(eccentricity, dtype=float), np.nextafter(1.0, 0.0))
    phi = (finite_steady_attitude(bearing, eps) if model == "finite"
           else ocvirk_attitude_angle(eps))
    return 0.5 * np.asarray(load, dtype=float) * bearing.clearance * eps * np.sin(phi)


def rest_torque(bearing, asperities: Asperities, load) -> np.ndarray:
    """Breakaway torque [N m] of a mixed bushing at rest: no film carries load, so the
    asperities carry all of it, (tau_0 A_a(0) + m W) d/2 with A_a(0) the Greenwood-Tripp area
    at lambda = 0 (capped at the projected area d L)."""
    from camtrain.formulas.mixed import greenwood_tripp_1970_area

    a = asperities
    area = bearing.diameter * bearing.length
    touching = min(float(greenwood_tripp_1970_area(0.0, area, a.sigma, a.beta, a.zeta)), area)
    return (a.tau0 * touching + a.m * np.asarray(load, dtype=float)) * 0.5 * bearing.diameter


def asperity_torque(bearing, asperities: Asperities, eccentricity, load) -> np.ndarray:
    """Greenwood-Tripp asperity friction torque [N m] (>= 0) of a bushing at eccentricity
    ratio eps under ``load`` [N]: (tau_0 A_a + m W_a) d/2 at h_min = c (1 - eps) over the
    projected area d L, W_a <= load (see the module docstring)."""
    from camtrain.formulas import teodorescu_2005_friction

    a = asperities
    eps = np.asarray(eccentricity, dtype=float)
    W = np.broadcast_to(np.asarray(load, dtype=float), eps.shape)
    lam = bearing.clearance * (1.0 - eps) / a.sigma
    out = np.zeros(eps.shape)
    mixed = lam < a.lambda_limit
    if np.count_nonzero(mixed):
        area = bearing.diameter * bearing.length
        n = np.count_nonzero(mixed)
        t = teodorescu_2005_friction(W[mixed], np.full(n, area), lam[mixed], a.tau0, 0.0, a.m,
                                     a.reduced_modulus, np.full(n, a.sigma),
                                     np.full(n, a.beta), np.full(n, a.zeta),
                                     lambda_limit=a.lambda_limit)
        out[mixed] = t.boundary * 0.5 * bearing.diameter
    return out
