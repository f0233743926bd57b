"""The elastic film law of the cam contact (``tribology.film_model = "ehl"``).

The transient elastohydrodynamic line contact of :mod:`camtrain.lubrication.ehl_transient`
marched through the cam cycle: the Reynolds equation with the squeeze term, the cam's changing
radius, load and signed entrainment, the elastic deflection of both surfaces, piezoviscous and
compressible oil, mass-conserving (Elrod-Adams) cavitation, Greenwood-Tripp asperities and
Eyring friction (docs/ehl.md). Like ``averaged_reynolds`` it solves the contact: its friction
comes from the same solution, and its FilmField carries the steady formula film, the regime
per angle and the whole record (:class:`EHLFilmSolution`, with the film map).
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.contact.film import steady_film
from camtrain.contact.hertz import is_line
from camtrain.contact.products import FilmField
from camtrain.contact.transient import march_grid, nearest, periodic
from camtrain.errors import field_error

#: asperity share of the load bounding the regimes (as the averaged Reynolds film)
HYDRODYNAMIC_SHARE, BOUNDARY_SHARE = 0.01, 0.90


#: the closed-form films written beside the elastic film (docs/ehl.md "Outputs"), by the name
#: of their function in :mod:`camtrain.formulas.film_line`: Dowson & Higginson (1977) and Pan &
#: Hamrock (1989) minimum films, Pan & Hamrock (1989), Moes (1992, mean-speed groups) and
#: Dowson & Toyoda (1979) central films
FORMULA_FILMS = ("dowson_higginson_1977", "pan_hamrock_1989_min", "pan_hamrock_1989_cen",
                 "moes_1992", "dowson_toyoda_1979")


class EHLFilmSolution:
    """The record an ``ehl`` film field carries: the march grid [rad], the
    :class:`camtrain.lubrication.ehl_transient.EHLCycle` on it, the knobs it ran with, and the
    closed-form films of :data:`FORMULA_FILMS` on the run's angles (:func:`formula_films`)."""

    __slots__ = ("grid", "cycle", "resolution", "formulas")

    def __init__(self, grid, cycle, resolution, formulas=None):
        self.grid, self.cycle, self.resolution = grid, cycle, resolution
        self.formulas = formulas if formulas is not None else {}


def formula_films(contact, kin, load, R) -> dict[str, np.ndarray]:
    """The films of :data:`FORMULA_FILMS` [m] per run angle, from the inputs the march takes:
    load per unit width, the contact radius ``R``, the mean entrainment |u| = |u1 + u2|/2 (the
    march's own, whatever ``tribology.entrainment`` says for the deck's formula film), the oil's
    eta0 and alpha and the reduced modulus. NaN where the pair carries no load; 0 where the
    entrainment is zero (each formula's h ~ |u|^0.7 or Moes' sqrt(2U) factor: no film without
    entrainment, the steady value the squeeze film is compared with)."""
    from camtrain.formulas import film_line

    loaded = load > 0.0
    lub = contact.lubricant
    args = (load[loaded] / contact.width, R[loaded], np.abs(kin.entrainment)[loaded],
            lub.viscosity, lub.pressure_viscosity, contact.reduced_modulus)
    films = {}
    for name in FORMULA_FILMS:
        h = np.full(load.shape, np.nan)
        h[loaded] = getattr(film_line, name)(*args)
        films[name] = h
    return films


def _knob(contact, name):
    """A knob of the deck's [solver], or its default for a contact built without a deck."""
    from camtrain.contact.film_march import DEFAULTS

    return getattr(contact.solver if contact.solver is not None else DEFAULTS, name)


def ehl_resolution(contact):
    from camtrain.lubrication.ehl_transient import CycleResolution

    trib = contact.tribology
    return CycleResolution(nodes=int(_knob(contact, "ehl_nodes")),
                           inlet=float(_knob(contact, "ehl_inlet")),
                           tolerance=float(_knob(contact, "ehl_tolerance")),
                           march=str(_knob(contact, "ehl_march")),
                           linear_solver=str(_knob(contact, "ehl_linear_solver")),
                           cavitation=getattr(trib, "ehl_cavitation", "elrod_adams"))


