"""The hydrodynamic film of one piston ring at one instant (Yang 1992 §5.3, eqs. 5.17-5.31).

Worked in the *entrainment frame*: xi runs from the inlet flank (xi = 0) to the outlet flank
(xi = b) in the direction the liner drags the oil, at speed u >= 0. The caller mirrors the face
(x_c -> b - x_c) and swaps the flank pressures when the liner moves the other way. With
C_1 = 6 eta u and C_2 = 12 eta V (V = dh_min/dt, uniform over the rigid face), Reynolds' equation
(5.19) integrates once to

    dp/dxi = (C_1 h + C_2 xi + C_3) / h^3                                              (5.20)
    p      = p_in + C_1 I_1 + C_2 I_2 + C_3 I_3           (5.21; I_n from ring_face)

Boundary conditions: p(xi_1) = p_in at the (flooded or starved) inlet; Reynolds rupture at xi_2
(p = dp/dxi = 0, 5.22), a striated cavity at zero gauge pressure, reformation at xi_3 with the
flow of the rupture line, u h_2/2, carried on (squeeze neglected there, 5.24-5.26) up to p_out at
the outlet flank. When the full film stays at or above the cavity pressure (flank pressures high
enough, or a squeeze that closes the gap) no rupture is imposed: p(xi_1) = p_in, p(b) = p_out.

Friction on the ring (5.31) is the wall shear -h/2 dp/dxi + eta u / h over the films, with the
cavity carrying Couette shear on its oil fraction, eta u h_2 / h^2 (Yang prints no cavity
formula; this is the usual striated-film reading, ``cavity_shear``).

The integrals I_n are closed forms for the parabolic face h = h_m + (x - x_c)^2/(2 R_r) (5.15):
with s = sqrt(2 R_r h_m) and t = (x - x_c)/s, h = h_m (1 + t^2) and every integral reduces to
int dt/(1+t^2)^n and int t dt/(1+t^2)^n (arctan and rational terms). The arithmetic lives in the
compiled kernel :mod:`camtrain.piston._ring_kernel`.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class FaceIntegrals:
    """Definite integrals over [a, c] of the parabolic gap (SI): ``h_1 = int dx/h``,
    ``h_2 = int dx/h^2`` (Yang's I_1), ``h_3 = int dx/h^3`` (I_3), ``x_2 = int x dx/h^2``,
    ``x_3 = int x dx/h^3`` (I_2), ``xx_3 = int x^2 dx/h^3``."""

    h_1: float
    h_2: float
    h_3: float
    x_2: float
    x_3: float
    xx_3: float


def face_integrals(a: float, c: float, h_m: float, x_c: float, radius: float) -> FaceIntegrals:
    """The integrals of :class:`FaceIntegrals` over [a, c] (Yang eq. 5.22, closed form)."""
    from camtrain.piston._ring_kernel import integrals

    return FaceIntegrals(*integrals(float(a), float(c), float(h_m), float(x_c), float(radius)))


@dataclass(frozen=True)
class RingFilm:
    """One instant of a ring film (entrainment frame; SI, per metre of circumference).

    ``load`` [N/m] carried by the film; ``friction`` [N/m] on the ring along +xi; ``flow``
    [m^2/s] leaving the outlet (+xi); ``x_rupture``, ``x_reform`` [m] (both b for a full film);
    ``cavitated``; ``fallback`` when no consistent rupture exists and the negative pressures of
    the full film were dropped (half-Sommerfeld) instead.
    """

    load: float
    friction: float
    flow: float
    x_rupture: float
    x_reform: float
    cavitated: bool
    fallback: bool


def ring_film(h_m, V, u, eta, p_in, p_out, b, x_c, radius, x1=0.0,
              cavity_shear: str = "striated") -> RingFilm:
    """The film of a parabolic ring face at one instant (entrainment frame, see module doc).

    Args:
        h_m: minimum face gap [m]; V: dh_m/dt [m/s]; u: liner speed along +xi [m/s] (>= 0);
        eta: viscosity [Pa s]; p_in, p_out: gauge gas pressures at the inlet and outlet flanks
        [Pa] (the cavity is at zero gauge; negative flank pressures are taken as zero);
        b: face height [m]; x_c: position of the minimum gap from the inlet flank [m];
        radius: face radius R_r [m]; x1: starved inlet position [m] (0 = flooded);
        cavity_shear: ``"striated"`` (eta u h_2/h^2) or ``"none"``.
    """
    from camtrain.piston._ring_kernel import film

    if cavity_shear not in ("striated", "none"):
        raise ValueError(f"unknown cavity shear {cavity_shear!r}; expected 'striated' or 'none'")
    out = film(*(float(v) for v in (h_m, V, u, eta, p_in, p_out, b, x_c, radius, x1)),
               cavity_shear == "striated")
    return RingFilm(*(float(v) for v in out[:5]), bool(out[5]), bool(out[6]))
