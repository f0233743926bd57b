"""EHL and hydrodynamic film thickness of line contacts (cylinder on plane, cam on flat follower).

Common symbols (SI):

* w   load per unit contact length [N/m] (W/L, L the cam width);
* R   reduced radius in the entraining direction [m], 0 < R < inf;
* u   entrainment speed [m/s], the **mean** of the two surface speeds (u1 + u2)/2. Only |u|
  enters. Ball (1988) printed numbers use the *sum* u1 + u2: a caller reproducing them passes
  the sum (see :func:`camtrain.formulas.elastic.entrainment_speed`);
* eta0 ambient-pressure viscosity [Pa s]; alpha pressure-viscosity coefficient [1/Pa];
* E_r reduced modulus E' [Pa];
* dimensionless groups U = eta0 |u| / (E' R), G = alpha E', W = w / (E' R).

Validity ranges, in these groups and Moes' M and L, are held by the registry
(:data:`camtrain.formulas.film.FILM_METHODS`) and listed in docs/formulas.md. For the power-law
EHL fits they are nominal: U 1e-14..1e-9, G 1000..10000, W 1e-6..1e-3 (isothermal, fully
flooded, Newtonian, steady, smooth surfaces).

Edge cases: u = 0 gives h = 0 exactly (no warning); w = 0 gives h = +inf (no warning: an
unloaded contact separates; these formulas are not defined there); negative w and non-Hertzian
radii are field errors.
"""
from __future__ import annotations

import numpy as np

from ._util import arr, checking, non_negative, out, positive, radius, safe_exp

__all__ = ["line_groups", "dowson_higginson_1977", "dowson_higginson_1966",
           "dowson_toyoda_1979", "pan_hamrock_1989_min", "pan_hamrock_1989_cen", "moes_1992",
           "martin_1916", "dowson_dunn_taylor_1983", "rahnejat_1984"]


def speed_material_groups(R, u, eta0, alpha, E_r):
    """U = eta0 |u| / (E' R) and G = alpha E' (Dowson-Higginson groups), for validated R, E'."""
    U = positive("eta0", eta0) * np.abs(arr(u)) / (E_r * R)
    if checking() and not np.all(np.isfinite(U)):
        raise ValueError("u must be finite")
    return U, non_negative("alpha", alpha) * E_r


def line_groups(w, R, u, eta0, alpha, E_r):
    """Validated dimensionless groups (U, G, W) of a line contact; W may be None if w is."""
    R, E_r = radius("R", R), positive("E_r", E_r)
    U, G = speed_material_groups(R, u, eta0, alpha, E_r)
    W = None if w is None else non_negative("w", w) / (E_r * R)
    return U, G, W


def _power_film(C, a_u, a_g, a_w, w, R, u, eta0, alpha, E_r):
    return power_film_of_groups((C, a_u, a_g, a_w), arr(R), *line_groups(w, R, u, eta0, alpha,
                                                                          E_r))


def power_film_of_groups(power_law, R, U, G, W):
    """h = R C U^a_u G^a_g W^a_w of a power-law fit ``power_law`` = (C, a_u, a_g, a_w) from
    validated groups (:func:`line_groups`); several fits of one contact share the groups."""
    C, a_u, a_g, a_w = power_law
    loaded = W > 0
    h = R * C * U**a_u * G**a_g * np.where(loaded, W, 1.0) ** a_w
    return out(np.where(loaded, h, np.inf))  # unloaded: +inf even when u = 0


def _power_law(*coefficients):
    """Mark a formula as the power-law fit h/R = C U^a_u G^a_g W^a_w with these coefficients."""
    def mark(fn):
        fn.power_law = coefficients
        return fn
    return mark


@_power_law(2.65, 0.70, 0.54, -0.13)
def dowson_higginson_1977(w, R, u, eta0, alpha, E_r):
    r"""Dowson & Higginson minimum film thickness, line contact.

    .. math:: \frac{h_{min}}{R} = 2.65\, U^{0.70} G^{0.54} W^{-0.13}

    Isothermal, fully flooded, Newtonian, steady; piezoviscous-elastic regime.

    Returns:
        h_min [m].

    Reference: Dowson & Higginson (1977) *Elastohydrodynamic Lubrication*, SI ed.; Ball (1988)
    eq. 4.1 (coefficient set as commonly quoted). Benchmarks (formulas_and_anchors §4.1):
    case A 336.5 nm, B 34.9 nm, C 429.4 nm.
    """
    return _power_film(*dowson_higginson_1977.power_law, w, R, u, eta0, alpha, E_r)