def _check_geometry(kin, load, theta):
    if not is_line(kin):
        raise field_error("tribology.film_model", "the elastic film is a line-contact model",
                          "ehl", "a flat or roller follower (line contact), or film_model = "
                          "squeeze or steady")
    R = np.asarray(kin.radius_x, dtype=float)
    bad = (load > 0.0) & ~((R > 0.0) & np.isfinite(R))
    if np.any(bad):
        i = int(np.flatnonzero(bad)[0])
        raise field_error("tribology.film_model", "the elastic film needs a finite, convex "
                          f"contact radius at every loaded angle; at cam angle "
                          f"{math.degrees(theta[i]):.2f} deg it is {R[i]:.4g} m", "ehl",
                          "film_model = squeeze or steady for this cam")


def ehl_film(contact, kin, load=None) -> FilmField:
    """The transient elastic film of one pair over the cycle (module docstring)."""
    from camtrain.lubrication.ehl_line import NotConverged
    from camtrain.lubrication.ehl_oil import Oil
    from camtrain.lubrication.ehl_transient import CycleContact, march_ehl_cycle

    steady = steady_film(contact, kin, load)
    if load is None:
        return steady
    theta = np.asarray(kin.theta, dtype=float)
    load = np.maximum(np.asarray(load, dtype=float), 0.0)
    _check_geometry(kin, load, theta)
    if not np.any(load > 0.0):
        return steady
    lub, trib = contact.lubricant, contact.tribology
    R_run = np.asarray(kin.radius_x, dtype=float)
    R_run = np.where((R_run > 0.0) & np.isfinite(R_run), R_run, 1.0)
    grid = march_grid(theta, _knob(contact, "ehl_angle_step"))
    res = ehl_resolution(contact)
    oil = Oil(lub.viscosity, lub.pressure_viscosity,
              getattr(trib, "ehl_viscosity", "roelands"),
              getattr(trib, "ehl_density", "dowson_higginson"))
    cycle_contact = CycleContact(
        t=(grid - grid[0]) / kin.omega, w=periodic(load, theta, grid) / contact.width,
        R=periodic(R_run, theta, grid), u=periodic(kin.entrainment, theta, grid),
        u_s=periodic(kin.sliding, theta, grid), E_r=contact.reduced_modulus,
        width=contact.width, oil=oil, sigma=lub.roughness,
        zeta_beta_sigma=trib.asperity_density_product, sigma_over_beta=trib.roughness_slope,
        eyring_stress=trib.eyring_stress, boundary_shear=trib.boundary_shear_coefficient)
    try:
        cycle = march_ehl_cycle(cycle_contact, res)
    except NotConverged as exc:
        raise field_error("solver.ehl_angle_step", f"the elastic film did not converge ({exc})",
                          math.degrees(_knob(contact, "ehl_angle_step")),
                          "a smaller solver.ehl_angle_step or other solver.ehl_nodes",
                          "or tribology.film_model = averaged_reynolds") from None
    loaded = load > 0.0

    def on_run(v):
        return np.where(loaded, periodic(v, grid, theta), np.nan)

    h_min, h_c = on_run(cycle.h_min), on_run(cycle.h_central)
    friction = np.where(loaded, periodic(cycle.friction, grid, theta), 0.0)
    labels = regime_labels(cycle.asperity_share, cycle_contact.w > 0.0)
    regime = np.where(loaded, nearest(labels, grid, theta), "separated").astype(object)
    method = (f"elastic (transient EHL line contact, {res.cavitation} cavitation, "
              f"{res.nodes} points, {res.march})")
    return FilmField(min=h_min, central=h_c, method=method, central_method=method,
                     steady=steady.min, regime=regime, friction=friction,
                     solution=EHLFilmSolution(grid, cycle, res,
                                              formula_films(contact, kin, load, R_run)))


def regime_labels(share, loaded) -> np.ndarray:
    """hydrodynamic (asperity share <= 1 %), mixed, boundary (>= 90 %), separated."""
    share = np.nan_to_num(np.asarray(share, dtype=float))
    lab = np.where(share <= HYDRODYNAMIC_SHARE, "hydrodynamic",
                   np.where(share >= BOUNDARY_SHARE, "boundary", "mixed"))
    return np.where(loaded, lab, "separated").astype(object)
