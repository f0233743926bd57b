"""Engineering units for what people read (tables, terminal, plots): SI inside, mm/µm/MPa outside.

One table of display rules keeps the report, the terminal and every plot in the same units.
"""
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

#: readable labels of well-known columns (others show their name)
LABELS = {
    "lift": "lift", "valve_lift": "valve lift", "velocity": "velocity dl/dθ",
    "acceleration": "acceleration d²l/dθ²", "jerk": "jerk d³l/dθ³",
    "eccentricity": "contact position e", "cam_radius": "cam radius r_c",
    "equivalent_radius": "equivalent radius R", "v_cam": "V_c", "v_follower": "V_f",
    "entrainment": "entrainment", "sliding": "sliding V_c − V_f",
    "pressure_angle": "pressure angle", "rocker_ratio": "rocker ratio",
    "load": "contact load W", "valve_force": "valve force", "hertz_pmax": "Hertz p_max",
    "hertz_half_width": "Hertz half-width b", "film_min": "h_min", "film_central": "h_cen",
    "lambda": "λ = h_min/σ", "friction_force": "friction force",
    "friction_coefficient": "friction coefficient μ", "friction_torque": "friction torque",
    "cam_torque": "total cam torque", "power_loss": "friction power",
}


def display_unit(name: str, si_unit: str) -> tuple[str, float]:
    """(unit shown, factor from SI) for a column or metric called ``name``."""
    if si_unit == "m" and any(k in name for k in _MICRO):
        return "µm", 1e6
    if si_unit == "rad" and name == "cam_angle":
        return "deg", 180.0 / math.pi
    return _BY_UNIT.get(si_unit, (si_unit, 1.0))


#: unit systems of the files a run writes: the deck's engineering units (default) or SI
UNIT_SYSTEMS = ("deck", "si")


#: how a unit written in ASCII in the code reads on a plot or page
_TYPESET = (("^2", "²"), ("^3", "³"), ("^-1", "⁻¹"), ("*", "·"))


def typeset(unit: str) -> str:
    """A unit as people read it: m/s^2 -> m/s², N*m -> N·m (plots and sheets; the tables keep
    their ASCII headers, which scripts parse)."""
    for ascii_, shown_ in _TYPESET:
        unit = unit.replace(ascii_, shown_)
    return unit


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


def shown(name: str, value: float, si_unit: str, digits: int = 4) -> tuple[str, str]:
    """(formatted value, unit) in display units, e.g. ('417.3', 'MPa')."""
    unit, factor = display_unit(name, si_unit)
    return fmt(value * factor, digits), unit


def fmt(x: float, digits: int = 4) -> str:
    """Compact number: fixed point for ordinary magnitudes, exponent only when needed."""
    if x is None or not math.isfinite(x):
        return "—" if x is None else str(x)
    if x == 0:
        return "0"
    mag = abs(x)
    if 1e-3 <= mag < 1e6:
        decimals = max(0, digits - 1 - int(math.floor(math.log10(mag))))
        return f"{x:.{decimals}f}"
    return f"{x:.{digits - 1}e}"


def deg(angle: float | None) -> str:
    return "" if angle is None else f"{math.degrees(angle):.1f}"