@_power_law(1.6, 0.70, 0.60, -0.13)
def dowson_higginson_1966(w, R, u, eta0, alpha, E_r):
    r"""Earlier Dowson & Higginson minimum film formula (coefficient 1.6), line contact.

    .. math:: \frac{h_{min}}{R} = 1.6\, G^{0.6} U^{0.7} W^{-0.13}
       \;\Leftrightarrow\; h = 1.6\,\alpha^{0.6}(\eta_0 u)^{0.7} E'^{0.03} R^{0.43} w^{-0.13}

    Göçmen (2013) eq. 2.1 uses the dimensional form with speed |U/2| where U is already the mean
    entraining speed (a second halving). His base-circle 0.0938 um is reproduced only by passing
    u = U_mean/2 as he does literally; the standard mean speed gives 0.152 um.

    Returns:
        h_min [m]. Reference: Dowson & Higginson (1966) *Elasto-hydrodynamic Lubrication*,
        Pergamon; Göçmen (2013) eq. 2.1.
    """
    return _power_film(*dowson_higginson_1966.power_law, w, R, u, eta0, alpha, E_r)


@_power_law(3.06, 0.69, 0.56, -0.10)
def dowson_toyoda_1979(w, R, u, eta0, alpha, E_r):
    r"""Dowson & Toyoda central film thickness, line contact.

    .. math:: \frac{h_{cen}}{R} = 3.06\, U^{0.69} G^{0.56} W^{-0.10}

    Returns:
        h_cen [m].

    Reference: Dowson & Toyoda, Proc. 5th Leeds-Lyon Symp. (held 1978, publ. 1979) p. 60;
    Ball (1988) eq. 4.2 (cited there as 1978). Benchmarks (formulas_and_anchors §4.1): case A
    439.0 nm, B 47.8 nm, C 557.0 nm.
    """
    return _power_film(*dowson_toyoda_1979.power_law, w, R, u, eta0, alpha, E_r)


@_power_law(1.714, 0.694, 0.568, -0.128)
def pan_hamrock_1989_min(w, R, u, eta0, alpha, E_r):
    r"""Pan & Hamrock minimum film thickness, line contact.

    .. math:: \frac{h_{min}}{R} = 1.714\, W^{-0.128} U^{0.694} G^{0.568}

    Reference: Pan & Hamrock (1989) ASME J. Tribol. 111:246 (coefficients as quoted in
    formulas_and_anchors §4.1, tag [K]). Benchmarks: A 314.5, B 32.8, C 400.8 nm.
    """
    return _power_film(*pan_hamrock_1989_min.power_law, w, R, u, eta0, alpha, E_r)


@_power_law(2.922, 0.692, 0.470, -0.166)
def pan_hamrock_1989_cen(w, R, u, eta0, alpha, E_r):
    r"""Pan & Hamrock central film thickness, line contact.

    .. math:: \frac{h_{cen}}{R} = 2.922\, W^{-0.166} U^{0.692} G^{0.470}

    Reference: Pan & Hamrock (1989) (coefficients tag [K]). Benchmarks: A 362.0, B 36.2,
    C 468.9 nm.
    """
    return _power_film(*pan_hamrock_1989_cen.power_law, w, R, u, eta0, alpha, E_r)


def moes_groups(w, R, u, eta0, alpha, E_r):
    """Moes parameters (M, L) with the mean-speed scaling M = W (2U)^-1/2, L = G (2U)^1/4.

    M is +inf where u = 0 (no entrainment).
    """
    U, G, W = line_groups(w, R, u, eta0, alpha, E_r)
    moving = U > 0
    M = np.where(moving, W / np.sqrt(2.0 * np.where(moving, U, 1.0)), np.inf)
    return M, G * (2.0 * U) ** 0.25


def moes_1992(w, R, u, eta0, alpha, E_r):
    r"""Moes central film thickness, line contact, valid across all four regimes.

    With U on the **mean** speed, M = W (2U)^{-1/2}, L = G (2U)^{1/4}, H = (h/R)(2U)^{-1/2}:

    .. math::
        H_{RI} = 3M^{-1},\; H_{EI} = 2.621 M^{-1/5},\; H_{RP} = 1.287 L^{2/3},\;
        H_{EP} = 1.311 M^{-1/8} L^{3/4},\; s = \tfrac15\left(7 + 8e^{-2H_{EI}/H_{RI}}\right)

    .. math::
        H = \left[\left(H_{RI}^{7/3} + H_{EI}^{7/3}\right)^{3s/7}
            + \left(H_{RP}^{-7/2} + H_{EP}^{-7/2}\right)^{-2s/7}\right]^{1/s}

    Validity: all four regimes by construction (registry: M 0.1..1e4, L 0..25, nominal).
    The factor 2 is Moes' "sum speed" scaling expressed with the mean speed. Writing
    M = W U^{-1/2} with U on the mean speed (a common slip) gives films ~38 % too low
    (formulas_and_anchors §4.1; tested). Flag: H_RI implies h = 6 eta0 u R / w, not Martin's
    4.895, so the low-M limit is not tested against :func:`martin_1916`.

    Returns:
        h_cen [m]; u = 0 gives 0, w = 0 gives +inf.

    Reference: Moes (1992) Wear 159:57; Venner (1991) thesis (constants as confirmed in public
    code, formulas_and_anchors §4.1). Benchmarks: A 438.0, B 46.7, C 555.8 nm.
    """
    M, L = moes_groups(w, R, u, eta0, alpha, E_r)
    U, _, W = line_groups(w, R, u, eta0, alpha, E_r)
    ok = (U > 0) & (W > 0)
    Ms = np.where(ok, M, 1.0)
    h_ri, h_ei = 3.0 / Ms, 2.621 * Ms**-0.2
    s = (7.0 + 8.0 * np.exp(-2.0 * h_ei / h_ri)) / 5.0
    iso = (h_ri ** (7.0 / 3.0) + h_ei ** (7.0 / 3.0)) ** (3.0 * s / 7.0)
    piezo = L > 0  # without piezoviscosity the second bracket vanishes (its limit is 0)
    Ls = np.where(piezo, L, 1.0)
    h_rp, h_ep = 1.287 * Ls ** (2.0 / 3.0), 1.311 * Ms**-0.125 * Ls**0.75
    vis = np.where(piezo, (h_rp**-3.5 + h_ep**-3.5) ** (-2.0 * s / 7.0), 0.0)
    H = (iso + vis) ** (1.0 / s)
    h = R * H * np.sqrt(2.0 * np.where(ok, U, 0.0))
    return out(np.where(ok, h, np.where(W > 0, 0.0, np.inf)))


