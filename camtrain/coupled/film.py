"""The level-1 squeeze film of every cam contact inside the monolithic march
(:mod:`camtrain.coupled.march`): what the compiled revolution needs to carry each
contact's film from step to step and to take its friction from the current load and film.

Teodorescu et al. (2005) eq. 5 gives the film h = F exp(-96.775 w_s), w_s = (dh/dt)/u (eq. 6),
with F the Rahnejat steady film; written as the relaxation law dh/dt = -(|u|/96.775) ln(h/F)
(docs/transient_film.md) it is one scalar state per contact, marched by implicit Euler once per
accepted time step (:func:`._film_kernel.film_step`). The steady film depends on the load
only through W^e (e = -0.059, or +0.059 as printed: ``tribology.squeeze_load_exponent``), so
F = F_1(theta) W^e with F_1 the film under 1 N, tabulated once per grid angle.

The friction law (Ball's capped shear, Teodorescu's Greenwood-Tripp law, ...) depends on the
angle's kinematics, the load and the film. It is tabulated once per grid angle over the load
levels of the steady path (:data:`camtrain.coupled.tables.FRICTION_LEVELS`, cam-level here)
and over film ratios h/F (:data:`FILM_RATIOS`): h = F (no squeeze) is a level, so the
quasi-steady limit reads the steady law's own table. Films thicker than 64 F (at a reversal the
trapped film stays while F falls to 0) read the 64 F column: there the viscous shear is small
either way and the per-revolution correction puts the exact value in at the grid angles.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["FILM_RATIOS", "SqueezeFilmModel", "squeeze_film_model"]

#: film ratios h / F of the friction table (ratio sqrt 2: 1/8 to 64, 1 among them)
FILM_RATIOS = 2.0 ** np.arange(-3.0, 6.25, 0.5)


@dataclass(frozen=True)
class SqueezeFilmModel:
    """The level-1 film of one pair for the march, every array on the run's grid in the lobe's
    own angle frame: ``unit_film`` F_1 [m] (the steady film under 1 N cam-level load; NaN where
    the contact has no film: not convex), ``exponent`` e (F = F_1 W^e), ``speed`` |u| [m/s],
    ``table`` (film ratios, load levels, grid) the friction coefficient, ``levels`` the
    cam-level load levels [N], ``squeeze`` (False: h = F at every step, the quasi-steady
    limit), ``friction(loads, films)`` the contact model's coefficient under cam-level loads
    with given films (n_lobes, grid; own frame), ``radius`` the contact radius R [m] and
    ``unit_of(R, u)`` F_1 at any radius and speed (the march evaluates F_1 at every step from
    R and u interpolated there, as the single train's film march does: F_1 ~ |u|^0.541 is far
    from linear near a reversal)."""

    unit_film: np.ndarray
    exponent: float
    speed: np.ndarray
    table: np.ndarray
    levels: np.ndarray
    friction: object
    radius: np.ndarray
    unit_of: object
    squeeze: bool = True

    def steady(self, loads):
        """Steady film F [m] under cam-level ``loads`` (own frame, any leading shape)."""
        w = np.asarray(loads, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(w > 0.0, self.unit_film * np.where(w > 0.0, w, 1.0) ** self.exponent,
                            np.inf)

    def tabled(self, loads, films, cols):
        """The table's coefficient at cam-level ``loads``, ``films`` [m] and integer grid
        ``cols`` (same shapes), read as the kernel reads it at a grid angle."""
        levels, ratios = self.levels, FILM_RATIOS
        w = np.maximum(np.asarray(loads, dtype=float), levels[0])
        x = np.clip(np.log(w / levels[0]) / np.log(levels[1] / levels[0]), 0.0, levels.size - 1.0)
        iw = np.minimum(x.astype(int), levels.size - 2)
        tw = x - iw
        F = self.steady(loads)
        with np.errstate(divide="ignore", invalid="ignore"):
            ln_r = np.where(np.isfinite(F) & (F > 0.0), np.log(films / F), 0.0)
        ln_r = np.nan_to_num(ln_r, nan=0.0)
        y = np.clip((ln_r - np.log(ratios[0])) / np.log(ratios[1] / ratios[0]), 0.0,
                    ratios.size - 1.0)
        ir = np.minimum(y.astype(int), ratios.size - 2)
        tr = y - ir
        t = self.table
        return ((1.0 - tr) * ((1.0 - tw) * t[ir, iw, cols] + tw * t[ir, iw + 1, cols])
                + tr * ((1.0 - tw) * t[ir + 1, iw, cols] + tw * t[ir + 1, iw + 1, cols]))


def squeeze_film_model(contact, kin, levels, squeeze: bool = True) -> SqueezeFilmModel:
    """The level-1 film model of ``contact`` (a :class:`camtrain.contact.model.CamContact` with
    ``film_law = "squeeze"``) on the kinematics ``kin``, its friction tabulated over the
    cam-level load ``levels`` [N] and :data:`FILM_RATIOS` (49 x 19 evaluations of the friction
    law on the grid)."""
    from camtrain.contact.film import entrainment
    from camtrain.contact.products import FilmField
    from camtrain.lubrication import teodorescu_steady_film
    from camtrain.lubrication.squeeze import load_exponent

    lub, trib = contact.lubricant, contact.tribology
    R = np.asarray(kin.radius_x, dtype=float)
    u = np.asarray(entrainment(trib, kin), dtype=float)

    def unit_of(radius, speed):
        """Steady film under 1 N [m] (NaN where the contact is not convex)."""
        radius = np.asarray(radius, dtype=float)
        out = np.full(radius.shape, np.nan)
        convex = (radius > 0.0) & np.isfinite(radius)
        if np.any(convex):
            out[convex] = teodorescu_steady_film(1.0 / contact.width, radius[convex],
                                                 np.asarray(speed, dtype=float)[convex],
                                                 lub.viscosity, lub.pressure_viscosity,
                                                 contact.reduced_modulus,
                                                 trib.squeeze_load_exponent)
        return out

    unit = unit_of(R, u)
    exponent = load_exponent(trib.squeeze_load_exponent)
    method = f"teodorescu_2005_squeeze ({trib.squeeze_load_exponent} W* exponent)"

    def friction(loads, films):
        """Coefficient of the contact model under cam-level loads with the given films."""
        out = np.zeros(np.shape(loads))
        for j, (w, h) in enumerate(zip(np.atleast_2d(loads), np.atleast_2d(films),
                                       strict=True)):
            w = np.maximum(np.asarray(w, dtype=float), 0.0)
            h = np.where(w > 0.0, h, np.nan)
            film = FilmField(min=h, central=h, method=method, central_method=method)
            force = contact.friction(kin, w, contact.hertz(kin, w), film).force
            out.reshape(-1, w.size)[j] = np.divide(force, w, out=np.zeros_like(w), where=w > 0)
        return out

    levels = np.asarray(levels, dtype=float)
    table = np.zeros((FILM_RATIOS.size, levels.size, R.size))
    for i, level in enumerate(levels):
        w = np.full(R.shape, level)
        hertz = contact.hertz(kin, w)
        steady = unit * level ** exponent
        for k, ratio in enumerate(FILM_RATIOS):
            h = ratio * steady
            film = FilmField(min=h, central=h, method=method, central_method=method)
            table[k, i] = contact.friction(kin, w, hertz, film).force / level
    return SqueezeFilmModel(unit, exponent, u, table, levels, friction, R, unit_of, squeeze)


# the march's film state (camtrain.coupled.march.march_coupled)
def film_state(film, theta_grid, local, n_lobes: int, grid: int) -> dict:
    """The kernel's film arguments: the steady film under 1 N, the entrainment speed and the
    fractional grid column of every step in each lobe's own frame, the table and its film
    ratios, the film state h (placeholders without a film)."""
    if film is None:
        z = np.zeros((n_lobes, 1))
        return dict(h=np.ones(n_lobes), unit=z, exponent=0.0, speed=z, table=np.zeros((2, 2, 1)),
                    col=z, ln_r0=0.0, d_ln_r=1.0, ratios=FILM_RATIOS)
    two_pi = 2.0 * math.pi
    step = two_pi / grid
    speed = np.array([np.interp(row, theta_grid, film.speed, period=two_pi) for row in local])
    radius = np.array([np.interp(row, theta_grid, film.radius, period=two_pi) for row in local])
    return dict(
        h=np.ones(n_lobes),
        unit=film.unit_of(radius, speed),
        exponent=float(film.exponent),
        speed=speed,
        table=np.ascontiguousarray(film.table),
        col=np.mod((local - theta_grid[0]) / step, grid),
        ln_r0=math.log(FILM_RATIOS[0]), d_ln_r=math.log(FILM_RATIOS[1] / FILM_RATIOS[0]),
        ratios=FILM_RATIOS)


def _shift(values, theta_grid, by):
    """Periodic curves ``values`` (n_lobes, grid) read at theta + by_j (row j)."""
    return np.array([np.interp(theta_grid + b, theta_grid, row, period=2.0 * math.pi)
                     for row, b in zip(values, by, strict=True)])


def start_film(film, start, theta_grid, phases, ratio, omega):
    """Every contact's film at the march's first angle: the periodic level-1 film of the
    single train's load (on the grid), at its lobe's angle."""
    from camtrain.dynamics.train import CAM
    from camtrain.lubrication import squeeze_film_march

    w = np.interp(theta_grid, start.theta, np.maximum(start.contact_force[CAM], 0.0),
                  period=2.0 * math.pi) * np.asarray(ratio, dtype=float)
    F = film.steady(w)
    h = squeeze_film_march(theta_grid, F, film.speed, omega, squeeze=film.squeeze).film
    good = np.isfinite(h) & (h > 0.0)
    h = np.where(good, h, np.max(h[good]) if np.any(good) else 1e-6)
    at = theta_grid[0] - np.asarray(phases, dtype=float)
    return np.interp(at, theta_grid, h, period=2.0 * math.pi)


def film_table_error(film, loads, films, ratio, theta_grid, phases):
    """The film table's error at one revolution's loads and films (shaft frame, n_lobes x
    grid): the contact model's coefficient with the marched film minus the table's."""
    phases = np.asarray(phases, dtype=float)
    own_w = _shift(loads, theta_grid, phases) * np.asarray(ratio, dtype=float)
    own_h = _shift(films, theta_grid, phases)
    exact = film.friction(own_w, own_h)
    cols = np.broadcast_to(np.arange(theta_grid.size), own_w.shape)
    error = np.where(own_w >= film.levels[0], exact - film.tabled(own_w, own_h, cols), 0.0)
    return _shift(error, theta_grid, -phases)
