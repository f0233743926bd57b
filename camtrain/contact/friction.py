"""Friction of one cam/follower pair around the cycle.

Isothermal Newtonian shear of a Barus fluid over the Hertz zone with the sliding speed and the
central film (Ball 1988 eqs. 4.4-4.7, exact integral; Yang 1992 eq. 3.24 for an ellipse), limited
by boundary friction mu_b W (Ball §4.2.3.4; ``tribology.friction_model``: cap, lambda or
lambda_cap), or the mixed model ``greenwood_tripp`` (:func:`greenwood_tripp_friction`). Where the
central film is not available (Blok film) the minimum film is used.
"""
from __future__ import annotations

import numpy as np

from camtrain.contact.film import contact_film
from camtrain.contact.hertz import contact_hertz, modulus
from camtrain.contact.products import FilmField, FrictionField, HertzField
from camtrain.formulas import (
    ball_1988_friction,
    ball_1988_shear_force,
    greenwood_tripp_1970_area,
    greenwood_tripp_1970_load,
    yang_1992_friction,
    yang_1992_shear_force,
)

#: Teodorescu et al. (2005) §2.4: asperity contact is counted only below this film parameter.
GT_LAMBDA_LIMIT = 3.0


def greenwood_tripp_friction(deck, hz: HertzField, h, u_s, W, use) -> np.ndarray:
    r"""Mixed friction: asperity share with boundary shear plus the viscous shear of the film.

    Teodorescu, Kushwaha, Rahnejat & Taraza (2005) eqs. 8-15 with the Greenwood-Tripp asperity
    load and area (eqs. 9, 10) at lambda = h_cen / sigma (zero above lambda = 3, as the paper)::

        F = F_b + F_v,   F_b = tau0 A_a + m W_a                                 (eq. 8)
        F_v = min( F_N (A - A_a)/A ,  tau0 (A - A_a) + gamma (W - W_a) )         (eqs. 11-14)

    F_N is the Newtonian Barus shear over the whole Hertz zone (Ball eq. 4.7 corrected; Yang eq.
    3.24 for an ellipse). Teodorescu's fluid term is the limiting (Eyring) shear alone; camtrain
    takes the lesser of it and the Newtonian shear so that a lightly loaded, slowly sliding
    film is not charged the limiting stress. For lambda -> infinity W_a = A_a = 0 and F is the
    viscous result min(F_N, tau0 A + gamma W). A is the Hertz area (2 b L, or pi a_x a_y).
    Greenwood-Tripp parameters come as zeta beta sigma and sigma/beta (``tribology``).
    """
    lub, trib = deck.lubricant, deck.tribology
    sigma = lub.roughness
    beta = sigma / trib.roughness_slope
    zeta = trib.asperity_density_product / (beta * sigma)
    bx = hz.half_width[use]
    if hz.line:
        area = 2.0 * bx * deck.cam.width
    else:
        area = np.pi * bx * hz.half_length[use]
    lam = np.where(np.isfinite(h), h / sigma, np.inf)
    mixed = lam < GT_LAMBDA_LIMIT
    lam_m = np.where(mixed, lam, GT_LAMBDA_LIMIT)
    E = modulus(deck)
    w_a = np.where(mixed, greenwood_tripp_1970_load(lam_m, area, E, sigma, beta, zeta), 0.0)
    a_a = np.where(mixed, greenwood_tripp_1970_area(lam_m, area, sigma, beta, zeta), 0.0)
    w_a, a_a = np.minimum(w_a, W), np.minimum(a_a, area)   # the statistics over-predict at lambda << 1
    tau0, g = trib.eyring_stress, trib.shear_pressure_coefficient
    f_b = tau0 * a_a + trib.boundary_shear_coefficient * w_a
    f_lim = tau0 * (area - a_a) + g * (W - w_a)
    share = np.where(area > 0.0, (area - a_a) / np.where(area > 0.0, area, 1.0), 0.0)
    cap = np.where(share > 0.0, f_lim / np.where(share > 0.0, share, 1.0), 0.0)
    common = dict(u_s=u_s, h=h, eta0=lub.viscosity, alpha=lub.pressure_viscosity,
                  p_max=hz.pmax[use], cap=cap, viscosity_law=trib.viscosity_law)
    if hz.line:
        f_n = ball_1988_shear_force(b=bx, L=deck.cam.width, **common)
    else:
        f_n = yang_1992_shear_force(a_x=bx, a_y=hz.half_length[use], **common)
    return f_b + np.asarray(f_n, dtype=float) * share


def contact_friction(deck, kin, load) -> FrictionField:
    """Hertz, film and friction force [N] of one pair for a per-angle load (the load iteration,
    the friction effect and the camshaft all use this one function)."""
    load = np.maximum(np.asarray(load, dtype=float), 0.0)
    return friction_field(deck, kin, load, contact_hertz(deck, kin, load),
                          contact_film(deck, kin, load))


def friction_field(deck, kin, load, hz: HertzField, film: FilmField) -> FrictionField:
    """Friction of one pair from its (non-negative) load and the Hertz field and film under it."""
    load = np.asarray(load, dtype=float)
    h = film.for_shear
    lub, trib = deck.lubricant, deck.tribology
    use = (load > 0.0) & np.isfinite(h) & np.isfinite(hz.pmax)
    force = np.zeros_like(load)
    if np.any(use) and trib.friction_model == "greenwood_tripp":
        force[use] = greenwood_tripp_friction(deck, hz, h[use], np.abs(kin.sliding[use]),
                                              load[use], use)
    elif np.any(use):
        common = dict(u_s=np.abs(kin.sliding[use]), h=h[use], eta0=lub.viscosity,
                      alpha=lub.pressure_viscosity, p_max=hz.pmax[use], W=load[use],
                      mu=trib.boundary_friction, model=trib.friction_model,
                      sigma=lub.roughness, viscosity_law=trib.viscosity_law)
        if hz.line:
            force[use] = ball_1988_friction(b=hz.half_width[use], L=deck.cam.width, **common)
        else:
            force[use] = yang_1992_friction(a_x=hz.half_width[use],
                                            a_y=hz.half_length[use], **common)
    return FrictionField(force=force, hertz=hz, film=film, used=use)