def martin_1916(w, R, u, eta0):
    r"""Martin rigid-isoviscous minimum film, line contact (Reynolds exit condition).

    .. math:: h_{min} = 4.895\,\frac{\eta_0 u R}{w}

    The coefficient is 24 x 0.20395 (load integral with exit at X_e = 0.4751).

    Validity: rigid-isoviscous regime only (registry: Moes M <= 1 and L <= 1, nominal).
    Reference: Martin (1916) Engineering 102:119; formulas_and_anchors §4.1 (re-derived).
    Benchmarks: A 19.6 nm, C 29.4 nm.
    """
    R = radius("R", R)
    num = 4.895 * positive("eta0", eta0) * np.abs(arr(u)) * R
    w = non_negative("w", w)
    loaded = w > 0
    return out(np.where(loaded, num / np.where(loaded, w, 1.0), np.inf))


def dowson_dunn_taylor_1983(R, u, eta0, alpha):
    r"""Rigid-piezoviscous ("Blok limitation") minimum film, line contact; needs no load.

    .. math:: h_{min} = 1.666\,(\eta_0 u \alpha)^{2/3} R^{1/3}

    Used by Ball when the load is unknown. Validity: rigid-piezoviscous regime (negligible
    elastic flattening; registry: Moes M <= 3 when the load is known, nominal); over-predicts
    in the elastic regimes.

    Returns:
        h_min [m]. Reference: Ball (1988) eq. 4.3, citing Dowson, Dunn & Taylor (1983)
        after Blok (1965). Harrison nose at 1500 rpm (R = 6.0766 mm, u = 1.197 m/s mean,
        eta0 = 0.05, alpha = 22e-9) gives 0.365 um (Ball extraction §4.4, derived).
    """
    R = radius("R", R)
    base = positive("eta0", eta0) * np.abs(arr(u)) * non_negative("alpha", alpha)
    return out(1.666 * base ** (2.0 / 3.0) * np.cbrt(R))


def rahnejat_1984(w, R, u, eta0, alpha, E_r, squeeze_ratio=0.0, load_exponent=-0.059):
    r"""Rahnejat central film for a finite line contact with entraining and squeeze action.

    .. math:: \frac{h_0}{R} = 1.67\, G^{0.421} U^{0.541} W^{e_w} \exp(-96.775\, w_s)

    with w_s = (dh0/dt)/u the squeeze-roll ratio (negative when the surfaces approach, which
    thickens the film). The load exponent e_w is printed +0.059 in Teodorescu et al. (2005)
    eq. 5; every EHL fit has a negative load exponent, so the default is -0.059 (configurable).

    Unvalidated here: no published value to test against, and at formulas_and_anchors §4.1
    case A it gives ~5x Dowson & Toyoda, so treat it as indicative only.

    Returns:
        h_0 [m]. Reference: Rahnejat (1984) PhD thesis, Imperial College; Teodorescu, Kushwaha,
        Rahnejat & Taraza (2005) eqs. 5-6. Check: w_s = -0.01 multiplies h by 2.632.
    """
    U, G, W = line_groups(w, R, u, eta0, alpha, E_r)
    ws = arr(squeeze_ratio)
    if not np.all(np.isfinite(ws)):
        raise ValueError("squeeze_ratio must be finite (clamp it near zero entrainment)")
    loaded = W > 0
    h = R * 1.67 * G**0.421 * U**0.541 * np.where(loaded, W, 1.0) ** load_exponent
    pos = h > 0  # apply the squeeze factor in log space: +inf (silent) only for absurd rates
    h = np.where(pos, safe_exp(np.log(np.where(pos, h, 1.0)) - 96.775 * ws), 0.0)
    return out(np.where(loaded, h, np.inf if load_exponent < 0 else 0.0))
