r"""Semi-analytic solution of the 1-D averaged Reynolds equation across a line contact.

Göçmen (2013) eq. 2.5 (Patir & Cheng 1978 averaged Reynolds equation reduced to the entraining
direction, with the squeeze term), written with the mean entrainment speed u_e = (U1 + U2)/2 and
the sliding speed u_s = U1 - U2:

.. math::
    \frac{d}{dx}\Big(\frac{\phi_x h^3}{12\eta}\frac{dp}{dx}\Big)
      = u_e\frac{d\bar h_T}{dx} + \frac{u_s}{2}\,\sigma\,\frac{d\Phi_s}{dx}
        + \phi_c\frac{\partial h}{\partial t}

Eq. 2.6 is its non-dimensional form (X = 2x/b, H = h/c, P = p c^2/(3 eta r omega b)); it is solved
here in SI units, which is the same equation. In 1-D it integrates once exactly:

.. math::
    \frac{\phi_x h^3}{12\eta}p' = A(x) + C,\qquad
    A = u_e\bar h_T + \tfrac{u_s}{2}\sigma\Phi_s + \int_{x_{in}}^{x}\phi_c\,\partial_t h\,dx'

so p = 12 eta (I_1 + C I_0), I_0 = int 1/D, I_1 = int A/D, D = phi_x h^3 (cumulative trapezoid
on the caller's nodes: second order in the node spacing; no linear system).

Boundary conditions (Göçmen Sec. 2.2.4.1): p = 0 at the upstream edge (chosen by the sign of u_e:
the entrainment-direction switch; pure squeeze u_e = 0 is symmetric either way) and

* ``reynolds`` (Swift-Stieber, default): p = dp/dx = 0 at the film rupture x_c. With
  g = -I_1/I_0, p >= 0 up to x_c requires C = g(x_c) at the first maximum of g, i.e. the first
  + to - sign change of f = I_1 - A I_0 = g' D I_0^2 (found on the nodes, located by linear
  interpolation). No change: the zone is *flooded* (p = 0 at the far edge); f <= 0 at once: the
  film is ruptured from the inlet (separating surfaces, p = 0). Downstream of x_c the film is
  cavitated and flow continuity gives the liquid fraction h_T(x_c)/h_T(x) (used in the friction).
  A film that builds no pressure at its inlet (f <= 0 at once: diverging or opening there),
  or whose cavitated part would re-pressurise downstream (a converging or approaching gap
  there: the edges opening faster than the centre approaches near an entrainment reversal) is
  handed to the complementarity solver of :mod:`.reynolds_fd`, which places every zone.
* ``half_sommerfeld``: p = 0 at both edges (linear), negative pressures dropped in the load
  (Göçmen eq. 2.7, Psi).
"""
from __future__ import annotations

import numpy as np

from .flow_factors import contact_factor, mean_gap, pressure_flow_factor, shear_flow_factor
from .pressure_solution import CAVITATION_MODELS, PressureSolution

__all__ = ["CAVITATION_MODELS", "PressureSolution", "cumulative_trapezoid", "reynolds_pressure",
           "contact_grid"]

