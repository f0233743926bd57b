"""Lubricant density against pressure.

SI: pressure [Pa] (gauge), density as the ratio rho(p)/rho0 [-].
"""
from __future__ import annotations

from ._util import arr, out

__all__ = ["dowson_higginson_density", "dowson_higginson_density_slope"]

#: Dowson-Higginson constants: 0.6e-9 /Pa and 1.7e-9 /Pa.
DH_A = 0.6e-9
DH_B = 1.7e-9


def dowson_higginson_density(p):
    r"""Dowson & Higginson (1966) compressibility of a mineral oil, as a density ratio.

    .. math:: \frac{\rho}{\rho_0} = 1 + \frac{0.6\times10^{-9}\,p}{1 + 1.7\times10^{-9}\,p}

    It tends to 1 + 0.6/1.7 = 1.353 at infinite pressure (about +28 % at 1 GPa).

    Args:
        p: gauge pressure [Pa], >= 0 in a lubricated contact.

    Returns:
        rho/rho0 [-].

    Reference: Dowson & Higginson (1966) *Elasto-hydrodynamic Lubrication*, Pergamon
    (the density law of their numerical solutions); Venner & Lubrecht (2000) ch. 2.
    """
    p = arr(p)
    return out(1.0 + DH_A * p / (1.0 + DH_B * p))


def dowson_higginson_density_slope(p):
    r"""d(rho/rho0)/dp of :func:`dowson_higginson_density` [1/Pa]: 0.6e-9 / (1 + 1.7e-9 p)^2."""
    p = arr(p)
    return out(DH_A / (1.0 + DH_B * p) ** 2)
