"""Choice of the journal-bearing film model, and the finite model's quasi-static locus.

``model``: ``"short"`` (Ocvirk's short bearing, pi film: Ball 1988, Yang 1992), ``"finite"``
(the Reynolds solution over the whole bearing, :mod:`.finite_map` for orbits) or ``"auto"``:
finite unless every land is short, b/d <= 0.05, where the short bearing's film is within 3.5 %
of the finite one for S >= 0.1 (docs/bearings.md, validity table). Each choice comes with the
sentence a plan shows.
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from camtrain.errors import field_error

from .geometry import JournalBearing

__all__ = ["BEARING_MODELS", "SHORT_LIMIT", "choose_model", "orbit_mobility",
           "finite_steady_orbit"]

BEARING_MODELS = ("auto", "short", "finite")
#: Largest land b/d for which "auto" keeps the short bearing.
SHORT_LIMIT = 0.05


def choose_model(bearing: JournalBearing, model: str = "auto", *,
                 sommerfeld: float | None = None) -> tuple[str, str]:
    """(model used, reason) for ``bearing``; ``sommerfeld`` (of a land at the largest load, when
    known before the run) sharpens the short model's warning."""
    if model not in BEARING_MODELS:
        raise field_error("model", "unknown bearing model", model, " or ".join(BEARING_MODELS))
    ld = bearing.land / bearing.diameter
    if model == "short":
        from .validity import short_model_warning

        warning = short_model_warning(ld, SHORT_LIMIT, sommerfeld)
        return "short", (f"short bearing (Ocvirk) as the deck asks; land b/d = {ld:.3g}"
                         + (f"; {warning}" if warning else ""))
    if model == "finite":
        return "finite", f"finite-length Reynolds film as the deck asks; land b/d = {ld:.3g}"
    if ld <= SHORT_LIMIT:
        return "short", (f"auto: land b/d = {ld:.3g} <= {SHORT_LIMIT}, where the short bearing "
                         "is within 3.5 % of the finite film")
    return "finite", (f"auto: land b/d = {ld:.3g} > {SHORT_LIMIT}; the short bearing would "
                      "overstate the film (x1.1-x3 at S 0.1-0.01)")


def orbit_mobility(bearing: JournalBearing, model: str, mobility: str = "exact",
                   cavitation: str = "reynolds", n_theta: int = 72, n_z: int = 6):
    """The ``mobility`` argument of :func:`~.orbit.bearing_orbit` for the model used."""
    if model == "short":
        return mobility
    from .finite_map import bearing_mobility_map

    return bearing_mobility_map(bearing, cavitation, n_theta, n_z)


@lru_cache(maxsize=32)
def _steady_curve(b_over_d: float, cavitation: str, n_theta: int, n_z: int):
    """Dimensionless load F and attitude over eps for steady rotation (no groove)."""
    from .reynolds import FilmGrid, solve_film

    eps = np.array([0.0, 0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.93,
                    0.95, 0.965, 0.975, 0.983, 0.99])
    grid = FilmGrid(b_over_d, n_theta, n_z)
    force, att, start = [0.0], [0.5 * math.pi], None
    for e in eps[1:]:
        f = solve_film(grid, float(e), cavitation=cavitation, start=start)
        start = f.pressure
        force.append(math.hypot(f.force_r, f.force_t))
        att.append(math.atan2(-f.force_t, f.force_r))
    return eps, np.array(force), np.array(att)


def finite_steady_eccentricity(bearing: JournalBearing, load, wbar, *,
                               cavitation: str = "reynolds", n_theta: int = 120,
                               n_z: int = 12) -> np.ndarray:
    """Eccentricity ratio of the finite-length film under a steady load magnitude ``load`` [N]
    at mean speed ``wbar`` [rad/s] (no groove), from the cached steady curve F(eps) of
    :func:`finite_steady_orbit`; loads beyond the curve's last point (eps 0.99) are held there
    (the film below 1 % of the clearance is outside the curve)."""
    eps_t, force_t, _ = _steady_curve(round(bearing.land / bearing.diameter, 12), cavitation,
                                      int(n_theta), int(n_z))
    w = np.abs(np.asarray(wbar, dtype=float))
    target = np.abs(np.asarray(load, dtype=float)) * bearing.clearance ** 2 / (
        12.0 * bearing.viscosity * np.where(w > 0.0, w, 1.0) * bearing.radius ** 4)
    target = np.where(w > 0.0, np.minimum(target, force_t[-1]), force_t[-1])
    lf = np.log(np.maximum(target, 1e-300))
    gap = np.exp(np.interp(lf, np.log(force_t[1:]), np.log(1.0 - eps_t[1:]),
                           left=math.log(1.0 - eps_t[1])))
    return np.where(target < force_t[1], target / force_t[1] * eps_t[1], 1.0 - gap)