def cumulative_trapezoid(y: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Cumulative trapezoid integral from x[0], starting at 0 (same length as x)."""
    out = np.empty_like(y)
    out[0] = 0.0
    np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(x), out=out[1:])
    return out


def contact_grid(n: int, clustering: float = 0.0) -> np.ndarray:
    """n nodes on [-1, 1]: uniform (clustering 0) or sinh-clustered at the centre.

    x = sinh(c s)/sinh(c), s uniform on [-1, 1]: a smooth map, so the trapezoid rule keeps its
    second order; c ~ 3-6 resolves a rigid-contact pressure in a zone many Hertz widths wide.
    """
    if n < 5:
        raise ValueError(f"nodes across the contact: got {n}, expected >= 5")
    s = np.linspace(-1.0, 1.0, n)
    if clustering <= 0.0:
        return s
    return np.sinh(clustering * s) / np.sinh(clustering)


def reynolds_pressure(x, h, u_e, dhdt, eta, sigma: float = 0.0, u_s: float = 0.0,
                      shear_weight: float = 1.0, cavitation: str = "reynolds",
                      flow_factors: bool = True) -> PressureSolution:
    """Pressure of the averaged Reynolds equation on the nodes x for a given gap (see module).

    Args:
        x: ascending nodes [m]; h: nominal gap h(x) > 0 [m]; u_e: mean entrainment [m/s];
        dhdt: local squeeze rate dh/dt at the nodes [m/s] (scalar or array; < 0 approach);
        eta: viscosity [Pa s]; sigma: composite rms roughness [m] (0: smooth, factors 1/0);
        u_s: sliding speed U1 - U2 [m/s]; shear_weight: Vr1 - Vr2 of the shear term;
        cavitation: ``reynolds`` or ``half_sommerfeld``; flow_factors: False sets phi = 1.

    Returns:
        :class:`PressureSolution`.
    """
    x = np.asarray(x, dtype=float)
    h = np.asarray(h, dtype=float)
    dhdt = np.broadcast_to(np.asarray(dhdt, dtype=float), x.shape)
    if cavitation not in CAVITATION_MODELS:
        raise ValueError(f"cavitation {cavitation!r}: expected one of {CAVITATION_MODELS}")
    if u_e < 0.0:   # entrainment-direction switch: solve the mirror image, inlet on the left
        s = reynolds_pressure(-x[::-1], h[::-1], -u_e, dhdt[::-1], eta, sigma, -u_s,
                              shear_weight, cavitation, flow_factors)
        return PressureSolution(s.pressure[::-1], s.load, -s.rupture, s.flooded,
                                s.liquid_fraction[::-1])
    rough = flow_factors and sigma > 0.0
    if rough:
        H = h / sigma
        phi_x, phi_c = pressure_flow_factor(H), contact_factor(H)
        h_mean = sigma * mean_gap(H)
        shear = 0.5 * u_s * sigma * shear_weight * shear_flow_factor(H) if u_s else 0.0
    else:
        phi_x, phi_c, h_mean, shear = 1.0, 1.0, h, 0.0
    S = u_e * h_mean + shear                  # Couette and shear flow
    A = S + cumulative_trapezoid(phi_c * dhdt, x)
    inv_D = 12.0 * eta / (phi_x * h**3)
    I0 = cumulative_trapezoid(inv_D, x)
    I1 = cumulative_trapezoid(A * inv_D, x)
    n = x.size
    fraction = np.ones(n)
    if cavitation == "half_sommerfeld":
        p = np.maximum(I1 - (I1[-1] / I0[-1]) * I0, 0.0)
        return PressureSolution(p, _trapezoid(p, x), np.nan, False, fraction)
    f = I1 - A * I0
    if not f[1] > 0.0:
        return _multi_zone(x, h, u_e, dhdt, eta, sigma, u_s, shear_weight, flow_factors)
    down = np.flatnonzero(f[2:] <= 0.0)
    if down.size == 0:      # flooded: p = 0 at the far edge, p >= 0 throughout
        p = np.maximum(I1 - (I1[-1] / I0[-1]) * I0, 0.0)
        return PressureSolution(p, _trapezoid(p, x), np.nan, True, fraction)
    k = int(down[0]) + 2    # f[k-1] > 0 >= f[k]: the rupture lies in (x[k-1], x[k]]
    # downstream the film stays cavitated only while nothing there would raise a pressure:
    # d(u_e h_T + shear)/dx + phi_c dh/dt >= 0 (the complementarity condition at p = 0)
    Sx = S * np.ones(n)
    source = (Sx[k + 2:] - Sx[k:-2]) / (x[k + 2:] - x[k:-2]) + (phi_c * dhdt)[k + 1:-1]
    if np.any(source < 0.0):
        return _multi_zone(x, h, u_e, dhdt, eta, sigma, u_s, shear_weight, flow_factors)
    t = f[k - 1] / (f[k - 1] - f[k])
    x_c = x[k - 1] + t * (x[k] - x[k - 1])
    A_c = A[k - 1] + t * (A[k] - A[k - 1])
    p = np.zeros(n)
    p[:k] = np.maximum(I1[:k] - A_c * I0[:k], 0.0)
    # p ~ (x_c - x)^2 near the rupture: the last partial cell integrates to p (x_c - x) / 3
    load = _trapezoid(p[:k], x[:k]) + p[k - 1] * (x_c - x[k - 1]) / 3.0
    hm_c = h_mean[k - 1] + t * (h_mean[k] - h_mean[k - 1])
    fraction[k:] = np.minimum(hm_c / h_mean[k:], 1.0)
    return PressureSolution(p, float(load), float(x_c), False, fraction)


def _multi_zone(x, h, u_e, dhdt, eta, sigma, u_s, shear_weight, flow_factors):
    """A pressure zone that does not start at the inlet, or more than one zone: any pressurised
    zone starts inside, which the single-zone integral cannot place; the complementarity solver
    finds every zone."""
    from .reynolds_fd import fd_reynolds_pressure
    return fd_reynolds_pressure(x, h, u_e, dhdt, eta, sigma, u_s, shear_weight, "reynolds",
                                flow_factors)


def _trapezoid(y, x) -> float:
    return float(np.dot(0.5 * (y[1:] + y[:-1]), np.diff(x))) if y.size > 1 else 0.0
