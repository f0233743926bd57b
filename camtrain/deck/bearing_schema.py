"""The stand-alone journal-bearing deck (``kind = "journal_bearing"``): one plain bearing under a
periodic load diagram, solved by :mod:`camtrain.bearings`.

Like the valve-train schema, this module is the single description of the deck: validation,
the SI model and the template are derived from it. Values in the model are SI.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import When, option, quantity, section
from camtrain.deck.schema_bearing_model import (
    BearingCavitation,
    BearingModelName,
    cavitation_field,
    model_field,
    n_theta_field,
    n_z_field,
)
from camtrain.deck.schema_journal import (
    bearing_geometry_problems,
    clearance_field,
    diameter_field,
    groove_width_field,
    length_field,
)
from camtrain.errors import Problem
from camtrain.units import from_si


@dataclass(frozen=True, kw_only=True)
class BearingGeometry:
    """The bearing and its oil (a full central groove makes two lands)."""

    diameter: float = diameter_field(example=25.0)
    length: float = length_field(example=18.0)
    clearance: float = clearance_field(example=0.025)
    groove_width: float = groove_width_field()
    viscosity: float = quantity("Effective dynamic viscosity of the oil film", "Pa·s", gt=0,
                                example=0.01)

    def problems(self, path: str) -> list[Problem]:
        return bearing_geometry_problems(self, path)


@dataclass(frozen=True, kw_only=True)
class BearingSpeed:
    """Journal and bush speeds in the bush frame, counter-clockwise positive."""

    journal: float = quantity("Journal speed", "rpm", gt=-1e6, lt=1e6, example=1500.0)
    bearing: float = quantity("Bush (bearing) speed; 0 for a fixed bush", "rpm", default=0.0,
                              gt=-1e6, lt=1e6)

    schema_rules = (When("journal", (0,), reject=True),)

    @property
    def omega(self) -> float:
        """Journal angular speed [rad/s] (what the report header shows as the run speed)."""
        return self.journal

    def problems(self, path: str) -> list[Problem]:
        if self.journal == 0.0:
            return [Problem(f"{path}.journal", "must not be 0 (the load diagram advances with "
                            "the journal)", 0, "a speed in rpm")]
        return []


@dataclass(frozen=True, kw_only=True)
class LoadDiagram:
    """The load on the film (the force the journal puts on the bearing) over one period."""

    angles: tuple[float, ...] = quantity(
        "Journal angles of the load points, increasing, spanning less than one period", "deg",
        min_items=2, example=[0.0, 180.0])
    load_x: tuple[float, ...] = quantity("Load component along x at each angle", "N",
                                         min_items=2, example=[0.0, 0.0])
    load_y: tuple[float, ...] = quantity("Load component along y at each angle", "N",
                                         min_items=2, example=[-500.0, -500.0])
    period: float = quantity("Angle of one load cycle (360 camshaft, 720 four-stroke crank)",
                             "deg", default=360.0, gt=0, le=7200)

    def problems(self, path: str) -> list[Problem]:
        out = []
        n = len(self.angles)
        for name in ("load_x", "load_y"):
            if len(getattr(self, name)) != n:
                out.append(Problem(f"{path}.{name}", f"has {len(getattr(self, name))} values "
                                   f"but angles has {n}", None, "one value per angle"))
        for i in range(1, n):
            if not self.angles[i] > self.angles[i - 1]:
                out.append(Problem(f"{path}.angles[{i}]", "does not increase",
                                   f"{from_si(self.angles[i], 'deg'):g} deg",
                                   "angles strictly increasing"))
                break
        if n and self.angles[-1] - self.angles[0] >= self.period:
            out.append(Problem(f"{path}.angles", "span one period or more", None,
                               "a span < period (the diagram repeats)"))
        return out


@dataclass(frozen=True, kw_only=True)
class BearingSolver:
    """Model and resolution knobs (see `camtrain accuracy`)."""

    method: Literal["mobility", "steady", "petroff"] = option(
        "mobility (Booker orbit, marched until periodic), steady (quasi-static locus) or "
        "petroff (concentric power only)", default="mobility")
    model: BearingModelName = model_field()
    cavitation: BearingCavitation = cavitation_field()
    n_theta: int = n_theta_field()
    n_z: int = n_z_field()
    mobility: Literal["exact", "booker"] = option(
        "Mobility of the short model: exact pi-film inversion or Booker's closed form",
        default="exact")
    film: Literal["pi", "2pi"] = option(
        "Shear film for power: 2pi = complete film (Martin 1985, Yang eq. 1.22; Ball eq. 6.7) "
        "or pi = loaded pi film only (Booker 1965, Yang eq. 1.21)", default="pi")
    terms: Literal["shear", "all"] = option(
        "Power terms: shear only, or shear plus the translatory (squeeze) term", default="shear")
    step_tolerance: float = quantity("Absolute error per time step on the eccentricity ratio",
                                     "-", default=1e-7, gt=0, lt=0.01)
    period_tolerance: float = quantity(
        "Cycle-to-cycle change of the eccentricity ratio that counts as periodic", "-",
        default=1e-5, gt=0, lt=0.1)
    max_cycles: int = quantity("Most load cycles marched before giving up", "-", default=20,
                               ge=2, le=1000)
    start: Literal["steady", "centre"] = option(
        "Start of the march: the steady position at the first angle, or the bush centre",
        default="steady")


@dataclass(frozen=True, kw_only=True)
class BearingDeck:
    """A stand-alone journal-bearing deck."""

    kind: Literal["journal_bearing"] = option(
        "Deck kind: journal_bearing (a valve-train deck omits it or says valve_train)",
        example="journal_bearing")
    title: str = option("Name of the bearing case", example="Short bearing under constant load")
    bearing: BearingGeometry = section("Bearing geometry and oil", required=True)
    speed: BearingSpeed = section("Journal and bush speeds", required=True)
    load: LoadDiagram = section("Load diagram", required=True)
    solver: BearingSolver = section("Model and resolution", default=BearingSolver())

    @property
    def effects(self) -> str:
        """The plan is automatic: the deck kind has one effect, the bearing orbit."""
        return "auto"
