"""Traction and rolling resistance of the cam-roller line contact at a given roller speed.

The contact (:class:`camtrain.contact.model.CamContact`: materials, cam width, lubricant,
tribology options, steady film law) is evaluated on the **roller's kinematics**: the chain's
:class:`~camtrain.mechanisms.base.Kinematics` with the follower surface speed V_f replaced by
the roller's V_roll = V_f + w_r r_r (:mod:`.speeds`), so the film sees the roller's entrainment
and the shear its sliding. The Hertz field does not depend on the speeds and is the chain's.

Traction laws (``law``, the deck's ``roller.traction``):

* ``limiting_shear`` (default): Newtonian Barus shear over the Hertz zone (Ball 1988 eq. 4.7,
  :func:`camtrain.formulas.ball_1988_shear_force`) on the fluid share of the area, limited by the
  limiting shear stress tau_L = tau_0 + gamma p (Teodorescu et al. 2005 eq. 12, as
  tau_0 (A - A_a) + gamma (W - W_a)), plus the asperity (boundary) friction of the
  Greenwood-Tripp mixed film tau_0 A_a + m W_a (Teodorescu eqs. 8-15,
  :func:`camtrain.formulas.teodorescu_2005_friction`); the sum capped at mu_b W.
* ``eyring``: as above with the zone-mean Newtonian stress passed through the Eyring law
  tau_0 asinh(tau_N / tau_0) (Johnson & Tevaarwerk 1977), still below the limiting shear.
* ``contact``: the deck's own friction law (``tribology.friction_model``) on the roller's
  kinematics: with a locked roller this is exactly the non-rotating follower's friction.

Every law is odd in the sliding speed: the traction on the roller has the sign of u_s (it drives
the roller towards rolling), and the asperity part is Coulomb-like (0 at u_s = 0 exactly).

Rolling resistance (``rolling``): the hydrodynamic rolling force of an EHL line contact,
Goksem & Hargreaves (1978, ASME J. Lubr. Technol. 100:346), in the form used for cam-roller slip
by Chiu (1992) and Alakhramsing et al. (2018):

    F_R = 4.318 (G U)^0.658 W^0.0126 R L / alpha,  G = alpha E', U = eta_0 |u_e| / (E' R),
    W = w / (E' R L)

(constant and exponents as those papers quote them; not checked against the 1978 original
here). camtrain charges the rolling loss F_R |u_e| to the cam's drive and keeps it out of the
roller's torque balance (a named choice: the pressure-centre shift it stands for acts on both
bodies, and its moment on the roller is small beside the pin's); ``none`` leaves it out.

A **crowned roller** (``mechanism.roller.crown_radius``: the Kinematics carry R_y = the crown
radius) makes an elliptical contact, and every part above takes its point-contact form: the
Hertz ellipse (semi-axes a_x along the rolling direction, a_y across; exact Hertz, Hamrock &
Dowson 1981 ch. 3), the Hamrock & Dowson (1977) point-contact film, the Newtonian Barus shear
over the ellipse (Yang 1992 eq. 3.24) and the area pi a_x a_y in the limiting shear and the
asperity terms. The rolling resistance of the ellipse is the line formula above on its slices
across the rolling direction (strip theory, side leakage neglected, as roller-profile analyses
slice a crowned roller: Harris & Kotzalas, *Rolling Bearing Analysis*, 2006): each slice at
y carries the Hertz load per unit length w(y) = (3 W / 4 a_y)(1 - y^2/a_y^2), so

    F_R = 4.318 (G U)^0.658 (w_0 / (E' R))^0.0126 R a_y I / alpha,
    w_0 = 3 W / (4 a_y),  I = int_{-1}^{1} (1 - s^2)^0.0126 ds = B(1/2, 1.0126),

which is (3/2)^0.0126 B(1/2, 1.0126)/2 = 0.9974 of the line formula over the ellipse's
length 2 a_y at any crown (the load exponent 0.0126 makes F_R nearly indifferent to how the
load is spread).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from camtrain.contact._points import at
from camtrain.contact.products import FilmField, HertzField

TRACTION_LAWS = ("limiting_shear", "eyring", "contact")
ROLLING_LAWS = ("goksem_hargreaves", "none")
#: Teodorescu et al. (2005) §2.4: asperity contact counted only below this film parameter
LAMBDA_LIMIT = 3.0


@dataclass(frozen=True)
class Traction:
    """The cam-roller contact of one pair on the cycle grid: the contact model, the chain's
    kinematics (non-rotating follower), load [N] and Hertz field, the traction law and the
    rolling-resistance law."""

    contact: object            # camtrain.contact.model.CamContact
    kin: object                # camtrain.mechanisms.base.Kinematics (non-rotating follower)
    load: np.ndarray
    hertz: HertzField
    law: str = "limiting_shear"
    rolling: str = "goksem_hargreaves"
    #: the Greenwood-Tripp integrals of the mixed film from their table
    #: (:func:`camtrain.formulas.mixed.greenwood_tripp_tabulated`, within 2e-13 of the exact
    #: ones): the marched roller's tables evaluate the traction at some 10^5-10^6 points
    tabulated: bool = False

    def __post_init__(self):
        if self.law not in TRACTION_LAWS:
            raise ValueError(f"traction law {self.law!r}: expected one of {TRACTION_LAWS}")
        if self.rolling not in ROLLING_LAWS:
            raise ValueError(f"rolling law {self.rolling!r}: expected one of {ROLLING_LAWS}")

    @cached_property
    def unit_shear(self) -> np.ndarray:
        """Newtonian Barus shear over the Hertz zone per unit shear rate u_s/h [N s/m * m] at
        every loaded angle (Ball 1988 eq. 4.7 is linear in u_s/h; the zone integral is the
        costly part and does not change with the roller's speed): F_N = this x |u_s| / h."""
        from camtrain.formulas import ball_1988_shear_force, yang_1992_shear_force

        c, lub, hz = self.contact, self.contact.lubricant, self.hertz
        use = (self.load > 0.0) & np.isfinite(hz.pmax)
        out = np.zeros(self.load.shape)
        if np.count_nonzero(use):
            common = dict(eta0=at(lub.viscosity, use), alpha=at(lub.pressure_viscosity, use),
                          p_max=hz.pmax[use], viscosity_law=c.tribology.viscosity_law)
            if hz.line:
                out[use] = ball_1988_shear_force(1.0, 1.0, b=hz.half_width[use],
                                                 L=at(c.width, use), **common)
            else:   # a crowned roller's ellipse (Yang 1992 eq. 3.24)
                out[use] = yang_1992_shear_force(1.0, 1.0, a_x=hz.half_width[use],
                                                 a_y=hz.half_length[use], **common)
        return out

    @cached_property
    def area(self) -> np.ndarray:
        """Hertz area at every angle [m^2]: 2 b L of the line contact, pi a_x a_y of a crowned
        roller's ellipse (0 unloaded)."""
        hz = self.hertz
        if hz.line:
            every = np.ones(self.load.shape, dtype=bool)
            return 2.0 * hz.half_width * np.broadcast_to(at(self.contact.width, every),
                                                          self.load.shape)
        return np.pi * hz.half_width * hz.half_length

    def rolling_slope(self, at_angles) -> np.ndarray:
        """dF_N/du_s at zero sliding [N s/m] at the angles ``at_angles``: the Newtonian shear's
        slope with the film of pure rolling (a first guess of the slip for the solvers)."""
        idx = np.asarray(at_angles)
        view = _RollerView(self.kin, idx, np.zeros(idx.size))
        h = self.shear_film(view, idx, self.load[idx])
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(h > 0.0, self.unit_shear[idx] / h, np.inf)

    @cached_property
    def _rolling(self) -> tuple[FilmField, float | None, float | None]:
        """The film at pure rolling (entrainment V_c) at every angle, and the speed exponents
        a_u of its minimum- and central-film formulas where the film law is the steady one and
        the formula a power law h/R = C U^a_u G^a_g W^a_w (None otherwise)."""
        from camtrain.formulas.film import FILM_METHODS

        every = np.arange(self.load.size)
        film = self.contact.film(_RollerView(self.kin, every, np.zeros(every.size)), self.load)
        steady = self.contact.film_law == "steady"

        def exponent(method):
            if not (steady and method):
                return None
            func = FILM_METHODS.get_method(method).func
            law = getattr(func, "power_law", None)
            return law[1] if law is not None else getattr(func, "speed_exponent", None)

        return film, exponent(film.method), exponent(film.central_method)

    @property
    def _rolling_film(self) -> tuple[np.ndarray, float | None]:
        """The shear film at pure rolling at every angle and its speed exponent a_u (None
        where the film is not a steady power law)."""
        film, a_min, a_central = self._rolling
        return film.for_shear, (a_central if film.central is not None else a_min)

    def film(self, sliding) -> FilmField:
        """The cam-roller film at sliding speeds u_s at every angle (the roller's entrainment
        u_e = V_c - u_s/2). Power-law steady films are the rolling film scaled by
        (|u_e| / |V_c|)^a_u, exact as :meth:`shear_film` (one film evaluation per run); other
        film laws, and the angles where V_c = 0, are evaluated in full."""
        rolling, a_min, a_central = self._rolling
        if a_min is None or (rolling.central is not None and a_central is None):
            return self.contact.film(self.kinematics(sliding), self.load)
        u_s = np.asarray(sliding, dtype=float)
        u_roll = np.abs(self.kin.v_cam)
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.abs(self.kin.v_cam - 0.5 * u_s) / u_roll
            h_min = rolling.min * ratio ** a_min
            h_cen = None if rolling.central is None else rolling.central * ratio ** a_central
        still = np.flatnonzero(u_roll == 0.0)
        if still.size:
            part = _RollerView(self.kin, still, u_s[still])
            full = self.contact.film(part, self.load[still])
            h_min[still] = full.min
            if h_cen is not None:
                h_cen[still] = full.central
        return replace(rolling, min=h_min, central=h_cen)

    def shear_film(self, view, idx, load) -> np.ndarray:
        """The film the shear reads [m] at the roller's speeds of ``view`` (angles ``idx``).

        A power-law steady film depends on the speed only through U = eta_0 |u_e| / (E' R), so
        h(u_e) = h(V_c) (|u_e| / |V_c|)^a_u exactly: one film evaluation per run instead of one
        per step of the speed solver. Other film laws, and angles where V_c = 0, are evaluated
        in full."""
        h_roll, exponent = self._rolling_film
        if exponent is None:
            return self.contact.film(view, load).for_shear
        u_roll = np.abs(view.v_cam)
        moving = u_roll > 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            h = h_roll[idx] * (np.abs(view.entrainment) / u_roll) ** exponent
        if not np.all(moving):
            k = np.flatnonzero(~moving)
            part = _RollerView(self.kin, np.asarray(idx)[k], view.sliding[k])
            h[k] = self.contact.film(part, load[k]).for_shear
        return h

    @property
    def v_s0(self) -> np.ndarray:
        """Sliding speed of the non-rotating follower V_c - V_f [m/s]."""
        return self.kin.sliding

    def kinematics(self, sliding) -> object:
        """The roller's kinematics at sliding speed u_s: V_f replaced by V_roll = V_c - u_s."""
        return replace(self.kin, v_follower=self.kin.v_cam - np.asarray(sliding, dtype=float))

    def force(self, sliding, at_angles=None) -> np.ndarray:
        """Traction on the roller [N] at sliding speeds u_s, signed as u_s: at every angle, or
        at the angles ``at_angles`` (an index array; ``sliding`` then has one value each)."""
        u_s = np.asarray(sliding, dtype=float)
        idx = np.arange(u_s.size) if at_angles is None else np.asarray(at_angles)
        view = _RollerView(self.kin, idx, u_s)
        load = self.load[idx]
        hz = _hertz_at(self.hertz, idx)
        h = self.shear_film(view, idx, load)
        use = (load > 0.0) & np.isfinite(h) & np.isfinite(hz.pmax)
        out = np.zeros(u_s.shape)
        if np.count_nonzero(use):
            if self.law == "contact":
                from camtrain.contact.model import FRICTION_LAWS

                mag = FRICTION_LAWS[self.contact.friction_law](self.contact, view, load, hz, h,
                                                               use)
            else:
                rate = np.abs(u_s[use])
                hu = h[use]
                with np.errstate(divide="ignore", invalid="ignore"):
                    rate = np.where(hu > 0.0, rate / hu, np.where(rate > 0.0, np.inf, 0.0))
                newton = self.unit_shear[idx][use] * rate
                mag = mixed_traction(self.contact, self.area[idx][use], load, h, newton, use,
                                     self.law, self.tabulated)
            out[use] = np.sign(u_s[use]) * mag
        return out

    def rolling_force(self, sliding) -> np.ndarray:
        """Hydrodynamic rolling resistance F_R >= 0 [N] at sliding speeds u_s (0 unloaded)."""
        out = np.zeros(np.shape(self.load))
        if self.rolling == "none":
            return out
        u_e = self.kin.v_cam - 0.5 * np.asarray(sliding, dtype=float)
        lub, c = self.contact.lubricant, self.contact
        R = self.kin.radius_x
        use = (self.load > 0.0) & (R > 0.0) & np.isfinite(R)
        if np.count_nonzero(use):
            common = (u_e[use], at(lub.viscosity, use), at(lub.pressure_viscosity, use),
                      at(c.reduced_modulus, use), R[use])
            if self.hertz.line:
                out[use] = goksem_hargreaves_rolling(*common, at(c.width, use), self.load[use])
            else:
                out[use] = goksem_hargreaves_ellipse_rolling(
                    *common, self.hertz.half_length[use], self.load[use])
        return out


class _RollerView:
    """The speeds and radii the film and friction laws read, at some angles, with the roller's
    surface speed: a light stand-in for the roller's Kinematics inside the speed solvers."""

    def __init__(self, kin, idx, sliding):
        self.line_contact = kin.line_contact
        self.v_cam = kin.v_cam[idx]
        self.sliding = sliding
        self.v_follower = self.v_cam - sliding
        self.entrainment = self.v_cam - 0.5 * sliding
        self.entrainment_sum = 2.0 * self.entrainment
        self.radius_x = kin.radius_x[idx]
        self.radius_y = kin.radius_y[idx]


def _hertz_at(hz: HertzField, idx) -> HertzField:
    return HertzField(pmax=hz.pmax[idx], half_width=hz.half_width[idx],
                      half_length=hz.half_length[idx], bad=hz.bad[idx], line=hz.line)


def goksem_hargreaves_rolling(u_e, eta0, alpha, E_r, R, L, W):
    """Hydrodynamic rolling force of an EHL line contact [N] (Goksem & Hargreaves 1978; see the
    module docstring): 4.318 (G U)^0.658 W^0.0126 R L / alpha; 0 for alpha = 0 or u_e = 0."""
    alpha = np.asarray(alpha, dtype=float)
    safe = np.where(alpha > 0.0, alpha, 1.0)
    U = eta0 * np.abs(u_e) / (E_r * R)
    Wd = W / (E_r * R * L)
    F = 4.318 * (safe * E_r * U) ** 0.658 * Wd ** 0.0126 * R * L / safe
    return np.where(alpha > 0.0, F, 0.0)


#: int_{-1}^{1} (1 - s^2)^0.0126 ds = B(1/2, 1.0126): the slices' load factor of the ellipse
_SLICE_INTEGRAL = math.sqrt(math.pi) * math.gamma(1.0126) / math.gamma(1.5126)


def goksem_hargreaves_ellipse_rolling(u_e, eta0, alpha, E_r, R, a_y, W):
    """Hydrodynamic rolling force of an elliptical EHL contact [N]: the line formula on slices
    across the rolling direction, each with the Hertz load per length (3 W / 4 a_y)(1 - s^2)
    (see the module docstring); ``a_y`` the ellipse's semi-axis across the rolling direction."""
    alpha = np.asarray(alpha, dtype=float)
    safe = np.where(alpha > 0.0, alpha, 1.0)
    U = eta0 * np.abs(u_e) / (E_r * R)
    w0 = 0.75 * W / a_y
    F = (4.318 * (safe * E_r * U) ** 0.658 * (w0 / (E_r * R)) ** 0.0126 * R * a_y
         * _SLICE_INTEGRAL / safe)
    return np.where(alpha > 0.0, F, 0.0)


def mixed_traction(contact, area, load, h, newtonian, use, law: str,
                   tabulated: bool = False) -> np.ndarray:
    """|F| [N] on the angles ``use``: fluid shear (Newtonian ``newtonian`` [N] over the whole
    zone, or its Eyring form, below the limiting shear) on the fluid share plus Greenwood-Tripp
    asperity friction, capped at mu_b W; ``area`` the Hertz area of those angles
    (:attr:`Traction.area`); ``tabulated``: the Greenwood-Tripp integrals from their table."""
    from camtrain.formulas import teodorescu_2005_friction
    from camtrain.formulas.mixed import greenwood_tripp_function, greenwood_tripp_tabulated

    lub, trib = contact.lubricant, contact.tribology
    sigma = at(lub.roughness, use)
    beta = sigma / trib.roughness_slope
    zeta = trib.asperity_density_product / (beta * sigma)
    W, hu = load[use], h[use]
    lam = hu / sigma
    # Greenwood-Tripp asperities only below the limit (the integrals are the costly part)
    mixed = lam < LAMBDA_LIMIT
    boundary = np.zeros(area.shape)
    asperity_area = np.zeros(area.shape)
    asperity_load = np.zeros(area.shape)
    if np.count_nonzero(mixed):
        t = teodorescu_2005_friction(W[mixed], area[mixed], lam[mixed], trib.eyring_stress,
                                     trib.shear_pressure_coefficient,
                                     trib.boundary_shear_coefficient, contact.reduced_modulus,
                                     np.broadcast_to(sigma, area.shape)[mixed],
                                     np.broadcast_to(beta, area.shape)[mixed],
                                     np.broadcast_to(zeta, area.shape)[mixed],
                                     lambda_limit=LAMBDA_LIMIT,
                                     integral=(greenwood_tripp_tabulated if tabulated
                                               else greenwood_tripp_function))
        boundary[mixed] = t.boundary
        asperity_area[mixed] = t.asperity_area
        asperity_load[mixed] = t.asperity_load
    fluid_area = np.maximum(area - asperity_area, 0.0)
    share = np.divide(fluid_area, area, out=np.zeros(area.shape), where=area > 0.0)
    # the limiting shear tau_0 (A - A_a) + gamma (W - W_a) (Teodorescu eq. 12)
    limit = (trib.eyring_stress * (area - asperity_area)
             + trib.shear_pressure_coefficient * (W - asperity_load))
    newton = share * newtonian
    if law == "eyring":
        tau0 = trib.eyring_stress
        if tau0 > 0.0:
            mean = np.divide(newton, fluid_area, out=np.zeros(area.shape), where=fluid_area > 0)
            newton = fluid_area * tau0 * np.arcsinh(mean / tau0)
    fluid = np.minimum(newton, limit)
    total = boundary + fluid
    return np.minimum(total, at(trib.boundary_friction, use) * W)
