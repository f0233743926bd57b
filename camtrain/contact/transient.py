"""Transient film laws of the cam contact: the film as a function of its own history.

Registered in :mod:`camtrain.contact.model` as the film laws ``squeeze`` and
``averaged_reynolds`` (deck: ``tribology.film_model``; docs/transient_film.md):

* ``squeeze`` (level 1): Teodorescu et al. (2005) eq. 5 with the squeeze term, marched
  implicitly in cam angle (:func:`camtrain.lubrication.squeeze_film_march`). Where the
  entrainment passes through zero the film stays trapped at what the approach left. The film of
  eq. 5 is a central film; camtrain reports it as both the minimum and the central film.
* ``averaged_reynolds`` (level 2): Göçmen (2013) averaged Reynolds contact with squeeze, flow
  factors, Greenwood-Tripp asperities and Reynolds (or half-Sommerfeld) cavitation, the load
  balanced at every angle and marched implicitly over periodic cycles
  (:func:`camtrain.lubrication.transient_film`). The reported film is the larger of it and the
  steady EHL film (Göçmen eq. 2.1, ``tribology.film_floor``); the friction is the viscous plus
  asperity shear of the same solution.

Both use only the per-angle kinematics of the pair and the contact load's array, so they run on
any ContactLoad (rigid train or dynamics). The march runs along ascending cam angle (time), on the
run's grid or on its own uniform grid of ``solver.film_angle_step`` (inputs interpolated
periodically, results interpolated back).
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.contact.film import entrainment, steady_film
from camtrain.contact.hertz import is_line
from camtrain.contact.products import FilmField
from camtrain.errors import field_error

#: numeric code of each regime label in the ``film_regime`` column
REGIME_CODES = {"hydrodynamic": 0.0, "mixed": 1.0, "boundary": 2.0, "separated": 3.0}
TWO_PI = 2.0 * math.pi


def march_grid(theta, step: float | None):
    """The angles the film marches on: the run's grid, or a uniform one of ``step`` [rad]."""
    if step is None:
        return np.asarray(theta, dtype=float)
    n = max(int(round(TWO_PI / step)), 16)
    return theta[0] + TWO_PI * np.arange(n) / n


def periodic(values, theta, grid):
    """``values`` on ``theta`` taken to ``grid`` (linear, periodic over one revolution)."""
    values = np.asarray(values, dtype=float)
    if grid is theta or (grid.shape == theta.shape and np.array_equal(grid, theta)):
        return values
    return np.interp(grid, theta, values, period=TWO_PI)


def nearest(values, theta, grid):
    """Labels on ``theta`` taken to ``grid`` (nearest angle, periodic)."""
    if grid.shape == theta.shape and np.array_equal(grid, theta):
        return np.asarray(values)
    idx = np.interp(grid, theta, np.arange(theta.size), period=TWO_PI)
    return np.asarray(values)[np.rint(idx).astype(int) % theta.size]


def _solver(contact):
    if contact.solver is None:   # a contact built without solver options (no deck)
        from camtrain.contact.film_march import DEFAULTS
        return DEFAULTS
    return contact.solver


def squeeze_film(contact, kin, load=None) -> FilmField:
    """Level 1: Teodorescu's film with the squeeze term, marched in cam angle (see module)."""
    from camtrain.lubrication import squeeze_film_march, teodorescu_steady_film

    steady = steady_film(contact, kin, load)
    if load is None:        # no load: no squeeze formula (W enters it); the Blok film stands
        return steady
    lub, trib, solver = contact.lubricant, contact.tribology, _solver(contact)
    theta = np.asarray(kin.theta, dtype=float)
    grid = march_grid(theta, solver.film_angle_step)
    W = periodic(np.maximum(load, 0.0), theta, grid)
    R = periodic(kin.radius_x, theta, grid)
    u = periodic(entrainment(trib, kin), theta, grid)
    ok = (W > 0.0) & (R > 0.0) & np.isfinite(R)
    F = np.full(grid.shape, np.nan)     # NaN (not a convex loaded contact): the film is held
    F[W <= 0.0] = np.inf                # unloaded: held
    if not np.any(ok):
        return steady
    F[ok] = teodorescu_steady_film(W[ok] / contact.width, R[ok], u[ok], lub.viscosity,
                                   lub.pressure_viscosity, contact.reduced_modulus,
                                   trib.squeeze_load_exponent)
    march = squeeze_film_march(grid, F, u, kin.omega, cycles_max=solver.film_cycles_max,
                               period_tol=solver.film_period_tolerance)
    h = periodic(march.film, grid, theta)
    loaded = np.asarray(load) > 0.0
    h = np.where(loaded & np.isfinite(steady.min), h, np.nan)
    method = f"teodorescu_2005_squeeze ({trib.squeeze_load_exponent} W* exponent)"
    return FilmField(min=h, central=h, method=method, central_method=method,
                     steady=steady.min, solution=march)


