"""Piezoviscous and compressible oil of the line-contact EHL solver, in Hertzian units.

Dimensionless viscosity eta/eta0 and density rho/rho0 of the dimensionless pressure P = p/p_h,
each with its derivative in P (the Newton Jacobian needs them). The laws are the published ones
of :mod:`camtrain.formulas.viscosity` and :mod:`camtrain.formulas.density`; this module only
scales them and adds the analytic slopes.

Options (named, documented in docs/ehl.md):

* viscosity ``roelands`` (default; Roelands 1966 with z matched to alpha at p = 0, eta_inf =
  6.31e-5 Pa s, p_r = 1.96e8 Pa) or ``barus`` (eta0 exp(alpha p));
* density ``dowson_higginson`` (default) or ``incompressible``.

Both laws take max(P, 0): at P <= 0 the viscosity is eta0 and the density rho0. Roelands'
(1 + p/p_r)^z has no real value below p = -p_r and Barus' exponential would thin the oil
without a physical basis; negative P occurs in the half-Sommerfeld solution (the full-film
pressure, its negative part dropped) and within the smoothing of the Elrod-Adams kink.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from camtrain.formulas.density import dowson_higginson_density, dowson_higginson_density_slope
from camtrain.formulas.viscosity import ROELANDS_ETA_INF, ROELANDS_P_R, roelands_z

VISCOSITY_LAWS = ("roelands", "barus")
DENSITY_LAWS = ("dowson_higginson", "incompressible")


@dataclass(frozen=True)
class Oil:
    """Isothermal Newtonian oil: eta0 [Pa s], alpha [1/Pa] and the two law names."""

    eta0: float
    alpha: float
    viscosity: str = "roelands"
    density: str = "dowson_higginson"

    def __post_init__(self):
        if self.viscosity not in VISCOSITY_LAWS:
            raise ValueError(f"viscosity law {self.viscosity!r}: expected one of {VISCOSITY_LAWS}")
        if self.density not in DENSITY_LAWS:
            raise ValueError(f"density law {self.density!r}: expected one of {DENSITY_LAWS}")


@dataclass(frozen=True)
class ScaledOil:
    """The oil in Hertzian units for one Hertz pressure p_h [Pa]."""

    oil: Oil
    p_h: float
    #: Roelands' (z, ln(eta0/eta_inf)), fixed by the oil: computed once, not per iterate
    _roelands: tuple = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        z = s = 0.0
        if self.oil.viscosity == "roelands":
            z = float(roelands_z(self.oil.eta0, self.oil.alpha))
            s = float(np.log(self.oil.eta0 / ROELANDS_ETA_INF))
        object.__setattr__(self, "_roelands", (z, s))

    def log_viscosity(self, P: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """ln(eta/eta0) and its P-derivative; Roelands' slope as (1 + p/p_r)^z / (1 + p/p_r)
        (one power per call)."""
        if self.oil.viscosity == "barus":
            p = self.p_h * np.maximum(P, 0.0)
            return self.oil.alpha * p, np.full_like(P, self.oil.alpha * self.p_h)
        z, scale = self._roelands
        base = 1.0 + (self.p_h / ROELANDS_P_R) * np.maximum(P, 0.0)
        power = base**z
        return scale * (power - 1.0), (scale * z * self.p_h / ROELANDS_P_R) * (power / base)

    def density(self, P: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """rho/rho0 and its P-derivative."""
        if self.oil.density == "incompressible":
            return np.ones_like(P), np.zeros_like(P)
        p = self.p_h * np.maximum(P, 0.0)
        return (np.asarray(dowson_higginson_density(p)) + 0.0 * P,
                np.asarray(dowson_higginson_density_slope(p)) * self.p_h + 0.0 * P)
