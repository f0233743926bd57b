"""Friction laws of one cam/follower pair (registered in :mod:`camtrain.contact.model`).

``cap``, ``lambda``, ``lambda_cap`` (:func:`ball_yang_friction`): isothermal Newtonian shear of a
Barus (or Roelands) fluid over the Hertz zone with the sliding speed and the central film (Ball
1988 eqs. 4.4-4.7, exact integral; Yang 1992 eq. 3.24 for an ellipse), limited by boundary
friction mu_b W (Ball §4.2.3.4). ``greenwood_tripp`` (:func:`greenwood_tripp_law`): the mixed
model of Teodorescu et al. (2005), :func:`camtrain.formulas.teodorescu_2005_friction`. Where the
central film is not available (Blok film) the minimum film is used.
"""
from __future__ import annotations

import numpy as np

from camtrain.contact._points import at
from camtrain.contact.products import HertzField
from camtrain.formulas import (
    ball_1988_friction,
    ball_1988_shear_force,
    teodorescu_2005_friction,
    yang_1992_friction,
    yang_1992_shear_force,
)

#: Teodorescu et al. (2005) §2.4: asperity contact is counted only below this film parameter.
GT_LAMBDA_LIMIT = 3.0


def ball_yang_friction(contact, kin, load, hz: HertzField, h, use) -> np.ndarray:
    """Ball's viscous shear with the boundary limit (``tribology.friction_model``: cap, lambda,
    lambda_cap) on the angles ``use``: line contact Ball eqs. 4.4-4.7, ellipse Yang eq. 3.24."""
    lub, trib = contact.lubricant, contact.tribology
    common = dict(u_s=np.abs(kin.sliding[use]), h=h[use], eta0=at(lub.viscosity, use),
                  alpha=at(lub.pressure_viscosity, use), p_max=hz.pmax[use], W=load[use],
                  mu=at(trib.boundary_friction, use), model=trib.friction_model,
                  sigma=at(lub.roughness, use), viscosity_law=trib.viscosity_law)
    if hz.line:
        return ball_1988_friction(b=hz.half_width[use], L=at(contact.width, use), **common)
    return yang_1992_friction(a_x=hz.half_width[use], a_y=hz.half_length[use], **common)


def greenwood_tripp_law(contact, kin, load, hz: HertzField, h, use) -> np.ndarray:
    r"""Mixed friction on the angles ``use``: Teodorescu et al. (2005) eqs. 8-15 with the
    Greenwood-Tripp asperity load and area at lambda = h / sigma
    (:func:`camtrain.formulas.teodorescu_2005_friction`), with one option of camtrain's::

        F = F_b + min( F_N (A - A_a)/A ,  tau0 (A - A_a) + gamma (W - W_a) )

    F_N is the Newtonian Barus shear over the whole Hertz zone (Ball eq. 4.7; Yang eq. 3.24 for an
    ellipse). Teodorescu's fluid term is the limiting (Eyring) shear alone; camtrain takes the
    lesser of it and the Newtonian shear so that a lightly loaded, slowly sliding film is not
    charged the limiting stress. For lambda -> infinity W_a = A_a = 0 and F is the viscous result
    min(F_N, tau0 A + gamma W). A is the Hertz area (2 b L, or pi a_x a_y). Greenwood-Tripp
    parameters come from the deck as zeta beta sigma and sigma/beta (``tribology``).
    """
    lub, trib = contact.lubricant, contact.tribology
    sigma = lub.roughness
    beta = sigma / trib.roughness_slope
    zeta = trib.asperity_density_product / (beta * sigma)
    bx = hz.half_width[use]
    area = 2.0 * bx * contact.width if hz.line else np.pi * bx * hz.half_length[use]
    h = h[use]
    W = load[use]
    t = teodorescu_2005_friction(W, area, h / sigma, trib.eyring_stress,
                                 trib.shear_pressure_coefficient, trib.boundary_shear_coefficient,
                                 contact.reduced_modulus, sigma, beta, zeta,
                                 lambda_limit=GT_LAMBDA_LIMIT)
    a_a = np.asarray(t.asperity_area, dtype=float)
    share = np.where(area > 0.0, (area - a_a) / np.where(area > 0.0, area, 1.0), 0.0)
    cap = np.where(share > 0.0, t.viscous / np.where(share > 0.0, share, 1.0), 0.0)
    common = dict(u_s=np.abs(kin.sliding[use]), h=h, eta0=lub.viscosity,
                  alpha=lub.pressure_viscosity, p_max=hz.pmax[use], cap=cap,
                  viscosity_law=trib.viscosity_law)
    if hz.line:
        f_n = ball_1988_shear_force(b=bx, L=contact.width, **common)
    else:
        f_n = yang_1992_shear_force(a_x=bx, a_y=hz.half_length[use], **common)
    return np.asarray(t.boundary, dtype=float) + np.asarray(f_n, dtype=float) * share


def film_solution_friction(contact, kin, load, hz: HertzField, h, use) -> np.ndarray:
    """The ``averaged_reynolds`` friction: viscous plus asperity shear of the film solution. The
    contact model takes it from the film field; reached here only without that film."""
    raise ValueError("the averaged_reynolds friction comes from the averaged_reynolds film "
                     "(tribology.film_model = averaged_reynolds)")
