"""The engine deck (``kind = "engine"``): an in-line crank train and its crankshaft bearings.

Yang (1992) App. A and B list exactly these data: crank-train geometry and masses, cylinders
with their firing angles, bays, crank components with out-of-balance moments, flywheel,
cylinder-pressure tables against crank angle, and the big-end and main bearings. Like every
schema this module is the single description of the deck (validation, SI model, template,
JSON Schema, echo). Bearings and the solver live in :mod:`.schema_engine_bearings`.

Further parts of a whole engine (ring pack, piston skirt, FLAME total, accessories, valve-train
decks included by path) are optional sections of :class:`EngineDeck`, each defined in a schema
module of its own and added here as one ``section(...)`` field; the effects that use them say
in ``missing`` which section they need.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from camtrain.deck.engine_units import MOMENT_UNITS, PRESSURE_UNITS
from camtrain.deck.fields import When, option, quantity, section
from camtrain.deck.schema_correlations import CorrelationsSection, LoadSection, OilSection
from camtrain.deck.schema_engine_bearings import EngineBearingsSection, EngineSolver
from camtrain.deck.schema_flame import FlameSection
from camtrain.deck.schema_piston import PistonSection
from camtrain.errors import Problem
from camtrain.units import from_si

#: Yang's g for the out-of-balance weight moment (§1.2.2).
_G = 9.81


@dataclass(frozen=True, kw_only=True)
class EngineSpeed:
    """The engine speed of this run (pressure tables and viscosities are picked for it)."""

    engine: float = quantity("Engine (crankshaft) speed of this run", "rpm", gt=0, lt=1e5,
                             example=600.0)

    @property
    def omega(self) -> float:
        """Engine speed [rad/s] (what the report header shows as the run speed)."""
        return self.engine


@dataclass(frozen=True, kw_only=True)
class CrankTrainSection:
    """Slider-crank data common to every cylinder, the bays and the flywheel (Yang App. A.1)."""

    strokes: int = quantity("Strokes per cycle: 4 (cycle 720 deg) or 2 (360 deg)", default=4,
                            ge=2, le=4)
    bore: float = quantity("Cylinder bore D", "mm", gt=0, example=260.35)
    crank_radius: float = quantity("Crank radius R (half the stroke)", "mm", gt=0,
                                   example=184.15)
    rod_length: float | None = quantity(
        "Connecting-rod length L between centres (a bare engine deck with [correlations] may "
        "leave it and the masses and bays out)", "mm", default=None, gt=0, example=782.32)
    piston_mass: float | None = quantity("Piston-assembly mass m_p (piston, pin, rings)", "kg",
                                         default=None, ge=0, example=82.07)
    rod_mass: float | None = quantity(
        "Connecting-rod mass m_c (1/3 reciprocates, 2/3 rotates)", "kg", default=None, ge=0,
        example=81.62)
    bay_lengths: tuple[float, ...] | None = quantity(
        "Length of each bay between two mains, front to rear (n bays -> n + 1 mains)", "mm",
        default=None, gt=0, min_items=1, example=[444.5, 444.5])
    flywheel_mass: float = quantity("Flywheel mass; its weight acts on the last main", "kg",
                                    default=0.0, ge=0)

    def problems(self, path: str) -> list[Problem]:
        out = []
        if self.strokes not in (2, 4):
            out.append(Problem(f"{path}.strokes", "must be 2 or 4", self.strokes, "2 or 4"))
        return out


@dataclass(frozen=True, kw_only=True)
class CylinderSection:
    """One cylinder: its bay, its axial position in the bay and the angle of its firing TDC."""

    bay: int = quantity("Bay of the cylinder, 1 = front (belt side)", ge=1, example=1)
    position: float = quantity("Distance of the cylinder axis from the front of its bay", "mm",
                               ge=0, example=222.25)
    firing_angle: float = quantity(
        "Crank angle of this cylinder's firing TDC (Yang's 'angle to TDC firing')", "deg",
        ge=-7200, le=7200, example=0.0)


@dataclass(frozen=True, kw_only=True)
class CrankComponentSection:
    """A crank web, pin or counterweight: where it sits and its out-of-balance weight moment
    M_o = m r g (Yang §1.2.2: C = (M_o / g) omega^2)."""

    bay: int = quantity("Bay of the component, 1 = front", ge=1, example=1)
    position: float = quantity("Distance from the front of its bay", "mm", ge=0,
                               example=222.25)
    angle: float = quantity("Angular position from throw 1 in the sense of rotation", "deg",
                            ge=-720, le=720, example=0.0)
    moment: float = quantity("Out-of-balance weight moment M_o, in moment_unit", ge=0,
                             example=139.19)
    moment_unit: Literal["N·m", "N·mm"] = option(
        "Unit of moment (explicit: Yang's Ruston values are plausible in N·m, his Zeta values "
        "only in N·mm; check warns when a value looks like the other unit)", example="N·m")

    @property
    def unbalance(self) -> float:
        """Mass-radius product m r [kg m]."""
        return self.moment * MOMENT_UNITS[self.moment_unit] / _G


@dataclass(frozen=True, kw_only=True)
class PressureTableSection:
    """A cylinder-pressure table against crank angle from firing TDC, for the speeds listed."""

    speeds: tuple[float, ...] = quantity(
        "Engine speeds this table applies to; empty = every speed", "rpm", default=(),
        gt=0, example=[600.0])
    reference: Literal["gauge", "absolute"] = option(
        "Whether the values are gauge (above the crankcase) or absolute pressures",
        example="gauge")
    unit: Literal["bar", "MPa", "kPa", "Pa", "psi"] = option("Unit of values and crankcase",
                                                             example="bar")
    crankcase: float | None = quantity(
        "Crankcase pressure in `unit`, subtracted from an absolute table (unset: 1 atm)",
        default=None, ge=0)
    angle_step: float = quantity("Crank-angle step of the values, from `start_angle`", "deg",
                                 gt=0, le=360, example=10.0)
    start_angle: float = quantity("Crank angle of the first value from firing TDC", "deg",
                                  default=0.0, ge=-720, le=720)
    values: tuple[float, ...] = quantity("Cylinder pressure every angle_step, in `unit`",
                                         min_items=4, example=[47.37, 64.12, 48.61, 34.82])

    def problems(self, path: str) -> list[Problem]:
        if self.reference == "absolute" and min(self.values) < 0:
            return [Problem(f"{path}.values", "an absolute pressure cannot be negative",
                            min(self.values), "values >= 0, or reference = \"gauge\"")]
        return []

    @property
    def angles(self) -> tuple[float, ...]:
        """Crank angles of the values [rad]."""
        return tuple(self.start_angle + i * self.angle_step for i in range(len(self.values)))

    @property
    def pascal(self) -> tuple[float, ...]:
        """Values in Pa (as given: gauge or absolute)."""
        f = PRESSURE_UNITS[self.unit]
        return tuple(v * f for v in self.values)

    @property
    def crankcase_pa(self) -> float:
        if self.crankcase is None:
            return 101325.0
        return self.crankcase * PRESSURE_UNITS[self.unit]

    def applies_to(self, omega: float) -> bool:
        """Whether the run speed ``omega`` [rad/s] uses this table."""
        return not self.speeds or any(math.isclose(omega, s, rel_tol=1e-9) for s in self.speeds)


@dataclass(frozen=True, kw_only=True)
class EngineDeck:
    """A whole-engine deck: the crank train and its crankshaft bearings."""

    #: without [correlations] the crank train is required (a bare engine deck has only what
    #: the correlations need)
    schema_rules = (When("correlations", (None,), require=("cylinders", "pressure",
                                                          "bearings")),)

    kind: Literal["engine"] = option("Deck kind: engine", example="engine")
    title: str = option("Name of the engine case", example="Ruston 6VEB-X Mk III big-end")
    speed: EngineSpeed = section("Engine speed of this run", required=True)
    engine: CrankTrainSection = section("Crank train: geometry, masses, bays, flywheel",
                                        required=True)
    cylinders: tuple[CylinderSection, ...] = section(
        "Cylinders ([[cylinders]], one per cylinder; a bare engine deck gives "
        "correlations.cylinders instead)", default=())
    crank_components: tuple[CrankComponentSection, ...] = section(
        "Crank webs, pins and counterweights with out-of-balance moments", default=())
    pressure: tuple[PressureTableSection, ...] = section(
        "Cylinder-pressure tables ([[pressure]]); the run uses the one listing its speed",
        default=())
    bearings: EngineBearingsSection | None = section("Big-end and main bearings")
    solver: EngineSolver = section("Models and resolution of the crank-bearing calculation",
                                   default=EngineSolver())
    piston: PistonSection | None = section(
        "Piston assembly of every cylinder: rings, gas, oil-control ring, skirt, liner "
        "temperatures and oil (schema_piston)")
    flame: FlameSection | None = section(
        "Engine friction total by component: valve-train decks included by path, accessories "
        "(schema_flame)")
    correlations: CorrelationsSection | None = section(
        "Friction correlations beside FLAME, or alone on a bare engine deck: PNH 1989, "
        "Sandoval-Heywood 2003, Chen-Flynn (schema_correlations)")
    oil: OilSection | None = section("Engine oil: grade or viscosity, temperature "
                                     "(schema_correlations)")
    load: LoadSection | None = section(
        "Engine load: the pressure diagram scaled to a peak pressure or an IMEP "
        "(schema_correlations)")

    #: what the report's title line says after the run speed
    speed_label = "rpm engine"

    @property
    def effects(self) -> str:
        """The plan is automatic: each effect runs when its sections are given."""
        return "auto"

    @property
    def rpm(self) -> float:
        return from_si(self.speed.engine, "rpm")

    def pressure_table(self) -> PressureTableSection:
        """The pressure table of this run's speed (validated to exist by :meth:`problems`)."""
        return next(t for t in self.pressure if t.applies_to(self.speed.omega))

    def resolve_paths(self, base_dir, source: str) -> EngineDeck:
        """The deck with its included valve-train decks made absolute and validated."""
        import dataclasses

        from camtrain.deck.schema_flame import resolve_valve_trains

        if self.flame is None:
            return self
        return dataclasses.replace(self, flame=resolve_valve_trains(self.flame, base_dir,
                                                                    source))

    def problems(self, path: str) -> list[Problem]:
        from camtrain.deck.schema_correlations import bare_engine_problems

        out = bare_engine_problems(self)
        e = self.engine
        nb = len(e.bay_lengths or ())
        for what, items in (("cylinders", self.cylinders),
                            ("crank_components", self.crank_components)):
            for i, it in enumerate(items):
                if it.bay > nb:
                    out.append(Problem(f"{what}[{i}].bay", "no such bay", it.bay,
                                       f"1 to {nb} (engine.bay_lengths)"))
                elif it.position > e.bay_lengths[it.bay - 1] + 1e-12:
                    out.append(Problem(f"{what}[{i}].position", "lies outside its bay",
                                       f"{from_si(it.position, 'mm'):g} mm",
                                       f"0 to {from_si(e.bay_lengths[it.bay - 1], 'mm'):g} mm"))
        if not self.cylinders and self.correlations is None:
            out.append(Problem("cylinders", "needs at least one cylinder", 0))
        rpm = self.rpm
        hits = [i for i, t in enumerate(self.pressure) if t.applies_to(self.speed.omega)]
        listed = sorted({from_si(s, "rpm") for t in self.pressure for s in t.speeds})
        if self.pressure and not hits:
            out.append(Problem("pressure", "no table for the run speed", f"{rpm:g} rpm",
                               "a [[pressure]] table with this speed in `speeds` (tables for "
                               + ", ".join(f"{s:g}" for s in listed) + " rpm)"))
        elif len(hits) > 1:
            out.append(Problem("pressure", "several tables claim the run speed", f"{rpm:g} rpm",
                               f"one table per speed (tables {[h + 1 for h in hits]})"))
        cycle = 360.0 * e.strokes / 2.0
        for i, t in enumerate(self.pressure):
            span = math.degrees(t.angles[-1] - t.angles[0])
            if span >= cycle - 1e-9:
                out.append(Problem(f"pressure[{i}].values", "span a whole cycle or more",
                                   f"{span:g} deg", f"a span < {cycle:g} deg (the table "
                                   "repeats every cycle: do not repeat the first value)"))
        if self.bearings is not None:
            out += self.bearings.speed_problems(rpm, "bearings")
        return out

    @property
    def cylinder_count(self) -> int:
        """The engine's cylinders: the [[cylinders]] listed, or correlations.cylinders of a
        bare engine deck (:meth:`problems` requires one of them)."""
        if self.cylinders:
            return len(self.cylinders)
        return self.correlations.cylinders if self.correlations is not None else 0

    @property
    def has_crank_train(self) -> bool:
        """Whether the deck describes the crank train (cylinders, pressure, rod, masses, bays):
        a bare engine deck for the correlations alone does not."""
        e = self.engine
        return bool(self.cylinders and self.pressure) and None not in (
            e.rod_length, e.piston_mass, e.rod_mass, e.bay_lengths)

    def advisories(self) -> list[str]:
        """Warnings `check` and `run` print: values that look like a unit slip, models outside
        their range of validity."""
        from camtrain.deck.engine_advice import engine_advisories

        return engine_advisories(self)
