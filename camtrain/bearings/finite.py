"""Finite-length journal bearing at steady load: eccentricity, attitude, minimum film, friction
and side flow from the Reynolds solution over the whole bearing (:mod:`.reynolds`).

The performance variables are Raimondi & Boyd's (1958): Sommerfeld number
``S = (R/c)^2 eta N L D / W`` (N in rev/s), attitude angle, friction variable ``(R/c) f``
(journal friction with the clearance full of oil everywhere, so that eps -> 0 gives Petroff's
``2 pi^2 S``), flow variable ``Q / (R c N L)`` (circumferential flow entering the film at the
feed line) and side-flow ratio ``Q_s / Q``.

Units: SI throughout. The load is the load the journal puts on the film; a bearing with a full
circumferential central groove is two finite lands of ``bearing.land`` each carrying half of it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from camtrain.errors import field_error

from .geometry import JournalBearing
from .reynolds import CAVITATION, FilmField, FilmGrid, solve_film

__all__ = ["FEEDS", "FinitePerformance", "FiniteSteady", "finite_performance", "finite_steady",
           "film_grid"]

#: Oil feed of a steady solve: "none" (no groove: free Swift-Stieber boundaries both ends of the
#: film) or "max_film" (an axial line at ambient pressure at the thickest film, Raimondi & Boyd).
FEEDS = ("none", "max_film")
DEFAULT_MESH = (120, 12)


def film_grid(b_over_d: float, n_theta: int = DEFAULT_MESH[0], n_z: int = DEFAULT_MESH[1]):
    """Mesh over one half of a bearing of ratio b/d (land length over diameter)."""
    return FilmGrid(float(b_over_d), int(n_theta), int(n_z))


def _feed(feed: str):
    if feed not in FEEDS:
        raise field_error("feed", "unknown oil feed", feed, " or ".join(FEEDS))
    return (0.0, 0.0, 1.0) if feed == "max_film" else None


@dataclass(frozen=True)
class FinitePerformance:
    """Dimensionless steady performance at one eccentricity (Raimondi & Boyd variables).

    Attributes:
        b_over_d, eps: land length / diameter and eccentricity ratio.
        sommerfeld: S = (R/c)^2 eta N L D / W.
        attitude: angle from the load to the line of centres [rad] (in the sense of rotation).
        friction_variable: (R/c) f, journal friction, clearance full of oil.
        friction_variable_fraction: the same with Couette shear only where the JFO film
            fraction carries oil (equal to friction_variable unless cavitation = "jfo").
        flow_variable: Q/(R c N L), flow entering the film at the feed line (theta = 0).
        side_flow_ratio: Q_s / Q, leakage out of both ends over the inflow.
        pressure_ratio: mean pressure W/(L D) over the peak film pressure.
        load: dimensionless load W c^2 / (12 eta wbar R^4) (with wbar = omega_j/2).
        field: the film solution.
    """

    b_over_d: float
    eps: float
    sommerfeld: float
    attitude: float
    friction_variable: float
    friction_variable_fraction: float
    flow_variable: float
    side_flow_ratio: float
    pressure_ratio: float
    load: float
    field: FilmField


def _integrals(field: FilmField):
    """Full-length integrals over the film: Couette shear factors and end/inlet flows."""
    g = field.grid
    th, wz = g.theta, g.z_simpson
    h = 1.0 + field.eps * np.cos(th)
    wt = 2.0 * wz[:, None] * g.d_theta  # both halves
    shear_full = float(np.sum(wt / h[None, :]))
    shear_frac = float(np.sum(wt * field.fraction / h[None, :]))
    P = field.pressure
    # inflow at theta = 0+ (one-sided second-order derivative, P(0) held by the feed)
    dp = (-3.0 * P[:, 0] + 4.0 * P[:, 1] - P[:, 2]) / (2.0 * g.d_theta)
    q_in = 2.0 * float(np.sum(wz * (h[0] - h[0] ** 3 * dp)))
    # leakage out of both ends
    dz = (3.0 * P[-1] - 4.0 * P[-2] + P[-3]) / (2.0 * g.d_z)
    q_side = -2.0 * float(np.sum(h ** 3 * dz) * g.d_theta)
    return shear_full, shear_frac, q_in, q_side


def finite_performance(b_over_d: float, eps: float, *, cavitation: str = "reynolds",
                       feed: str = "max_film", n_theta: int = DEFAULT_MESH[0],
                       n_z: int = DEFAULT_MESH[1], start=None) -> FinitePerformance:
    """Raimondi & Boyd's steady variables of a finite bearing (fixed bush, load steady).

    Scale: omega_ref = wbar = omega_j/2, so S = (b/d) / (3 pi F) with F the dimensionless
    load, and (R/c) f = (2 I_shear + 6 eps I_sin) / (12 F) where I_sin = int P sin(theta) is
    the pressure part of the journal friction (it equals W e sin(phi) / R).
    """
    grid = film_grid(b_over_d, n_theta, n_z)
    field = solve_film(grid, float(eps), cavitation=cavitation, feed=_feed(feed), start=start)
    load = math.hypot(field.force_r, field.force_t)
    if load <= 0.0:
        raise field_error("eps", "no load carried (eccentricity zero)", eps, "eps > 0")
    att = math.atan2(-field.force_t, field.force_r)
    s_full, s_frac, q_in, q_side = _integrals(field)
    i_sin = -field.force_t
    ld = float(b_over_d)
    pmax = float(np.max(field.pressure))
    flow = math.pi * q_in / (2.0 * ld)
    return FinitePerformance(
        b_over_d=ld, eps=float(eps), sommerfeld=ld / (3.0 * math.pi * load), attitude=att,
        friction_variable=(2.0 * s_full + 6.0 * eps * i_sin) / (12.0 * load),
        friction_variable_fraction=(2.0 * s_frac + 6.0 * eps * i_sin) / (12.0 * load),
        flow_variable=flow, side_flow_ratio=(math.pi * q_side / (2.0 * ld)) / flow,
        pressure_ratio=load / (4.0 * ld * pmax) if pmax > 0 else math.inf, load=load,
        field=field)