def finite_steady_attitude(bearing: JournalBearing, eps, *, cavitation: str = "reynolds",
                           n_theta: int = 120, n_z: int = 12) -> np.ndarray:
    """Attitude angle [rad] of the finite-length film in steady rotation at eccentricity ratio
    ``eps``, interpolated on the cached steady curve of :func:`finite_steady_eccentricity`
    (held at its last point, eps 0.99, beyond it)."""
    eps_t, _, att_t = _steady_curve(round(bearing.land / bearing.diameter, 12), cavitation,
                                    int(n_theta), int(n_z))
    return np.interp(np.asarray(eps, dtype=float), eps_t, att_t)


def finite_steady_orbit(bearing: JournalBearing, load_x, load_y, angle_grid, omega_journal,
                        omega_bearing=0.0, *, angle_rate=None, period: float = 2.0 * math.pi,
                        film: str = "2pi", terms: str = "shear", cavitation: str = "reynolds",
                        n_theta: int = 120, n_z: int = 12):
    """Quasi-static locus with the finite film: at each angle the steady eccentricity for the
    load there (squeeze neglected), like :func:`~.steady.steady_orbit` for the short bearing.

    The steady curve F(eps), attitude(eps) is solved once per b/d at 19 eccentricities up to
    0.99 (cached) and interpolated in (log F, log(1 - eps)); loads beyond eps 0.99 raise.
    """
    from .orbit import assemble_orbit, diagram_rate, load_diagram
    from .power import check_film, check_terms

    film, terms = check_film(film), check_terms(terms)
    th, fx, fy, (wj, wb) = load_diagram(load_x, load_y, angle_grid, period, omega_journal,
                                        omega_bearing)
    rate = diagram_rate(angle_rate, omega_journal)
    wbar = 0.5 * (wj + wb)
    if np.any((wbar == 0.0) & (np.hypot(fx, fy) > 0.0)):
        raise field_error("omega", "steady-load method needs (omega_j + omega_b)/2 != 0", 0.0,
                          hint="at half-speed whirl only squeeze carries load; use the orbit")
    eps_t, force_t, att_t = _steady_curve(round(bearing.land / bearing.diameter, 12),
                                          cavitation, int(n_theta), int(n_z))
    share = 0.5 if bearing.grooved else 1.0
    r, c = bearing.radius, bearing.clearance
    w_abs = np.where(wbar == 0.0, 1.0, np.abs(wbar))
    target = share * np.hypot(fx, fy) * c ** 2 / (12.0 * bearing.viscosity * w_abs * r ** 4)
    if np.any(target > force_t[-1]):
        from camtrain.errors import ConvergenceError

        raise ConvergenceError(
            f"steady finite locus: a load of {float(np.max(np.hypot(fx, fy))):.6g} N needs "
            f"eps > {eps_t[-1]:g}, beyond the finite curve (film below "
            f"{100 * (1 - eps_t[-1]):g} % of the clearance); set the film model to short "
            "(closed form) or check the load and its units")
    lf = np.log(np.maximum(target, 1e-300))
    gap = np.exp(np.interp(lf, np.log(force_t[1:]), np.log(1.0 - eps_t[1:]),
                           left=math.log(1.0 - eps_t[1])))
    e = np.where(target < force_t[1], target / force_t[1] * eps_t[1], 1.0 - gap)
    att = np.interp(e, eps_t, att_t)
    pos = np.arctan2(fy, fx) + np.copysign(att, wbar)
    ex, ey = e * np.cos(pos), e * np.sin(pos)
    vel = np.column_stack([wbar * ey, -wbar * ex, np.where(wbar >= 0, -0.5, 0.5) * np.pi])
    t = (th - th[0]) / rate
    return assemble_orbit(bearing, th, t, period / rate, fx, fy, ex, ey, vel, wj - wb, film, terms,
                   "steady-finite", 1, 0.0, True)
