"""The compression-ring pack: oil handed from ring to ring on the liner (Yang 1992 §5.4, Table 6.1).

Each ring leaves an oil layer h_l = Q/|U| on the liner behind it (eq. 5.35; h_m/2 when the film
ruptures). The ring that follows meets that layer with its inlet where the face gap equals twice
the layer ('elementary geometry'), and never draws more oil through its inlet than the layer
brings (continuity, eq. 5.34; enforced in the film kernel by moving the inlet downstream, and
where even an inlet at the minimum gap draws more, by streamers that fill only part of the
circumference and draw all the layer brings). On
the downstroke the bottom ring is flooded (splash); on the upstroke the top ring has only what it
left on the liner on its previous downstroke (eq. 5.36). Just after a dead centre a following
ring has not yet reached its leader's oil (it must travel the ring spacing): it meets what it
left there itself on its previous stroke (Yang's assumption, which he notes over-estimates films
near TDC). Layers are mapped by liner position (depth below the top ring plus piston travel).

Passes (Table 6.1): every ring flooded; starved pass 1 from the bottom ring up; starved pass 2
from the top ring down. Yang states two starved passes reach the fixed point for any number of
rings; they do not: a ring's film near a dead centre is a squeeze film that remembers its
previous stroke, so the second ring's downstroke just after TDC (which feeds the top ring) still
moves when pass 2 changes its starved upstroke, and the top ring's zone within one ring spacing
of TDC, fed only by itself, drains under continuity (docs/piston.md). So by default the passes
go on, alternating, to the pack's fixed point within a stated tolerance (``converged``); Yang's
two passes are the ``yang1992`` option.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.piston.ring import Ring, RingCycle, march_ring
from camtrain.progress import detail


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
    top ring first) and the ``layers`` [m] each starved ring was given (NaN = flooded);
    ``passes`` the starved passes run, ``pass_change`` the largest change of a ring's films or
    of the layer it leaves between its last two marches (:func:`pass_change`), ``converged``
    whether that change is within the pass tolerance; per ring, ``cycles_most`` the most cycles
    any of its starved marches took and ``unrepeated`` how many of them stopped at their cap
    (:data:`STARVED_CYCLES`) before the film and own layer repeated."""

    flooded: list[RingCycle]
    starved: list[RingCycle]
    layers: list[np.ndarray]
    passes: int = 0
    pass_change: float = float("inf")
    converged: bool = False
    cycles_most: tuple = ()
    unrepeated: tuple = ()


