"""The in-line crank train as data (SI): geometry, masses, cylinders, bays, crank components.

Yang (1992) App. A.1-A.3 and B.2-B.3 list exactly these items. Bays are numbered from the front
(belt side); bay ``i`` lies between main bearings ``i`` and ``i + 1``, so an engine with
``n`` bays has ``n + 1`` mains. Angles (firing angle, component position) are in radians in the
sense of rotation (see :mod:`camtrain.engine.crank`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from camtrain.errors import field_error

from .pressure import PressureTable

__all__ = ["CrankTrain", "Cylinder", "CrankComponent", "Engine", "STANDARD_GRAVITY",
           "unbalance_from_weight_moment"]

#: Yang's g for the out-of-balance moment (§1.2.2 notation: g = 9.81 m/s^2).
STANDARD_GRAVITY = 9.81


def _positive(path: str, value) -> float:
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
        raise field_error(path, "must be a finite number > 0", value)
    return float(value)


def _non_negative(path: str, value) -> float:
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value >= 0):
        raise field_error(path, "must be a finite number >= 0", value)
    return float(value)


def unbalance_from_weight_moment(moment: float, g: float = STANDARD_GRAVITY) -> float:
    """Mass-radius product m r [kg m] of an out-of-balance given as a weight moment M_o [N m].

    Yang §1.2.2: C = (M_o / g) omega^2 is the out-of-balance force.
    """
    return moment / g


@dataclass(frozen=True)
class CrankTrain:
    """Slider-crank data common to every cylinder (Yang App. A.1).

    Attributes: bore D [m], crank_radius R [m], rod_length L [m] (centres), piston_mass m_p
    [kg] (piston assembly), rod_mass m_c [kg], strokes 2 or 4.
    """

    bore: float
    crank_radius: float
    rod_length: float
    piston_mass: float
    rod_mass: float
    strokes: int = 4

    def __post_init__(self):
        _positive("engine.bore", self.bore)
        _positive("engine.crank_radius", self.crank_radius)
        _positive("engine.rod_length", self.rod_length)
        _non_negative("engine.piston_mass", self.piston_mass)
        _non_negative("engine.rod_mass", self.rod_mass)
        if self.rod_length <= self.crank_radius:
            raise field_error("engine.rod_length", "must be longer than the crank radius",
                              self.rod_length, f"> {self.crank_radius} m")
        if self.strokes not in (2, 4):
            raise field_error("engine.strokes", "must be 2 or 4", self.strokes)

    @property
    def cycle(self) -> float:
        """Crank angle of one working cycle [rad]: 4 pi (4-stroke) or 2 pi (2-stroke)."""
        return 2.0 * math.pi * self.strokes / 2.0

    @property
    def reciprocating_mass(self) -> float:
        return self.piston_mass + self.rod_mass / 3.0

    @property
    def rotating_mass(self) -> float:
        return 2.0 * self.rod_mass / 3.0


@dataclass(frozen=True)
class Cylinder:
    """One cylinder: its bay (0-based), axial position from the front of the bay [m], the crank
    angle of its firing TDC [rad] (Yang's "angle to TDC firing") and its pressure table."""

    bay: int
    position: float
    firing_angle: float
    pressure: PressureTable
    name: str = "cylinder"


@dataclass(frozen=True)
class CrankComponent:
    """A crank web, pin or counterweight: bay (0-based), position from the front of the bay [m],
    out-of-balance m r [kg m] and angular position [rad] from throw 1 in the sense of rotation."""

    bay: int
    position: float
    unbalance: float
    angle: float
    name: str = "crank component"


@dataclass(frozen=True)
class Engine:
    """An in-line engine: crank train, bay lengths [m], cylinders, crank components, flywheel.

    The flywheel's weight (mass [kg] times g, along -y) acts on the last main bearing
    (Yang §1.2.2).
    """

    crank: CrankTrain
    bay_lengths: tuple
    cylinders: tuple
    components: tuple = field(default_factory=tuple)
    flywheel_mass: float = 0.0

    def __post_init__(self):
        if len(self.bay_lengths) < 1:
            raise field_error("engine.bays", "needs at least one bay", len(self.bay_lengths))
        for i, ell in enumerate(self.bay_lengths):
            _positive(f"engine.bays[{i}].length", ell)
        if not self.cylinders:
            raise field_error("engine.cylinders", "needs at least one cylinder", 0)
        for what, items in (("cylinders", self.cylinders), ("crank_components",
                                                            self.components)):
            for i, it in enumerate(items):
                if not (0 <= it.bay < len(self.bay_lengths)):
                    raise field_error(f"engine.{what}[{i}].bay", "no such bay", it.bay + 1,
                                      f"1 to {len(self.bay_lengths)}")
                ell = self.bay_lengths[it.bay]
                if not (0.0 <= it.position <= ell):
                    raise field_error(f"engine.{what}[{i}].position", "outside its bay",
                                      it.position, f"0 to {ell} m from the front of the bay")
        for i, cyl in enumerate(self.cylinders):
            if abs(cyl.pressure.cycle - self.crank.cycle) > 1e-9:
                raise field_error(f"engine.cylinders[{i}].pressure", "table cycle differs "
                                  "from the engine's", math.degrees(cyl.pressure.cycle),
                                  f"{math.degrees(self.crank.cycle):g} deg")
        _non_negative("engine.flywheel_mass", self.flywheel_mass)

    @property
    def n_mains(self) -> int:
        return len(self.bay_lengths) + 1
