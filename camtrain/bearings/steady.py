"""Steady-load (quasi-static) journal position: the Ocvirk short bearing at every instant.

Yang (1992) eq. 1.13: eps wbar = [4 F c^2 / (eta d b^3)] (1 - eps^2)^2 / sqrt(16 eps^2 +
pi^2 (1 - eps^2)), identical to Ocvirk's W(eps) with journal speed 2 wbar; solved at each angle
from |W| alone (squeeze ignored). As printed, Yang uses wbar = (omega_j + omega_b)/2, not the
load-relative speed; so does this module. A grooved bearing carries W/2 on each land.
The line of centres leads the load by the Ocvirk attitude angle in the sense of wbar.
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.errors import field_error
from camtrain.formulas.bearings import ocvirk_attitude_angle, ocvirk_eccentricity

from .geometry import JournalBearing
from .orbit import assemble_orbit, diagram_rate, load_diagram
from .power import check_film, check_terms
from .result import JournalOrbit

__all__ = ["steady_eccentricity", "steady_eccentricity_vector", "steady_orbit"]


def steady_eccentricity(bearing: JournalBearing, load, wbar):
    """Eccentricity ratio under a steady load magnitude ``load`` [N] at mean speed wbar [rad/s]."""
    load = np.abs(np.asarray(load, dtype=float))
    w = np.abs(np.asarray(wbar, dtype=float))
    if np.any((w == 0) & (load > 0)):
        raise field_error("omega", "steady-load method needs (omega_j + omega_b)/2 != 0",
                          0.0, hint="at half-speed whirl only squeeze carries load; use the "
                          "mobility orbit")
    w = np.where(w == 0, 1.0, w)
    share = 0.5 if bearing.grooved else 1.0
    return ocvirk_eccentricity(share * load, bearing.viscosity, 2.0 * w, bearing.radius,
                               bearing.land, bearing.clearance)


def steady_eccentricity_vector(bearing: JournalBearing, wx: float, wy: float, wbar: float):
    """(eps_x, eps_y) of the quasi-static position for the load vector (wx, wy) [N]."""
    load = math.hypot(wx, wy)
    if load == 0.0 or wbar == 0.0:
        return 0.0, 0.0
    e = float(steady_eccentricity(bearing, load, wbar))
    ang = math.atan2(wy, wx) + math.copysign(float(ocvirk_attitude_angle(e)), wbar)
    return e * math.cos(ang), e * math.sin(ang)


def steady_orbit(bearing: JournalBearing, load_x, load_y, angle_grid, omega_journal,
                 omega_bearing=0.0, *, angle_rate=None, period: float = 2.0 * math.pi,
                 film: str = "2pi", terms: str = "shear") -> JournalOrbit:
    """Quasi-static locus over a load diagram (same inputs and outputs as ``bearing_orbit``).

    Power: shear with J from the film (for "pi" the loaded film is the pure-rotation half,
    giving pi/sqrt(1 - eps^2)); "all" adds the pressure term wbar W e sin(attitude)
    (Yang eq. 1.20 with V = 0), here W . (c w) with w = -wbar z x eps.
    """
    film, terms = check_film(film), check_terms(terms)
    th, fx, fy, (wj, wb) = load_diagram(load_x, load_y, angle_grid, period, omega_journal,
                                        omega_bearing)
    angle_rate = diagram_rate(angle_rate, omega_journal)
    wbar = 0.5 * (wj + wb)
    e = np.atleast_1d(steady_eccentricity(bearing, np.hypot(fx, fy), wbar))
    att = np.atleast_1d(ocvirk_attitude_angle(e))
    pos = np.arctan2(fy, fx) + np.copysign(att, wbar)
    ex, ey = e * np.cos(pos), e * np.sin(pos)
    vel = np.column_stack([wbar * ey, -wbar * ex, np.where(wbar >= 0, -0.5, 0.5) * np.pi])
    t = (th - th[0]) / angle_rate
    return assemble_orbit(bearing, th, t, period / angle_rate, fx, fy, ex, ey, vel, wj - wb, film,
                   terms, "steady", 1, 0.0, True)