def _strokes(theta: np.ndarray) -> np.ndarray:
    """Stroke index (0 down, 1 up, 2 down, 3 up) of each angle of a 4-stroke cycle."""
    return np.minimum((np.mod(theta, 4.0 * np.pi) // np.pi).astype(int), 3)


def _on_stroke(target_s, stroke, travel, strokes):
    """Where on ``stroke`` the ring was at travel ``target_s``: the two bracketing angle
    indices and the linear weight of the second (interpolation in travel)."""
    idx = np.flatnonzero(strokes == stroke)
    order = np.argsort(travel[idx], kind="stable")
    s, idx = travel[idx][order], idx[order]
    k = int(np.clip(np.searchsorted(s, target_s), 1, s.size - 1))
    span = s[k] - s[k - 1]
    weight = 0.0 if span <= 0.0 else float(np.clip((target_s - s[k - 1]) / span, 0.0, 1.0))
    return int(idx[k - 1]), int(idx[k]), weight


@dataclass(frozen=True)
class Feed:
    """Where ring ``index``'s inlet oil comes from at every angle: ``source`` -1 flooded, the
    index of the ring whose layer it meets, and ``angle_from``, ``angle_to``, ``weight``: the
    angles at which that ring laid it (interpolated in liner position)."""

    source: np.ndarray
    angle_from: np.ndarray
    angle_to: np.ndarray
    weight: np.ndarray


def feed(index: int, pack: list[PackRing], theta, travel, U) -> Feed:
    """The oil each angle of ring ``index`` meets on the liner (Yang §5.4, §6.2.3).

    The liner position under a ring is its depth below the top ring plus the piston travel, so
    a ring meets, at each liner position, the layer left by whichever ring swept that position
    last: on the downstroke the ring below on the same stroke (the bottom ring is flooded:
    splash, Yang §5.4), on the upstroke the ring above on the same stroke (the top ring: the
    layer it left itself on its previous downstroke, eq. 5.36). Where the ring has not yet
    travelled the ring spacing past a dead centre, no other ring has been there since its own
    previous stroke: it meets its own layer (Yang's dead-centre assumption, §6.2.3).
    """
    n = travel.size
    theta_strokes = _strokes(np.asarray(theta, dtype=float))
    full = travel.max()
    last = len(pack) - 1
    source = np.full(n, -1, dtype=np.int64)
    a_from = np.full(n, -1, dtype=np.int64)
    a_to = np.full(n, -1, dtype=np.int64)
    weight = np.zeros(n)
    for i in range(n):
        k = theta_strokes[i]
        s = travel[i]
        src, stroke, target = index, (k - 1) % 4, s
        if U[i] < 0.0:                                # downstroke: oil comes from below
            if index == last:
                continue
            lag = pack[index + 1].depth - pack[index].depth
            if s - lag >= 0.0:
                src, stroke, target = index + 1, k, s - lag
        elif index > 0:                               # upstroke: oil comes from above
            lag = pack[index].depth - pack[index - 1].depth
            if s + lag <= full:
                src, stroke, target = index - 1, k, s + lag
        source[i] = src
        a_from[i], a_to[i], weight[i] = _on_stroke(target, stroke, travel, theta_strokes)
    return Feed(source, a_from, a_to, weight)


def _interpolate(values, fd: Feed, mask):
    v = np.nan_to_num(np.maximum(values, 0.0))
    out = (1.0 - fd.weight) * v[np.maximum(fd.angle_from, 0)] \
        + fd.weight * v[np.maximum(fd.angle_to, 0)]
    return np.where(mask, out, -1.0)


#: Starved marches: a ring's supply steps where it first meets its leader's oil, and the
#: trapezoid (not L-stable) rings there, step to step; backward Euler damps it.
STARVED_SCHEME = "backward_euler"
#: Cycles a starved march may take: the ring's own layer must repeat as well as its film.
STARVED_CYCLES = 40
#: How the starved passes end: ``converged`` repeats them until the pack is at its fixed point
#: (every ring's films and the layer it leaves change by less than the pass tolerance between
#: two marches); ``yang1992`` stops after the given number of passes (Table 6.1: two).
PASS_MODES = ("converged", "yang1992")


def pass_change(old: RingCycle, new: RingCycle) -> float:
    """Change of a ring between two marches: the largest change of its minimum film and of the
    layer it leaves on the liner (what the other rings are fed), each relative to its largest
    value over the cycle. Films far below that (a dry ring near a dead centre, riding on its
    asperities) move the flows and the friction by no more than this."""
    dh = np.max(np.abs(new.h_min - old.h_min)) / np.max(np.abs(new.h_min))
    a, b = (np.nan_to_num(rc.layer) for rc in (old, new))
    top = np.max(np.abs(b))
    return float(max(dh, np.max(np.abs(b - a)) / top if top > 0.0 else 0.0))


def solve_pack(pack: list[PackRing], theta, U, travel, omega: float, *, passes: int = 2,
               pass_mode: str = "converged", pass_tolerance: float = 1e-3,
               max_passes: int = 60, scheme: str = "trapezoid", tolerance: float = 1e-4,
               starved_scheme: str = STARVED_SCHEME,
               start: PackSolution | None = None) -> PackSolution:
    """Flooded rings (march ``scheme``), then starved passes alternating bottom-up and top-down
    (march ``starved_scheme``): ``passes`` of them (``pass_mode="yang1992"``, Table 6.1), or
    until the pack's fixed point (``"converged"``: at least two, at most ``max_passes``, until
    :func:`pass_change` of every ring marched in a pass is below ``pass_tolerance``; a ring whose
    feeding rings have not moved since its own last march is not marched again).

    In each pass a ring meets the layers the other rings left in the latest pass (Table 6.1);
    where it meets its own layer (eq. 5.36, dead centres) that layer is the one it lays in the
    same cyclic march, so a ring's own strokes agree with each other at its cyclic solution.
    ``start``: a solution to carry on from (its flooded films and its latest starved ones).
    """
    if pass_mode not in PASS_MODES:
        raise ValueError(f"unknown pass mode {pass_mode!r}; expected one of {PASS_MODES}")
    feeds = [feed(n, pack, theta, travel, U) for n in range(len(pack))]
    sources = [set(fd.source[(fd.source >= 0) & (fd.source != n)].tolist())
               for n, fd in enumerate(feeds)]

    def march(n: int, layer, own, h_start: float = 1e-6):
        pr = pack[n]
        fd = feeds[n]
        mine = fd.source == n
        if layer is None:
            return march_ring(pr.ring, theta, U, pr.eta, pr.p_above, pr.p_below, omega,
                              scheme=scheme, tolerance=tolerance,
                              boundary_roughness=pr.boundary_roughness)
        return march_ring(pr.ring, theta, U, pr.eta, pr.p_above, pr.p_below, omega,
                          layer=layer, own_feed=(np.where(mine, fd.angle_from, -1),
                                                 fd.angle_to, fd.weight),
                          own_start=own, h_start=h_start, scheme=starved_scheme,
                          tolerance=tolerance,
                          max_cycles=STARVED_CYCLES, boundary_roughness=pr.boundary_roughness)

    if start is None:
        flooded = [march(n, None, None) for n in range(len(pack))]
        results = list(flooded)
        layers = [np.full(len(theta), np.nan) for _ in pack]
        done = 0
    else:
        flooded, results = start.flooded, list(start.starved)
        layers, done = list(start.layers), start.passes
    # version[n] counts ring n's marches; fed[n] the versions of its feeding rings it last met
    version = [0] * len(pack)
    fed: list[dict | None] = [None] * len(pack)
    order = list(range(len(pack)))
    converged = pass_mode == "converged"
    change = start.pass_change if start is not None else float("inf")
    p = done
    most = [0] * len(pack)
    unrepeated = [0] * len(pack)
    while True:
        if converged and p - done >= max_passes:
            break
        if not converged and p - done >= passes:
            break
        detail(f"ring pack, starved pass {p + 1}"
               + ("" if p == done else f" (last change {change:.2g})"))
        change = 0.0
        for n in (order[::-1] if p % 2 == 0 else order):
            met = {m: version[m] for m in sources[n]}
            if converged and p > 0 and fed[n] == met:
                continue                                  # nothing it meets has moved
            fd = feeds[n]
            lay = np.full(len(theta), -1.0)
            for m in sources[n]:
                on = fd.source == m
                lay = np.where(on, _interpolate(results[m].layer, fd, on), lay)
            # each pass starts where the ring's latest cycle ended (its film and its own layer)
            new = march(n, lay, results[n].layer, results[n].h_min[-1])
            change = max(change, pass_change(results[n], new))
            results[n], fed[n] = new, met
            most[n] = max(most[n], new.cycles)
            unrepeated[n] += int(not new.cyclic_change < tolerance)
            version[n] += 1
            layers[n] = new.supply
        p += 1
        if converged and p >= 2 and change < pass_tolerance:
            break
    return PackSolution(flooded, results, layers, p, change, change < pass_tolerance,
                        tuple(most), tuple(unrepeated))
