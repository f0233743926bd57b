"""Elastic camshaft: stations, Euler-Bernoulli bending in two planes, and the torsion model.

Teodorescu et al. (2005) §2.6, Fig. 4: a line of cams C1..C4 between bearings B1..B5 on one shaft
that bends between its bearings and twists from its drive gear. Their shaft is lumped masses at
the cam and bearing stations; here the bending model is the standard two-node Euler-Bernoulli
beam element (transverse deflection and slope per node, Hermite cubics, consistent mass), which
converges to the continuous shaft as stations are added between the given ones, and torsion is a
chain of uniform shaft segments GJ/l with the segment inertia lumped half to each end.

Stations are the bearing positions, every force position (lobes, the drive) and ``nodes_per_span``
extra nodes in every span (the resolution knob). Bearings are springs to ground (stiffness
``inf`` = a rigid support, enforced as a constraint, not a penalty) with dashpots. Shaft damping
is stiffness-proportional, C = (2 zeta / omega_1) K, so the first free mode has damping ratio
zeta. Gyroscopic coupling of the two bending planes and shear deformation are neglected (slender
shaft at camshaft speeds; stated in docs/camshaft_dynamics.md).

Hinges (:class:`BeamShaft` ``hinges``) release the slope at a station; with a hinge at every
interior bearing and rigid supports the shaft becomes the chain of simply supported bays of the
statically determinate split (Ball 1988 §6.3, :func:`camtrain.camshaft.split_beam_loads`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camtrain.errors import field_error

__all__ = ["ShaftSection", "Stations", "BeamShaft", "TorsionShaft", "stations",
           "beam_shaft", "torsion_shaft"]


@dataclass(frozen=True)
class ShaftSection:
    """A uniform round shaft: EI [N m^2], GJ [N m^2/rad], mass per length [kg/m] and polar
    mass inertia per length [kg m]. :meth:`solid` and :meth:`hollow` build it from the diameter
    and the material (standard strength-of-materials section properties)."""

    EI: float
    GJ: float
    mass_per_length: float
    polar_inertia_per_length: float

    @classmethod
    def hollow(cls, diameter: float, bore: float = 0.0, modulus: float = 210e9,
               shear_modulus: float = 80e9, density: float = 7850.0) -> ShaftSection:
        if not (diameter > 0 and 0 <= bore < diameter):
            raise field_error("camshaft.flexibility.diameter", "need diameter > bore >= 0",
                              diameter, f"> {bore}")
        area = math.pi / 4.0 * (diameter ** 2 - bore ** 2)
        second = math.pi / 64.0 * (diameter ** 4 - bore ** 4)   # I, bending
        polar = 2.0 * second                                   # J of a round section
        return cls(modulus * second, shear_modulus * polar, density * area, density * polar)

    @classmethod
    def solid(cls, diameter: float, **material) -> ShaftSection:
        return cls.hollow(diameter, 0.0, **material)


@dataclass(frozen=True)
class Stations:
    """Sorted axial node positions [m] and where the bearings and the forces sit on them."""

    positions: np.ndarray
    bearing_nodes: np.ndarray
    force_nodes: np.ndarray


def stations(bearing_positions, force_positions, nodes_per_span: int = 0,
             merge: float = 1e-9) -> Stations:
    """Nodes at every bearing and force position, plus ``nodes_per_span`` evenly spaced nodes in
    every interval between neighbouring ones. Positions closer than ``merge`` [m] share a node."""
    zb = np.asarray(bearing_positions, dtype=float).ravel()
    zf = np.asarray(force_positions, dtype=float).ravel()
    if zb.size < 1 or not np.all(np.isfinite(zb)) or np.any(np.diff(zb) <= 0):
        raise field_error("camshaft.bearings.position", "must be finite and strictly increasing",
                          zb.tolist())
    if not np.all(np.isfinite(zf)):
        raise field_error("camshaft.lobes.position", "must be finite", zf.tolist())
    if int(nodes_per_span) < 0:
        raise field_error("camshaft.flexibility.nodes_per_span", "must be >= 0", nodes_per_span)
    base = np.sort(np.concatenate([zb, zf]))
    keep = np.concatenate([[True], np.diff(base) > merge])
    base = base[keep]
    if base.size < 2:
        raise field_error("camshaft.bearings", "the shaft needs at least two distinct stations",
                          base.tolist())
    extra = int(nodes_per_span)
    pts = [base[:1]]
    for a, b in zip(base[:-1], base[1:], strict=True):
        pts.append(a + (b - a) * np.arange(1, extra + 2) / (extra + 1))
    z = np.concatenate(pts)

    def where(v):
        i = np.abs(z[:, None] - v[None, :]).argmin(axis=0)
        return i

    return Stations(z, where(zb), where(zf))


@dataclass(frozen=True)
class BeamShaft:
    """Assembled bending model of one plane (the other plane is the same shaft).

    ``K``, ``M``, ``C`` act on the free degrees of freedom (transverse deflection v and slope
    per node, slopes split at hinges); ``v_index[i]`` is node i's deflection DOF in the full
    numbering and ``free`` the full indices that are not constrained (rigid bearings, clamped
    overhang slopes). Bearing springs and dashpots are inside K and C; ``bearing_k``/``_c`` keep
    them for the reactions.
    """

    stations: Stations
    K_full: np.ndarray
    M_full: np.ndarray
    C_full: np.ndarray
    v_index: np.ndarray
    free: np.ndarray
    fixed: np.ndarray
    bearing_k: np.ndarray
    bearing_c: np.ndarray

    @property
    def K(self):
        return self.K_full[np.ix_(self.free, self.free)]

    @property
    def M(self):
        return self.M_full[np.ix_(self.free, self.free)]

    @property
    def C(self):
        return self.C_full[np.ix_(self.free, self.free)]

    def natural_frequencies(self, count: int | None = None) -> np.ndarray:
        """Undamped natural frequencies [rad/s] of the bending model, ascending (the lowest
        ``count`` only, when given)."""
        from scipy.linalg import eigh

        subset = None if count is None else [0, min(count, self.K.shape[0]) - 1]
        lam = eigh(self.K, self.M, eigvals_only=True, subset_by_index=subset)
        return np.sqrt(np.clip(lam, 0.0, None))


def _element(EI, m, length):
    """Euler-Bernoulli element stiffness and consistent mass (v1, t1, v2, t2)."""
    L = length
    k = EI / L ** 3 * np.array([[12, 6 * L, -12, 6 * L], [6 * L, 4 * L * L, -6 * L, 2 * L * L],
                                [-12, -6 * L, 12, -6 * L], [6 * L, 2 * L * L, -6 * L, 4 * L * L]])
    mm = m * L / 420.0 * np.array([[156, 22 * L, 54, -13 * L], [22 * L, 4 * L * L, 13 * L, -3 * L * L],
                                   [54, 13 * L, 156, -22 * L], [-13 * L, -3 * L * L, -22 * L, 4 * L * L]])
    return k, mm


def _bearing_values(name, value, n):
    arr = np.broadcast_to(np.asarray(value, dtype=float), (n,)).copy()
    if np.any(np.isnan(arr)) or np.any(arr < 0):
        raise field_error(f"camshaft.flexibility.{name}", "must be >= 0 (inf = rigid)",
                          arr.tolist())
    return arr


def beam_shaft(st: Stations, section: ShaftSection, bearing_stiffness, bearing_damping=0.0,
               damping_ratio: float = 0.0, point_masses=None, hinges=(), clamp_overhang=False
               ) -> BeamShaft:
    """Assemble the bending model of one plane.

    Args:
        st: stations (:func:`stations`).
        section: shaft section properties.
        bearing_stiffness: per bearing or one value [N/m]; ``inf`` = rigid support.
        bearing_damping: per bearing or one value [N s/m].
        damping_ratio: of the first free bending mode (stiffness-proportional shaft damping).
        point_masses: extra mass per node [kg] (lobes, the drive gear), shape (n_nodes,).
        hinges: node indices where the slope is released (a pin joint in the shaft).
        clamp_overhang: the slope of the shaft beyond each end bearing is held (the overhang
            is cantilevered from a clamped support) - the ``nearest`` overhang rule of the
            determinate split; use with hinges at both end bearings.
    """
    z = st.positions
    n = z.size
    nb = st.bearing_nodes.size
    kb = _bearing_values("bearing_stiffness", bearing_stiffness, nb)
    cb = _bearing_values("bearing_damping", bearing_damping, nb)
    hinge = set(int(h) for h in hinges)
    # DOF numbering: v_i, then slope(s); at a hinge the left and right elements get their own
    v_idx = np.zeros(n, dtype=int)
    left_t = np.zeros(n, dtype=int)   # slope DOF used by the element to the left of node i
    right_t = np.zeros(n, dtype=int)  # ... and to the right
    d = 0
    for i in range(n):
        v_idx[i] = d
        left_t[i] = d + 1
        right_t[i] = d + 2 if i in hinge else d + 1
        d += 3 if i in hinge else 2
    K = np.zeros((d, d))
    M = np.zeros((d, d))
    for e in range(n - 1):
        ke, me = _element(section.EI, section.mass_per_length, z[e + 1] - z[e])
        dofs = [v_idx[e], right_t[e], v_idx[e + 1], left_t[e + 1]]
        K[np.ix_(dofs, dofs)] += ke
        M[np.ix_(dofs, dofs)] += me
    if point_masses is not None:
        pm = np.asarray(point_masses, dtype=float)
        M[v_idx, v_idx] += pm
    Cs = np.zeros_like(K)
    fixed = []
    Kb = np.zeros_like(K)
    for j, node in enumerate(st.bearing_nodes):
        if math.isinf(kb[j]):
            fixed.append(v_idx[node])
        else:
            Kb[v_idx[node], v_idx[node]] += kb[j]
            Cs[v_idx[node], v_idx[node]] += cb[j]
    if clamp_overhang:
        b0, b1 = st.bearing_nodes[0], st.bearing_nodes[-1]
        if b0 > 0:
            fixed.append(left_t[b0])
        if b1 < n - 1:
            fixed.append(right_t[b1])
    # a slope DOF no element uses (hinge at a shaft end) is fixed to keep K regular
    used = np.zeros(d, dtype=bool)
    used[v_idx] = True
    used[right_t[:-1]] = True
    used[left_t[1:]] = True
    fixed.extend(np.flatnonzero(~used).tolist())
    fixed = np.array(sorted(set(int(f) for f in fixed)), dtype=int)
    free = np.setdiff1d(np.arange(d), fixed)
    shaft = BeamShaft(st, K + Kb, M, Cs, v_idx, free, fixed, kb, cb)
    if damping_ratio > 0:
        w1 = shaft.natural_frequencies(1)[0]
        Cs = Cs + (2.0 * damping_ratio / w1) * K
        shaft = BeamShaft(st, K + Kb, M, Cs, v_idx, free, fixed, kb, cb)
    return shaft


@dataclass(frozen=True)
class TorsionShaft:
    """Torsion model: twist phi_i = psi_i - psi_drive, psi_drive the prescribed drive angle.

    ``K``, ``J``, ``C`` act on the free nodes ``free`` (all nodes but ``drive_node`` when the
    drive is rigid; all nodes when the drive node sits on the drive's torsional spring)."""

    stations: Stations
    K: np.ndarray
    J: np.ndarray
    C: np.ndarray
    free: np.ndarray
    drive_node: int

    def natural_frequencies(self) -> np.ndarray:
        from scipy.linalg import eigh

        return np.sqrt(np.clip(eigh(self.K, self.J, eigvals_only=True), 0.0, None))


def torsion_shaft(st: Stations, section: ShaftSection, drive_node: int,
                  point_inertias=None, damping_ratio: float = 0.0,
                  drive_stiffness: float = math.inf) -> TorsionShaft:
    """Chain of shaft segments GJ/l between nodes, segment inertia lumped half to each end,
    plus ``point_inertias`` [kg m^2] per node (lobes, gear). The drive turns the drive node:
    rigidly (``drive_stiffness`` inf, Teodorescu's held gear) or through a torsional spring
    [N m/rad] (a belt or chain), whose far end follows the prescribed drive angle."""
    z = st.positions
    n = z.size
    K = np.zeros((n, n))
    J = np.zeros(n)
    for e in range(n - 1):
        ell = z[e + 1] - z[e]
        k = section.GJ / ell
        K[e:e + 2, e:e + 2] += k * np.array([[1.0, -1.0], [-1.0, 1.0]])
        J[e:e + 2] += 0.5 * section.polar_inertia_per_length * ell
    if point_inertias is not None:
        J = J + np.asarray(point_inertias, dtype=float)
    if math.isinf(drive_stiffness):
        free = np.setdiff1d(np.arange(n), [int(drive_node)])
    else:
        if not drive_stiffness > 0:
            raise field_error("camshaft.flexibility.drive_stiffness", "must be > 0 (inf = rigid)",
                              drive_stiffness)
        free = np.arange(n)
        K[drive_node, drive_node] += drive_stiffness
    Kf = K[np.ix_(free, free)]
    Jf = np.diag(J[free])
    shaft = TorsionShaft(st, Kf, Jf, np.zeros_like(Kf), free, int(drive_node))
    if damping_ratio > 0:
        w1 = shaft.natural_frequencies()[0]
        shaft = TorsionShaft(st, Kf, Jf, (2.0 * damping_ratio / w1) * Kf, free, int(drive_node))
    return shaft
