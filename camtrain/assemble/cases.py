"""Many cases of one valve-train deck assembled for a run over a leading case axis.

The cases of a sweep batch share the deck except for scalars the valve-train chain uses
elementwise (speed, base radius, spring, valve-side mass, lubricant, boundary coefficient,
materials, cam width, follower radius). :func:`assemble_cases` turns the cases' validated
models into a :class:`Cases`: each such scalar one number when every case shares it (the
physics then sees exactly the number a single run sees), else a (cases, 1) column that
broadcasts against the angle grid, and the pair's contact model with those columns in place of
its scalars. An effect that can run over a case axis (``run_cases`` in its module) reads its
deck data from here, adds its metrics to :attr:`Cases.metrics` and sets aside the cases a
single run would report differently (:meth:`Cases.set_aside`).
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field


def _field(section: str, name: str):
    """Getter of ``model.<section>.<name>``; None when the deck has no such section."""
    def get(model):
        part = getattr(model, section)
        return None if part is None else getattr(part, name)
    return get


#: scalars read from every case's model: name -> getter of the validated model (SI units; None
#: where the deck lacks the section, and then no planned effect reads it)
SCALARS = {
    "omega": _field("speed", "omega"),
    "base_radius": _field("cam", "base_radius"),
    "width": _field("cam", "width"),
    "rate": _field("spring", "rate"),
    "preload_compression": _field("spring", "preload_compression"),
    "valve_mass": _field("masses", "valve_side"),
    "viscosity": _field("lubricant", "viscosity"),
    "pressure_viscosity": _field("lubricant", "pressure_viscosity"),
    "roughness": _field("lubricant", "roughness"),
    "boundary_friction": _field("tribology", "boundary_friction"),
    "follower_radius": _field("mechanism", "follower_radius"),
}

#: swept deck fields that only move the scalars above (deck paths); a sweep of anything else
#: assembles each case on its own
CASE_PATHS = frozenset({
    "speed.camshaft", "speed.engine", "cam.base_radius", "cam.width", "spring.rate",
    "spring.preload_compression", "masses.valve_side", "lubricant.viscosity",
    "lubricant.pressure_viscosity", "lubricant.roughness", "lubricant.temperature",
    "tribology.boundary_friction", "materials.cam_modulus", "materials.cam_poisson",
    "materials.follower_modulus", "materials.follower_poisson", "mechanism.follower_radius"})


@dataclass
class Cases:
    """``n`` cases of the ``datum`` deck: its per-case ``scalars`` (:data:`SCALARS` and the
    reduced modulus), the main pair's ``contact`` model with them, the metrics the effects
    added (:class:`camtrain.metric_rows.CaseMetric`, in plan order) and which cases the run
    over the case axis reports (``usable``; the others run alone)."""

    datum: object
    n: int
    scalars: dict
    contact: object
    metrics: list = field(default_factory=list)
    usable: object = None

    def __post_init__(self):
        import numpy as np

        if self.usable is None:
            self.usable = np.ones(self.n, dtype=bool)

    def add_metrics(self, rows) -> None:
        self.metrics.extend(rows)

    def set_aside(self, mask) -> None:
        """Cases (a bool per case) that must run alone: a geometry error, no convergence, a
        finding a single run reports as a warning."""
        import numpy as np

        self.usable = self.usable & ~np.asarray(mask, dtype=bool)


def columns(models: list) -> dict[str, object]:
    """Each scalar of the chain over the cases: a plain float when all cases share it, else a
    (cases, 1) column."""
    import numpy as np

    from camtrain.contact.model import modulus

    getters = dict(SCALARS, reduced_modulus=modulus)
    out: dict[str, object] = {}
    for name, get in getters.items():
        values = [get(m) for m in models]
        first = values[0]
        if all(v == first for v in values):
            out[name] = first
        else:
            out[name] = np.array(values, dtype=float)[:, None]
    return out


def contact_of(datum, scal: dict):
    """The datum's contact model with the per-case columns in place of its scalars."""
    from camtrain.contact.model import CamContact

    base = CamContact.from_deck(datum)
    # every case scalar is set, also one the cases share: it may differ from the datum's
    lub = dataclasses.replace(base.lubricant) if base.lubricant is not None else None
    for name in ("viscosity", "pressure_viscosity", "roughness"):
        if lub is not None:
            object.__setattr__(lub, name, scal[name])
    trib = dataclasses.replace(base.tribology)
    object.__setattr__(trib, "boundary_friction", scal["boundary_friction"])
    return dataclasses.replace(base, reduced_modulus=scal["reduced_modulus"],
                               width=scal["width"], lubricant=lub, tribology=trib)


def assemble_cases(datum, models: list) -> Cases:
    """The cases whose validated models are ``models`` (the ``datum`` with swept scalars
    replaced) as one :class:`Cases`."""
    scal = columns(models)
    return Cases(datum, len(models), scal, contact_of(datum, scal))
