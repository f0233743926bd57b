"""The adjuster placed in the lumped train: a plunger node between the follower (its body) and
the links to the valve (:func:`with_lash_adjuster`), the train's series element it is there
(:class:`SeriesAdjuster`), the march's record and chamber of it (:func:`march_record`), and the
constant-load adjuster it replaces (:func:`rigid_adjuster`, the reference of the lift loss)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.dynamics.hla.element import LashAdjuster


@dataclass(frozen=True)
class SeriesAdjuster:
    """The adjuster as the train's series element (``TrainModel.series``): ``adjuster``
    between the follower node (its body) and node ``node`` (its plunger), the plunger moving
    ``ratio`` times the valve-referred motion."""

    adjuster: LashAdjuster
    node: int
    ratio: float = 1.0

    def rest_force(self) -> float:
        """The chamber's valve-referred force on the base circle [N]: at the supply pressure
        (the plunger spring is in the train's stiffness and preload)."""
        return self.ratio * self.adjuster.supply_pressure * self.adjuster.area

    def stiffness(self) -> float:
        """The closed chamber's valve-referred stiffness at rest [N/m]."""
        return self.ratio ** 2 * self.adjuster.stiffness()


def with_element(model, adj: LashAdjuster):
    """The train ``model`` (with an adjuster placed) with the adjuster's element ``adj``
    instead (same plunger node and ratio: other oil, chamber or valve data)."""
    from dataclasses import replace

    return replace(model, series=replace(model.series, adjuster=adj))


def march_record(model, u0):
    """The march's adjuster record of ``model`` (a ``records.Hydraulic``; ``no_adjuster``
    without one) and its chamber at rest (the supply pressure, no flow), ``u0`` the train's
    displacements at rest."""
    from camtrain.dynamics.hla.chamber import chamber_start, hydraulic_record, no_adjuster
    from camtrain.dynamics.records import HP_SIZE

    if model.series is None:
        return no_adjuster(), np.zeros(HP_SIZE)
    s = model.series
    w0 = float(u0[model.follower] - u0[s.node])
    record = hydraulic_record(s.adjuster, model.follower, s.node, s.ratio, w0)
    return record, chamber_start(record, s.adjuster.supply_pressure)


def chamber_from(hp, rows, i: int) -> None:
    """A chamber state ``hp`` (records.HP_SLOTS) started from the sampled rows (records.H_ROWS)
    of a periodic response at sample i: its pressure, flows and ball lift; no rate guess, no
    volumes yet, the ball at rest."""
    hp[:] = 0.0
    hp[:3] = rows[:3, i]
    hp[6] = rows[6, i]


def with_lash_adjuster(model, adj: LashAdjuster, ratio: float = 1.0):
    """The train ``model`` (a :class:`camtrain.dynamics.train.TrainModel` with a follower node,
    built without a constant adjuster load) with ``adj`` between its follower node (the body)
    and a new plunger node: the follower-valve link (its stiffness and damping) is moved to run
    from the plunger to the valve, the plunger's mass (m ratio^2) and spring (k ratio^2, its
    preload ratio F_0) join, and the base circle carries the adjuster's rest force (the chamber
    at the supply pressure plus the spring) on the cam contact and off the seat, as
    ``assemble_train``'s constant adjuster load did."""
    from dataclasses import replace

    from camtrain.dynamics.train import CAM, SEAT, Element

    f, v = model.follower, model.valve
    if f == v:
        raise ValueError("a hydraulic lash adjuster needs a follower mass (a follower node)")
    n = model.size
    q = n
    k = np.zeros((n + 1, n + 1))
    c = np.zeros((n + 1, n + 1))
    k[:n, :n], c[:n, :n] = model.stiffness, model.damping
    k_link, c_link = -k[f, v], -c[f, v]
    for mat, val in ((k, k_link), (c, c_link)):
        mat[f, f] -= val
        mat[f, v] = mat[v, f] = 0.0
        mat[q, q] += val
        mat[q, v] = mat[v, q] = -val
    k_s = adj.spring_rate * ratio ** 2
    k[f, f] += k_s
    k[q, q] += k_s
    k[f, q] = k[q, f] = -k_s
    preload = np.append(model.preload, ratio * adj.spring_preload)
    preload[f] -= ratio * adj.spring_preload
    rest = ratio * adj.rest_force()
    off = model.uni_offset.copy()
    off[CAM] += rest / model.uni_k[CAM]
    off[SEAT] -= rest / model.uni_k[SEAT]
    mass = np.append(model.mass, adj.plunger_mass * ratio ** 2)
    elements = model.elements + (
        Element("hydraulic lash adjuster chamber (closed, at rest)",
                ratio ** 2 * adj.stiffness(), float(mass[q])),)
    placed = replace(model, mass=mass, stiffness=k, damping=c, preload=preload,
                     uni_offset=off, elements=elements, series=SeriesAdjuster(adj, q, ratio))
    return _spring_at_rest(placed, k_s, q)


def _spring_at_rest(model, k_s: float, q: int):
    """The plunger spring's preload pair shifted so that the spring pushes with its preload in
    the train's state at rest (where the links' compressions move the plunger against the
    follower by w0; ``q`` the plunger's node): the rest solved without the spring's rate
    first."""
    from dataclasses import replace

    from camtrain.dynamics.train import static_state

    f = model.follower
    k = model.stiffness.copy()
    k[f, f] -= k_s
    k[q, q] -= k_s
    k[f, q] += k_s
    k[q, f] += k_s
    u0 = static_state(replace(model, stiffness=k))[0]
    w0 = float(u0[f] - u0[q])
    preload = model.preload.copy()
    preload[q] -= k_s * w0
    preload[f] += k_s * w0
    return replace(model, preload=preload)


def rigid_adjuster(model):
    """The train of ``model`` (with an adjuster from :func:`with_lash_adjuster`) with the
    constant-load adjuster instead: the plunger's mass on the follower, the link back from the
    follower to the valve, the rest force (chamber at the supply pressure plus spring) as a
    constant force pushing follower and valve apart (``assemble_train``'s ``adjuster_load``)."""
    from dataclasses import replace

    f, v, q = model.follower, model.valve, model.series.node
    n = model.size - 1
    k = model.stiffness[:n, :n].copy()
    c = model.damping[:n, :n].copy()
    k_s = -model.stiffness[f, q]
    k_link, c_link = -model.stiffness[q, v], -model.damping[q, v]
    k[f, f] += k_link - k_s
    c[f, f] += c_link
    for mat, val in ((k, k_link), (c, c_link)):
        mat[f, v] = mat[v, f] = -val
    mass = model.mass[:n].copy()
    mass[f] += model.mass[q]
    rest = model.series.ratio * model.series.adjuster.rest_force()
    preload = model.preload[:n].copy()
    preload[f] = -rest
    preload[v] += rest
    return replace(model, mass=mass, stiffness=k, damping=c, preload=preload,
                   elements=model.elements[:-1], series=None)
