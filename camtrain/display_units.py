"""The units people read a column or metric in (mm, deg, µm, MPa, rpm): one table of display
rules for the report, the terminal, every plot, the files a run writes and the Result's
DataFrames (so Result, below the report, reads them here). SI inside, these outside."""
from __future__ import annotations

import math

#: SI unit of a column or metric -> (display unit, factor from SI)
_BY_UNIT = {
    "m": ("mm", 1e3),
    "rad": ("deg", 180.0 / math.pi),
    "Pa": ("MPa", 1e-6),
    "N*m": ("N·m", 1.0),
    "m/rad": ("mm/deg", 1e3 * math.pi / 180.0),
    "m/rad^2": ("mm/deg²", 1e3 * (math.pi / 180.0) ** 2),
    "m/rad^3": ("mm/deg³", 1e3 * (math.pi / 180.0) ** 3),
    "rad/s": ("rpm", 60.0 / (2.0 * math.pi)),
    "-": ("", 1.0),
}

#: names whose length is a film (shown in µm, like Ball's plots) or a contact size
_MICRO = ("film", "h_min", "h_cen", "hertz_half", "roughness", "deflection")


def display_unit(name: str, si_unit: str) -> tuple[str, float]:
    """(unit shown, factor from SI) for a column or metric called ``name``."""
    if si_unit == "m" and any(k in name for k in _MICRO):
        return "µm", 1e6
    if si_unit == "rad" and name == "cam_angle":
        return "deg", 180.0 / math.pi
    return _BY_UNIT.get(si_unit, (si_unit, 1.0))


#: unit systems of the files a run writes: the deck's engineering units (default) or SI
UNIT_SYSTEMS = ("deck", "si")


def output_unit(name: str, si_unit: str, units: str = "deck") -> tuple[str, float]:
    """(unit written beside a column or metric, factor from SI) in a file of ``units``.

    "deck" writes what the terminal and report show (mm, deg, µm, MPa, ...), "si" the SI unit
    camtrain computes in. A dimensionless quantity is written "-". Converting a value already
    in its display unit again leaves it unchanged (the display units map to themselves).
    """
    if units not in UNIT_SYSTEMS:
        raise ValueError(f"units {units!r}: expected one of {', '.join(UNIT_SYSTEMS)}")
    if units == "si":
        from camtrain.units import UNITS

        factor, si = UNITS.get(si_unit, (1.0, si_unit))   # a deck unit (deg, rpm) to SI
        return si or "-", factor
    unit, factor = display_unit(name, si_unit)
    return unit or "-", factor
