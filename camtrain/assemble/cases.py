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
import operator
from dataclasses import dataclass, field

#: scalars read from every case's model: name -> (section, field) of the validated model (SI
#: units; None where the deck lacks the section, and then no planned effect reads it)
SCALARS = {
    "omega": ("speed", "omega"),
    "base_radius": ("cam", "base_radius"),
    "width": ("cam", "width"),
    "rate": ("spring", "rate"),
    "preload_compression": ("spring", "preload_compression"),
    "valve_mass": ("masses", "valve_side"),
    "viscosity": ("lubricant", "viscosity"),
    "pressure_viscosity": ("lubricant", "pressure_viscosity"),
    "roughness": ("lubricant", "roughness"),
    "boundary_friction": ("tribology", "boundary_friction"),
    "follower_radius": ("mechanism", "follower_radius"),
}

#: the materials' fields the reduced modulus is formed of
_MATERIALS = ("cam_modulus", "cam_poisson", "follower_modulus", "follower_poisson")

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
    out = {name: _column(_values(models, section, attr))
           for name, (section, attr) in SCALARS.items()}
    out["reduced_modulus"] = _column(_moduli(models))
    return out


def _values(models: list, section: str, attr: str) -> list:
    """``model.<section>.<attr>`` of every case (None where the deck has no such section). A
    case differs from the datum only in swept scalars, so all cases have the same sections."""
    if any(getattr(m, section) is None for m in models):
        return [None if getattr(m, section) is None else getattr(getattr(m, section), attr)
                for m in models]
    return list(map(operator.attrgetter(f"{section}.{attr}"), models))


def _moduli(models: list) -> list:
    """The reduced modulus of every case, formed once per distinct set of materials."""
    from camtrain.contact.model import modulus

    formed: dict[tuple, float] = {}
    out = []
    for m in models:
        key = tuple(getattr(m.materials, a) for a in _MATERIALS)
        value = formed.get(key)
        if value is None:
            value = formed[key] = modulus(m)
        out.append(value)
    return out


def _column(values: list):
    """The first value when every case has it, else the values as a (cases, 1) column."""
    first = values[0]
    if values.count(first) == len(values):   # (== of each value, in C)
        return first
    import numpy as np

    return np.array(values, dtype=float)[:, None]


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
