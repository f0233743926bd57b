"""The elastic valve train as lumped masses on a line: assembly of M, C, K and the unilateral
contacts (Teodorescu et al. 2005 §2.5, eq. 16; rocker equivalent mass eqs A1-A3).

Every coordinate is referred to the valve (positive = valve opening): a mass m or stiffness k
that moves ``r`` times slower than the valve counts as m / r^2 or k / r^2. The nodes are, from
the cam: the follower node (tappet, push rod, half the rocker; absent when its mass is zero), the
valve node (valve, retainer, collets, the other half of the rocker and a third of the spring,
or the retainer end of the spring chain), and the interior nodes of the spring chain (surge).

Elements between nodes are linear springs with viscous dampers in parallel; elements in series
without a mass between them are combined by the series rule (Teodorescu eq. 16 text,
``series``). Two elements are unilateral: the cam contact (gap ``b(t) - u_follower - lash``,
``b`` the cam displacement referred to the valve) and the valve seat (the preloaded valve rests
on it at u = 0). A unilateral force is ``k delta + c delta'`` while ``psi = min(k delta,
k delta + c delta') > 0`` and zero otherwise, so a separating damper never pulls (the standard
guard of the reference notes, A-M2).

The model is plain data (``TrainModel``): a flexible camshaft can assemble several trains into
one system by stacking their matrices and driving each cam contact's input ``b(t)`` with its own
base motion (``UnilateralSet.node``/``offset`` say where each contact acts).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

__all__ = ["Element", "TrainModel", "series", "rocker_equivalent_mass", "damping_from_ratio",
           "surge_chain", "surge_frequency", "surge_frequency_discrete", "chain_end_mass",
           "CAM", "SEAT"]

CAM, SEAT = 0, 1


def series(*stiffnesses: float) -> float:
    """Stiffness of springs in series, 1/k = sum 1/k_i (Teodorescu 2005 eq. 16 text:
    k_e = k_i k_(i+1) / (k_i + k_(i+1))); infinite entries (rigid links) drop out."""
    finite = [k for k in stiffnesses if math.isfinite(k)]
    if not finite:
        return math.inf
    return 1.0 / sum(1.0 / k for k in finite)


def rocker_equivalent_mass(inertia: float, valve_arm: float) -> float:
    """Equivalent mass of a rocker at the valve, m_R = I_R / r^2 (Teodorescu 2005 eqs A1-A3;
    valid for rocker swings below about 12 deg, where 1/cos^2 stays within 4.5 % of 1)."""
    return inertia / (valve_arm * valve_arm)


def damping_from_ratio(ratio: float, stiffness: float, mass: float) -> float:
    """Viscous coefficient c = 2 zeta sqrt(k m) of an element of stiffness k on mass m."""
    return 2.0 * ratio * math.sqrt(stiffness * mass)


@dataclass(frozen=True)
class Element:
    """A named spring (and damper) of the train, for the printed series rule and the stability
    guard: ``k`` [N/m] and ``mass`` [kg] the (reduced) mass it acts on (its local frequency
    sqrt(k/mass))."""

    name: str
    k: float
    mass: float

    @property
    def omega(self) -> float:
        return math.sqrt(self.k / self.mass) if self.mass > 0 else math.inf


@dataclass(frozen=True)
class TrainModel:
    """Linear part M u'' + C u' + K u = f0 plus two unilateral contacts (cam, seat).

    ``mass`` [kg] (lumped, diagonal), ``stiffness`` [N/m] and ``damping`` [N s/m] n x n,
    ``preload`` the constant force vector [N] (the spring preload on the valve node, negative).
    Unilateral contact j acts on node ``uni_node[j]`` in +u with ``delta = b_j(t) - u + offset_j``
    (``b`` the cam input for the cam, 0 for the seat), stiffness ``uni_k`` and damping ``uni_c``.
    ``follower``/``valve`` are the node indices; ``elements`` the named springs; ``chain`` the
    nodes of the spring chain (retainer end first, excluding the valve node).
    """

    mass: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    preload: np.ndarray
    uni_node: np.ndarray
    uni_k: np.ndarray
    uni_c: np.ndarray
    uni_offset: np.ndarray
    follower: int
    valve: int
    elements: tuple[Element, ...]
    spring_rate: float
    spring_preload: float
    chain: tuple[int, ...] = ()
    #: the cam contact's own load-deflection law (a Hertz line contact) or None: linear, uni_k.
    #: With a law, uni_k[CAM] is its largest tangent stiffness over the cycle (for the step, the
    #: stability guard and the printed elements).
    cam_law: object = None
    #: a series element with a state of its own marched with the train, between the follower
    #: node and a node of its own (the hydraulic lash adjuster,
    #: :class:`camtrain.dynamics.hla.placement.SeriesAdjuster`), or None. The train asks it
    #: for ``node`` (its own node), ``stiffness()`` [N/m] (valve-referred, at rest: a spring
    #: of the closed matrices) and ``rest_force()`` [N] (valve-referred, pushing the follower
    #: and its node apart at rest beyond the train's springs and preloads)
    series: object = None
    #: a roller turning on its pin, its spin marched with the train
    #: (:class:`camtrain.dynamics.spin.RollerTables`); None: no roller, or one solved after
    #: the march by the roller effect
    roller: object = None

    @property
    def size(self) -> int:
        return int(self.mass.size)

    def closed_matrices(self) -> tuple[np.ndarray, np.ndarray]:
        """K and C with both unilateral contacts closed."""
        k, c = self.stiffness.copy(), self.damping.copy()
        for j in range(self.uni_node.size):
            i = self.uni_node[j]
            k[i, i] += self.uni_k[j]
            c[i, i] += self.uni_c[j]
        if self.series is not None:   # a series element as its spring at rest
            _add_link(k, np.zeros_like(c), self.follower, self.series.node,
                      self.series.stiffness(), 0.0)
        return k, c

    def omega_max(self) -> float:
        """Largest natural frequency [rad/s] with every contact closed (undamped)."""
        k, _ = self.closed_matrices()
        s = 1.0 / np.sqrt(self.mass)
        return float(np.sqrt(np.max(np.linalg.eigvalsh(k * s[:, None] * s[None, :]))))

    def stiffest(self) -> Element:
        """The element with the highest local frequency (what limits an explicit step)."""
        return max(self.elements, key=lambda e: e.omega)

    def total_mass(self) -> float:
        """Sum of the node masses [kg] (the rigid train's valve-referred mass, with the whole
        spring chain mass counted where present)."""
        return float(self.mass.sum())

    def spring_force_at_head(self, u: np.ndarray) -> np.ndarray:
        """Spring force on the cylinder head [N] per sample (u: n x samples)."""
        if not self.chain:
            return self.spring_preload + self.spring_rate * u[self.valve]
        n = len(self.chain) + 1
        return self.spring_preload + n * self.spring_rate * u[self.chain[-1]]

    def spring_force_at_retainer(self, u: np.ndarray) -> np.ndarray:
        """Spring force on the retainer [N] per sample."""
        if not self.chain:
            return self.spring_force_at_head(u)
        n = len(self.chain) + 1
        return self.spring_preload + n * self.spring_rate * (u[self.valve] - u[self.chain[0]])


# --------------------------------------------------------------------------- spring surge

def surge_frequency(rate: float, mass: float) -> float:
    """First surge frequency [Hz] of a spring held at both ends, f1 = 1/2 sqrt(k/m_s) (the
    fixed-fixed uniform rod; e.g. 518.5 Hz for the Zeta spring, 37 634 N/m and 0.035 kg)."""
    return 0.5 * math.sqrt(rate / mass)


def surge_frequency_discrete(rate: float, mass: float, elements: int) -> float:
    """First fixed-fixed mode [Hz] of the N-element chain with the end half-masses lumped as in
    ``surge_chain``: (2N/pi) sin(pi/(2N)) f1 (exact for the lumped chain, -0.64 % at N = 8)."""
    n = elements
    return surge_frequency(rate, mass) * (2.0 * n / math.pi) * math.sin(math.pi / (2.0 * n))


def chain_end_mass(mass: float, elements: int) -> float:
    """Equivalent end mass [kg] of the lumped chain for a linear (quasi-static) mode shape:
    sum_i (i/N)^2 m_s/N over the interior nodes + m_s/(2N) at the moving end; -> m_s/3 as N^-2."""
    n = elements
    i = np.arange(1, n)
    return float(mass / n * np.sum((i / n) ** 2) + mass / (2.0 * n))


def surge_chain(rate: float, mass: float, elements: int, damping_ratio: float):
    """Interior masses, element stiffness and element damping of an N-element spring chain.

    N elements of stiffness N k; interior nodes m_s/N; the moving (retainer) end carries
    m_s/(2N) and the fixed end's half mass goes to the head (reference notes A-M3: both the
    surge frequency and the 1/3 rule converge as N^-2). Damping is stiffness-proportional,
    c = beta k with beta = 2 zeta / omega_1 (modal ratio zeta in the first surge mode).
    Returns (interior masses, element k, element c, retainer-end mass).
    """
    n = elements
    k_el = n * rate
    omega1 = 2.0 * math.pi * surge_frequency_discrete(rate, mass, n)
    c_el = 2.0 * damping_ratio / omega1 * k_el
    return np.full(n - 1, mass / n), k_el, c_el, mass / (2.0 * n)


# --------------------------------------------------------------------------- assembly

def _add_link(k, c, i, j, kk, cc):
    """Spring-damper between nodes i and j (j = -1: ground)."""
    for mat, v in ((k, kk), (c, cc)):
        mat[i, i] += v
        if j >= 0:
            mat[j, j] += v
            mat[i, j] -= v
            mat[j, i] -= v


def _given_damping(damping) -> dict[str, float]:
    """The viscous coefficients given as values, by element (contact, link, seat, spring)."""
    given = dict(damping or {})
    unknown = set(given) - {"contact", "link", "seat", "spring"}
    if unknown:
        raise ValueError(f"unknown damping element(s) {sorted(unknown)}")
    return given


def _spring_chain(k, c, elements, valve, chain, element):
    """The valve spring as a chain of ``element`` = (stiffness, damping, spring mass, count)
    links from the valve node through the ``chain`` nodes to ground."""
    k_el, c_el, spring_mass, count = element
    order = (valve,) + chain
    for a, b in zip(order, order[1:] + (-1,), strict=True):
        _add_link(k, c, a, b, k_el, c_el)
    elements.append(Element(f"valve spring element (1/{count} of the spring)", k_el,
                            spring_mass / count / 2.0))


def _adjuster_squeeze(adjuster_load: float, cam_law, cam_k: float) -> float:
    """The cam contact's compression at rest under a lash adjuster's load (0 without): the
    adjuster takes up the slack, no link is strained, every node sits at u = 0."""
    if not adjuster_load:
        return 0.0
    return cam_law.at_rest(adjuster_load) if cam_law is not None else adjuster_load / cam_k


def _preload(n: int, follower, valve: int, spring_preload: float, adjuster_load: float):
    """The constant forces: the spring's preload on the valve node; a lash adjuster's load
    pushes the follower node (None: there is none) onto the cam and the valve off its seat."""
    preload = np.zeros(n)
    preload[valve] = -spring_preload
    if adjuster_load:
        if follower is None:
            raise ValueError("a lash adjuster load needs a follower mass (a follower node)")
        preload[follower] -= adjuster_load
        preload[valve] += adjuster_load
    return preload


def assemble_train(*, valve_mass: float, contact_stiffness: float, seat_stiffness: float,
                   spring_rate: float, spring_preload: float, follower_mass: float = 0.0,
                   follower_stiffness: float = math.inf,
                   links: dict[str, float] | None = None, lash: float = 0.0,
                   damping_ratio: float = 0.05, seat_damping_ratio: float | None = None,
                   spring_mass: float = 0.0, spring_elements: int = 0,
                   spring_damping_ratio: float = 0.02,
                   adjuster_load: float = 0.0,
                   damping: dict[str, float] | None = None,
                   cam_law=None) -> TrainModel:
    """Build the lumped train (all values referred to the valve, SI).

    ``links``: named stiffnesses between the follower and the valve node (push rod, rocker,
    stem; combined by the series rule). Without a follower mass the follower node is the valve
    node and the cam contact, the follower stiffness and the links are one series spring.
    ``valve_mass`` is the valve node's mass *without* the spring chain's end mass (that is added
    here when ``spring_elements`` > 0). Damping ratios set c = 2 zeta sqrt(k m) with m the node
    mass (contact, seat, single-rate spring) or the reduced mass of the two nodes (links).
    ``adjuster_load``: a hydraulic lash adjuster between follower and valve pushes them apart
    with a constant force (the follower onto the cam, the valve off its seat: the seat carries
    the spring preload less the adjuster's load); it needs a follower node.
    ``damping``: viscous coefficients [N s/m] given as values, which replace the ratios:
    ``contact`` (cam contact, with the series train when there is no follower node), ``link``
    (follower-valve link), ``seat``, ``spring`` (single rate: on the valve node; chain: the
    whole spring's end-to-end coefficient, each of the N elements N times it).
    ``cam_law``: a :class:`~camtrain.dynamics.contact_law.HertzLineLaw` makes the cam contact
    nonlinear; ``contact_stiffness`` is then its largest tangent stiffness (for the step and the
    damping ratio), and the law gets the series springs (follower, and links without a follower
    node) as its ``k_series``.
    """
    links = dict(links or {})
    given = _given_damping(damping)
    has_follower = follower_mass > 0.0
    nodes = 2 if has_follower else 1
    interior = np.zeros(0)
    end_mass = 0.0
    if spring_elements > 0:
        interior, k_el, c_el, end_mass = surge_chain(spring_rate, spring_mass, spring_elements,
                                                     spring_damping_ratio)
        if "spring" in given:
            c_el = spring_elements * given["spring"]
    n = nodes + interior.size
    mass = np.zeros(n)
    follower, valve = 0, nodes - 1
    mass[valve] = valve_mass + end_mass
    if has_follower:
        mass[follower] = follower_mass
    mass[nodes:] = interior
    k = np.zeros((n, n))
    c = np.zeros((n, n))
    elements = []
    link_k = series(*links.values()) if links else math.inf
    if has_follower:
        in_series = series(follower_stiffness)
        cam_k = series(contact_stiffness, follower_stiffness)
        if math.isfinite(link_k):
            m_red = mass[0] * mass[1] / (mass[0] + mass[1])
            _add_link(k, c, 0, 1, link_k, given.get(
                "link", damping_from_ratio(damping_ratio, link_k, m_red)))
            elements.append(Element("follower-valve link (" + " + ".join(links) + ")", link_k,
                                    m_red))
        else:
            raise ValueError("a follower mass needs a stiffness between follower and valve")
    else:
        in_series = series(follower_stiffness, link_k)
        cam_k = series(contact_stiffness, follower_stiffness, link_k)
    name = "cam contact"
    if cam_law is not None:
        cam_law = replace(cam_law, k_series=in_series)
        name += " (Hertz line, largest tangent)"
    if not has_follower:
        name += " (in series with the train)"
    elements.insert(0, Element(name, cam_k, mass[follower]))
    chain: tuple[int, ...] = ()
    if spring_elements > 0:
        chain = tuple(range(nodes, n))
        _spring_chain(k, c, elements, valve, chain, (k_el, c_el, spring_mass, spring_elements))
    else:
        _add_link(k, c, valve, -1, spring_rate, given.get(
            "spring", damping_from_ratio(spring_damping_ratio, spring_rate, mass[valve])))
        elements.append(Element("valve spring", spring_rate, mass[valve]))
    elements.append(Element("valve seat", seat_stiffness, mass[valve]))
    preload = _preload(n, follower if has_follower else None, valve, spring_preload,
                       adjuster_load)
    seat_load = spring_preload - (adjuster_load if has_follower else 0.0)
    zs = damping_ratio if seat_damping_ratio is None else seat_damping_ratio
    uni_node = np.array([follower, valve], dtype=np.int64)
    uni_k = np.array([cam_k, seat_stiffness])
    uni_c = np.array([given.get("contact", damping_from_ratio(damping_ratio, cam_k,
                                                              mass[follower])),
                      given.get("seat", damping_from_ratio(zs, seat_stiffness, mass[valve]))])
    squeeze = _adjuster_squeeze(adjuster_load if has_follower else 0.0, cam_law, cam_k)
    uni_offset = np.array([-lash + squeeze, seat_load / seat_stiffness])
    return TrainModel(mass=mass, stiffness=k, damping=c, preload=preload, uni_node=uni_node,
                      uni_k=uni_k, uni_c=uni_c, uni_offset=uni_offset, follower=follower,
                      valve=valve, elements=tuple(elements), spring_rate=spring_rate,
                      spring_preload=spring_preload, chain=chain, cam_law=cam_law)


def static_state(model: TrainModel) -> tuple[np.ndarray, np.ndarray]:
    """Displacements [m] and contact states at rest on the base circle (cam input 0).

    The seat's offset is set so that the valve rests at u = 0 carrying the spring preload (less
    an adjuster's load); the cam contact is closed when an adjuster pushes the follower onto
    the cam (the follower then sits at -F_h / k_c), open otherwise (L7: every element carries
    the preload it must, to round-off).
    """
    act = np.array([False, True])
    for cam_closed in (True, False):
        act[CAM] = cam_closed
        k = model.stiffness.copy()
        rhs = model.preload.copy()
        if model.series is not None:   # a series element's force at rest pushes them apart
            rhs[model.follower] -= model.series.rest_force()
            rhs[model.series.node] += model.series.rest_force()
        uni_k = model.uni_k.copy()
        off = model.uni_offset[CAM]
        if model.cam_law is not None and off > 0.0:
            # the secant of the nonlinear contact at its rest compression: u = 0 exactly
            uni_k[CAM] = model.cam_law.force(off, model.cam_law.base_radius,
                                             model.cam_law.base_ratio) / off
        for j in range(2):
            if act[j]:
                i = model.uni_node[j]
                k[i, i] += uni_k[j]
                rhs[i] += uni_k[j] * model.uni_offset[j]
        u = np.linalg.solve(k, rhs)
        cam_force = uni_k[CAM] * (-u[model.follower] + model.uni_offset[CAM])
        if (cam_force > 0.0) == cam_closed:
            return u, act.copy()
    return u, act.copy()
