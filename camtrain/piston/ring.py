"""One piston ring over an engine cycle: liner speed, radial balance and the implicit film march.

Yang 1992 §5.3: the ring is held still and the liner moves past it at U_l = -U_r (eq. 5.16); the
film must carry the radial load of the gas on its back face and its own tension (5.17)

    F_z = p_back b + T b - p_in x_1           (p_back = max(p_1, p_2); x_1 the dry, starved inlet)

and the minimum film h follows from F_z = W(h, dh/dt) (5.27, 5.28). Yang marches h with a
trapezoidal predictor-corrector (5.29); camtrain solves each step's implicit equation for
h_{n+1} exactly by a bracketed root (the film load falls monotonically with h at the step's
squeeze velocity), by the trapezoid (second order, Yang's) or backward Euler (first order,
L-stable), and repeats cycles until the film at the start angle repeats (Yang: ~1.25 cycles).

Boundary lubrication (Yang §5.3.2.3): where h <= the composite roughness the friction is
mu F_z with mu = 0.08; the film march itself goes on unchanged.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: Yang §5.3.2.3: boundary friction coefficient of a ring below the roughness.
RING_BOUNDARY_FRICTION = 0.08


@dataclass(frozen=True)
class Ring:
    """A compression ring (SI): face height ``height``, face radius ``radius``, non-dimensional
    ``offset`` O/(b/2) in [-1, 1] (> 0: the minimum gap towards the chamber), elastic
    ``tension`` as a pressure on the face [Pa], face ``roughness`` [m]."""

    height: float
    radius: float
    offset: float
    tension: float
    roughness: float

    @property
    def x_min(self) -> float:
        """Position of the minimum gap from the chamber-side flank, b/2 - O (Yang eq. 5.15)."""
        return 0.5 * self.height * (1.0 - self.offset)


def liner_speed(theta, crank_radius: float, rod_length: float, omega: float):
    """Liner speed relative to the ring, U_l = -U_r [m/s], +x towards the crankcase (Yang 5.16).

    U_r = R omega (sin theta + sin 2 theta / (2 sqrt((L/R)^2 - sin^2 theta))), theta from TDC.
    """
    theta = np.asarray(theta, dtype=float)
    lam = rod_length / crank_radius
    s = np.sin(theta)
    return -crank_radius * omega * (s + np.sin(2.0 * theta) / (2.0 * np.sqrt(lam * lam - s * s)))


def piston_position(theta, crank_radius: float, rod_length: float):
    """Piston travel from TDC [m] of the exact slider crank (Williams 2013 App. A5)."""
    from camtrain.engine.crank import slider_crank_exact

    x = slider_crank_exact(theta, crank_radius, rod_length, 0.0)[0]
    return crank_radius + rod_length - x


def composite_roughness(sigma_ring: float, sigma_liner: float, rule: str = "rms") -> float:
    """Ring/liner composite roughness: sqrt(s1^2 + s2^2) (``rms``) or s1 + s2 (``sum``); Yang
    leaves the rule open (§5.3.2.3)."""
    if rule == "rms":
        return math.hypot(sigma_ring, sigma_liner)
    if rule == "sum":
        return sigma_ring + sigma_liner
    raise ValueError(f"unknown roughness rule {rule!r}; expected 'rms' or 'sum'")


@dataclass(frozen=True)
class RingCycle:
    """A ring's cyclic film (per metre of circumference unless stated).

    ``theta`` [rad]; ``h_min`` [m]; ``load`` F_z [N/m]; ``friction`` [N/m] on the ring, +x
    towards the crankcase (boundary where ``boundary``); ``flow`` [m^2/s] through the ring, +x;
    ``layer`` [m] oil left on the liner behind the ring (Yang 5.35); ``inflow`` [m^2/s] drawn
    through the inlet meniscus, +x (equal to ``flow`` but for the squeeze); ``supply`` [m] the
    layer the inlet was given (NaN where flooded); ``boundary`` mask; ``cycles`` marched and the
    relative ``cyclic_change`` of the start film (and of the own layer where the ring feeds on
    it).
    """

    theta: np.ndarray
    h_min: np.ndarray
    load: np.ndarray
    friction: np.ndarray
    flow: np.ndarray
    layer: np.ndarray
    inflow: np.ndarray
    supply: np.ndarray
    boundary: np.ndarray
    cycles: int
    cyclic_change: float


def march_ring(ring: Ring, theta, U, eta, p_above, p_below, omega: float, *,
               layer=None, own_feed=None, own_start=None, scheme: str = "trapezoid",
               h_start: float = 1e-6,
               tolerance: float = 1e-4, max_cycles: int = 12, boundary_roughness: float = 0.0,
               boundary_friction: float = RING_BOUNDARY_FRICTION) -> RingCycle:
    """March a ring's minimum film around the cycle until it repeats (Yang §5.3, §6.2.2).

    Args:
        theta: uniform crank-angle grid over one cycle [rad], without the end point.
        U, eta, p_above, p_below: liner speed [m/s], viscosity [Pa s] and gauge gas pressures
            above and below the ring [Pa] on that grid.
        layer: oil layer on the liner available to the inlet [m] per angle (None: flooded;
            negative entries flooded).
        own_feed: (from, to, weight) per angle: where ``from >= 0`` the inlet is fed by the layer
            the ring itself left at angles from/to of the same march, linearly weighted (its
            previous stroke at the same liner position; Yang eq. 5.36 and the dead centres).
        own_start: the ring's own layer [m] per angle before the march has laid it (-1: none).
        scheme: ``"trapezoid"`` (Yang 5.29, order 2) or ``"backward_euler"`` (order 1).
        tolerance: relative cyclic-convergence tolerance on h at the start angle.
        boundary_roughness: composite roughness [m]: at or below it the friction is
            ``boundary_friction`` x F_z.
    """
    from camtrain.piston import _ring_kernel as K

    if scheme not in ("trapezoid", "backward_euler"):
        raise ValueError(f"unknown ring march {scheme!r}; expected 'trapezoid' or "
                         "'backward_euler'")
    theta = np.asarray(theta, dtype=float)
    n = theta.size
    dth = float(theta[1] - theta[0])
    w = abs(float(omega))
    U, eta, p_above, p_below = (np.ascontiguousarray(np.broadcast_to(np.asarray(a, float), (n,)))
                                for a in (U, eta, p_above, p_below))
    lay = np.full(n, -1.0) if layer is None else np.ascontiguousarray(
        np.broadcast_to(np.asarray(layer, float), (n,)))
    if own_feed is None:
        own_from = np.full(n, -1, dtype=np.int64)
        own_to, own_weight = own_from.copy(), np.zeros(n)
    else:
        own_from, own_to = (np.ascontiguousarray(a, dtype=np.int64) for a in own_feed[:2])
        own_weight = np.ascontiguousarray(own_feed[2], dtype=float)
    start = np.full(n, -1.0) if own_start is None else np.ascontiguousarray(
        np.nan_to_num(np.asarray(own_start, float), nan=-1.0))
    geometry = K.RingGeometry(ring.height, ring.radius, ring.x_min, ring.tension, True)
    h, g, supply, cycles, change = K.march(h_start, dth, w, scheme == "trapezoid", U, eta, p_above,
                                        p_below, lay, K.OwnFeed(own_from, own_to, own_weight,
                                                                start), geometry, tolerance,
                                        max_cycles)
    u_dead = K.DEAD_CENTRE * float(np.max(np.abs(U)))
    load, friction, flow, inflow, layer_out = (np.empty(n) for _ in range(5))
    for i in range(n):
        f, f_z, sign, _ = K.state(h[i], w * g[i], U[i], eta[i], p_above[i], p_below[i], supply[i],
                               *geometry)
        load[i], friction[i], flow[i], inflow[i] = f_z, sign * f[1], sign * f[2], sign * f[7]
        layer_out[i] = f[2] / abs(U[i]) if abs(U[i]) > u_dead else np.nan
    boundary = h <= boundary_roughness
    friction = np.where(boundary, boundary_friction * load * np.sign(U), friction)
    return RingCycle(theta, h, load, friction, flow, layer_out, inflow,
                     np.where(supply < 0.0, np.nan, supply), boundary, int(cycles), float(change))
