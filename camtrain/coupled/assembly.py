"""The shaft and every lobe's train assembled into one linear system (block diagonal: both
bending planes of :class:`camtrain.camshaft.elastic.ElasticShaft`, its twist, each lobe's lumped
train :class:`camtrain.dynamics.train.TrainModel`); the lobes' cam contacts couple them in the
march (:mod:`camtrain.coupled.march`)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Assembly", "assemble"]


@dataclass(frozen=True)
class Assembly:
    """The assembled march: matrices (M, K, C, f0) and the state indices of every lobe's shaft
    coordinates (ix, iy, iphi), follower (ifol), seat (ival) and valve, the block boundaries
    and the drive station's bending coordinates (hub_x, hub_y; -1 at a rigid support)."""

    M: np.ndarray
    K: np.ndarray
    C: np.ndarray
    f0: np.ndarray
    ix: np.ndarray
    iy: np.ndarray
    iphi: np.ndarray
    ifol: np.ndarray
    ival: np.ndarray
    valve: np.ndarray
    blocks: np.ndarray
    nb: int
    t0: int
    tr0: int
    hub_x: int
    hub_y: int


def assemble(shaft, train, n_lobes: int) -> Assembly:
    from camtrain.dynamics.train import CAM, SEAT

    beam, tors = shaft.beam, shaft.torsion
    Kb, Mb, Cb = beam.K, beam.M, beam.C
    nb = Kb.shape[0]
    Kt, Jt, Ct = tors.K, tors.J, tors.C
    ntor = Kt.shape[0]
    nt = train.size
    n = 2 * nb + ntor + n_lobes * nt
    M = np.zeros((n, n))
    K = np.zeros((n, n))
    C = np.zeros((n, n))
    for off in (0, nb):
        M[off:off + nb, off:off + nb] = Mb
        K[off:off + nb, off:off + nb] = Kb
        C[off:off + nb, off:off + nb] = Cb
    t0 = 2 * nb
    M[t0:t0 + ntor, t0:t0 + ntor] = Jt
    K[t0:t0 + ntor, t0:t0 + ntor] = Kt
    C[t0:t0 + ntor, t0:t0 + ntor] = Ct
    f0 = np.zeros(n)
    tr0 = t0 + ntor
    for j in range(n_lobes):
        s = slice(tr0 + j * nt, tr0 + (j + 1) * nt)
        M[s, s] = np.diag(train.mass)
        K[s, s] = train.stiffness
        C[s, s] = train.damping
        f0[s] = train.preload
    free_b = {int(d): i for i, d in enumerate(beam.free)}
    free_t = {int(d): i for i, d in enumerate(tors.free)}
    ix = np.array([free_b[int(beam.v_index[node])] for node in shaft.lobe_nodes])
    iphi = np.array([t0 + free_t[int(node)] for node in shaft.lobe_nodes])
    hub = free_b.get(int(beam.v_index[shaft.drive_node]), -1)
    # the linear part is block diagonal: both bending planes, the twist, each train
    blocks = np.array([0, nb, 2 * nb, tr0] + [tr0 + (j + 1) * nt for j in range(n_lobes)],
                      dtype=np.int64)
    trains = tr0 + np.arange(n_lobes) * nt
    return Assembly(M, K, C, f0, ix, ix + nb, iphi, trains + train.uni_node[CAM],
                   trains + train.uni_node[SEAT], trains + train.valve, blocks, nb, t0, tr0,
                   int(hub), int(hub + nb) if hub >= 0 else -1)
