"""Tabulated mobility maps: any bearing model's mobility, sampled, for the orbit march.

Booker's (1965) mobility method needs only the map from the eccentricity (seen from the load) to
the squeeze velocity. A finite-length bearing has no closed form; its map is tabulated once from a
Reynolds solution and the march interpolates it. Normalisation (Booker 1965, Yang 1992 eq. 1.12)::

    w = W (c/r)^2 / (eta b d) * M(xi, mu)

with w the journal-centre velocity in clearance units per second seen from the frame turning at
wbar, xi the eccentricity-ratio component along the load W and mu the component normal to it,
positive in the sense of wbar; M = (M_xi, M_mu) in the same frame. ``b`` is the bearing's overall
length and ``d`` its diameter: a map belongs to one b/d (and groove) geometry.

The table is on a polar grid: eccentricity ratios ``eps`` (increasing, from 0, below 1) by
``n_angle`` angles of the eccentricity from the load direction, uniform over one turn starting at
0 (periodic). The march interpolates bilinearly and stops with a ConvergenceError if the journal
leaves the table (eccentricity above the last ``eps``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camtrain.errors import field_error

from .mobility import mobility_booker

__all__ = ["MobilityMap"]


@dataclass(frozen=True, eq=False)
class MobilityMap:
    """Mobility components M_xi, M_mu [-] on an (eps, angle) grid, shape (len(eps), n_angle).

    Attributes:
        eps: eccentricity ratios of the rows, strictly increasing, 0 <= eps < 1.
        m_xi, m_mu: mobility components in the load frame (see the module docstring).
        name: label of the model that produced the map (shown as the orbit's method).
    """

    eps: np.ndarray
    m_xi: np.ndarray
    m_mu: np.ndarray
    name: str = "table"

    def __post_init__(self):
        eps = np.ascontiguousarray(self.eps, dtype=float)
        mxi = np.ascontiguousarray(self.m_xi, dtype=float)
        mmu = np.ascontiguousarray(self.m_mu, dtype=float)
        if eps.ndim != 1 or eps.size < 2 or eps[0] != 0.0 or np.any(np.diff(eps) <= 0) \
                or eps[-1] >= 1.0:
            raise field_error("mobility.eps", "must increase strictly from 0 and stay below 1",
                              eps[:3] if eps.size else eps)
        if mxi.ndim != 2 or mxi.shape[0] != eps.size or mxi.shape[1] < 4 \
                or mmu.shape != mxi.shape:
            raise field_error("mobility.m_xi", "tables must have one row per eps and the same "
                              "shape, with at least 4 angles", (mxi.shape, mmu.shape))
        if not (np.all(np.isfinite(mxi)) and np.all(np.isfinite(mmu))):
            raise field_error("mobility.m_xi", "must be finite")
        for name, value in (("eps", eps), ("m_xi", mxi), ("m_mu", mmu)):
            value.flags.writeable = False
            object.__setattr__(self, name, value)

    @property
    def angles(self) -> np.ndarray:
        """Angles of the columns [rad], from the load direction in the sense of wbar."""
        n = self.m_xi.shape[1]
        return np.arange(n) * (2.0 * math.pi / n)

    @classmethod
    def tabulate(cls, function, eps, n_angle: int = 72, name: str = "table") -> MobilityMap:
        """Sample ``function(xi, mu) -> (M_xi, M_mu)`` on the polar grid."""
        eps = np.asarray(eps, dtype=float)
        ang = np.arange(int(n_angle)) * (2.0 * math.pi / int(n_angle))
        m = np.array([[function(e * math.cos(a), e * math.sin(a)) for a in ang] for e in eps])
        return cls(eps, m[..., 0], m[..., 1], name)

    @classmethod
    def booker(cls, length_ratio: float, eps=None, n_angle: int = 72) -> MobilityMap:
        """Booker's closed-form short-bearing map (Yang 1992 eqs 1.15, 1.16) for b/d =
        ``length_ratio``, tabulated: the closed form scaled by (d/b)^2."""
        if not (length_ratio > 0 and math.isfinite(length_ratio)):
            raise field_error("length_ratio", "must be > 0", length_ratio)
        eps = np.linspace(0.0, 0.995, 200) if eps is None else eps
        scale = 1.0 / length_ratio ** 2
        return cls.tabulate(lambda x, m: tuple(scale * v for v in mobility_booker(x, m)), eps,
                            n_angle, f"booker-table(b/d={length_ratio:g})")

    def gain(self, bearing) -> float:
        """(c/r)^2 / (eta b d) [1/(N s)] of ``bearing``: w = W * gain * M."""
        return (bearing.clearance / bearing.radius) ** 2 / (
            bearing.viscosity * bearing.length * bearing.diameter)