def averaged_reynolds_film(contact, kin, load=None) -> FilmField:
    """Level 2: Göçmen's averaged Reynolds contact marched in cam angle (see module)."""
    from camtrain.lubrication import (
        FilmProperties,
        FilmResolution,
        hertz_zone_half_width,
        transient_film,
    )

    steady = steady_film(contact, kin, load)
    if load is None:
        return steady
    if not is_line(kin):
        raise field_error("tribology.film_model", "the averaged Reynolds film is a line-contact "
                          "model", "averaged_reynolds", "a flat or roller follower (line "
                          "contact), or film_model = squeeze or steady")
    lub, trib, solver = contact.lubricant, contact.tribology, _solver(contact)
    theta = np.asarray(kin.theta, dtype=float)
    load = np.maximum(np.asarray(load, dtype=float), 0.0)
    R_run = np.asarray(kin.radius_x, dtype=float)
    convex = (R_run > 0.0) & np.isfinite(R_run)
    bad = (load > 0.0) & ~convex
    if np.any(bad):
        i = int(np.flatnonzero(bad)[0])
        raise field_error("tribology.film_model", "the averaged Reynolds film needs a finite, "
                          f"convex contact radius at every loaded angle; at cam angle "
                          f"{math.degrees(theta[i]):.2f} deg it is {R_run[i]:.4g} m",
                          "averaged_reynolds", "film_model = squeeze or steady for this cam")
    if not np.any(load > 0.0):
        return steady
    # unloaded angles need some positive radius for the zone geometry; it does not enter a balance
    R_run = np.where(convex, R_run, float(np.max(R_run[convex])))
    grid = march_grid(theta, solver.film_angle_step)
    W = periodic(load, theta, grid)
    R = periodic(R_run, theta, grid)
    u_e = periodic(kin.entrainment, theta, grid)      # the mean speed: Reynolds' Couette term
    u_s = periodic(kin.sliding, theta, grid)
    props = FilmProperties(viscosity=lub.viscosity, width=contact.width,
                           modulus=contact.reduced_modulus, roughness=lub.roughness,
                           zeta_beta_sigma=trib.asperity_density_product,
                           sigma_over_beta=trib.roughness_slope, flow_factors=trib.flow_factors,
                           cavitation=trib.cavitation, squeeze_terms=trib.squeeze_terms,
                           eyring_stress=trib.eyring_stress,
                           boundary_shear=trib.boundary_shear_coefficient)
    res = FilmResolution(nodes=solver.film_nodes, march=solver.film_march,
                         tolerance=solver.film_tolerance, cycles_max=solver.film_cycles_max,
                         period_tol=solver.film_period_tolerance)
    half = hertz_zone_half_width(W, contact.width, R, contact.reduced_modulus,
                                 factor=solver.film_zone_width)
    tf = transient_film(grid, kin.omega, R, u_e, W, half, props, res, u_s=u_s, strict=False)
    film = periodic(tf.film, grid, theta)
    loaded = load > 0.0
    own = np.where(loaded, film, np.nan)
    h = own
    if trib.film_floor == "dowson_higginson":
        h = np.where(np.isfinite(steady.min), np.fmax(own, steady.min), own)
    friction = np.where(loaded, periodic(tf.friction, grid, theta), 0.0)
    regime = nearest(tf.regime, grid, theta)
    regime = np.where(loaded, regime, "separated").astype(object)
    floor = " floored by the steady EHL film" if trib.film_floor == "dowson_higginson" else ""
    return FilmField(min=h, central=None,
                     method=f"averaged_reynolds (Göçmen 2013, {trib.cavitation} "
                            f"cavitation){floor}",
                     central_method=None, steady=steady.min, regime=regime, friction=friction,
                     solution=TransientSolution(grid, tf, own, res.tolerance))


class TransientSolution:
    """The level-2 record a film field carries: the march grid [rad], the
    :class:`camtrain.lubrication.TransientFilm` on it, the marched film on the run's grid before
    the floor [m] and the load-balance tolerance it marched to."""

    __slots__ = ("grid", "film", "own", "tolerance")

    def __init__(self, grid, film, own, tolerance):
        self.grid, self.film, self.own, self.tolerance = grid, film, own, tolerance
