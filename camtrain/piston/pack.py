"""The compression-ring pack: oil handed from ring to ring on the liner (Yang 1992 §5.4, Table 6.1).

Each ring leaves an oil layer h_l = Q/|U| on the liner behind it (eq. 5.35; h_m/2 when the film
ruptures). The ring that follows meets that layer with its inlet where the face gap equals twice
the layer ('elementary geometry'), and never passes more oil than the layer brings (continuity,
eq. 5.34; enforced in the film kernel by moving the inlet downstream). On the downstroke the
bottom ring is flooded (splash); on the upstroke the top ring has only what it left on the liner
on its previous downstroke (eq. 5.36). Just after a dead centre a following ring has not yet
reached its leader's oil (it must travel the ring spacing): it meets what it left there itself on
its previous stroke (Yang's assumption, which he notes over-estimates films near TDC).

Passes (Table 6.1): every ring flooded; starved pass 1 from the bottom ring up; starved pass 2
from the top ring down. Two starved passes reach the fixed point for any number of rings.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.piston.ring import Ring, RingCycle, march_ring


@dataclass(frozen=True)
class PackRing:
    """A ring of the pack: its face, its depth below the top ring [m], the gauge gas pressures
    above and below it [Pa] on the cycle grid, its viscosity [Pa s] and composite roughness [m]."""

    ring: Ring
    depth: float
    p_above: np.ndarray
    p_below: np.ndarray
    eta: np.ndarray
    boundary_roughness: float


@dataclass(frozen=True)
class PackSolution:
    """Films of every ring after each pass: ``flooded`` and ``starved`` (lists of RingCycle,
    top ring first) and the ``layers`` [m] each starved ring was given (NaN = flooded)."""

    flooded: list[RingCycle]
    starved: list[RingCycle]
    layers: list[np.ndarray]


def _strokes(theta: np.ndarray) -> np.ndarray:
    """Stroke index (0 down, 1 up, 2 down, 3 up) of each angle of a 4-stroke cycle."""
    return np.minimum((np.mod(theta, 4.0 * np.pi) // np.pi).astype(int), 3)


def _layer_on_stroke(target_s, stroke, travel, strokes, layer):
    """Layer a ring left at travel ``target_s`` on ``stroke`` (interpolated in travel)."""
    on = strokes == stroke
    s, lay = travel[on], np.nan_to_num(np.maximum(layer[on], 0.0))
    order = np.argsort(s)
    return np.interp(target_s, s[order], lay[order])


def available_layer(index: int, pack: list[PackRing], results: list[RingCycle], travel,
                    U) -> np.ndarray:
    """Oil layer [m] at ring ``index``'s inlet at every angle (-1 where it is flooded)."""
    theta = results[index].theta
    strokes = _strokes(theta)
    full = travel.max()
    out = np.empty(theta.size)
    last = len(pack) - 1
    for i in range(theta.size):
        k = strokes[i]
        previous = (k - 1) % 4
        s = travel[i]
        if U[i] < 0.0:                                # downstroke: oil comes from below
            if index == last:
                out[i] = -1.0
                continue
            lag = pack[index + 1].depth - pack[index].depth
            if s - lag >= 0.0:
                out[i] = _layer_on_stroke(s - lag, k, travel, strokes, results[index + 1].layer)
            else:
                out[i] = _layer_on_stroke(s, previous, travel, strokes, results[index].layer)
        else:                                         # upstroke: oil comes from above
            if index > 0:
                lag = pack[index].depth - pack[index - 1].depth
                if s + lag <= full:
                    out[i] = _layer_on_stroke(s + lag, k, travel, strokes,
                                              results[index - 1].layer)
                    continue
            out[i] = _layer_on_stroke(s, previous, travel, strokes, results[index].layer)
    return np.where(np.isfinite(out), out, -1.0)


def solve_pack(pack: list[PackRing], theta, U, travel, omega: float, *, passes: int = 2,
               scheme: str = "trapezoid", tolerance: float = 1e-4) -> PackSolution:
    """Flooded rings, then ``passes`` starved passes alternating bottom-up and top-down."""
    def march(pr: PackRing, layer):
        return march_ring(pr.ring, theta, U, pr.eta, pr.p_above, pr.p_below, omega,
                          layer=layer, scheme=scheme, tolerance=tolerance,
                          boundary_roughness=pr.boundary_roughness)

    flooded = [march(pr, None) for pr in pack]
    results = list(flooded)
    layers = [np.full(len(theta), np.nan) for _ in pack]
    order = list(range(len(pack)))
    for p in range(passes):
        for n in (order[::-1] if p % 2 == 0 else order):
            lay = available_layer(n, pack, results, travel, U)
            layers[n] = np.where(lay < 0.0, np.nan, lay)
            results[n] = march(pack[n], lay)
    return PackSolution(flooded, results, layers)
