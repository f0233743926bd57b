"""Engineering units for what people read (tables, terminal, plots): SI inside, mm/µm/MPa outside.

One table of display rules keeps the report, the terminal and every plot in the same units.
"""
from __future__ import annotations

import math

from camtrain.display_units import UNIT_SYSTEMS, display_unit, output_unit

__all__ = ["LABELS", "UNIT_SYSTEMS", "deg", "display_unit", "fmt", "output_unit", "shown",
           "typeset"]

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


#: how a unit written in ASCII in the code reads on a plot or page
_TYPESET = (("^2", "²"), ("^3", "³"), ("^-1", "⁻¹"), ("*", "·"))


def typeset(unit: str) -> str:
    """A unit as people read it: m/s^2 -> m/s², N*m -> N·m (plots and sheets; the tables keep
    their ASCII headers, which scripts parse)."""
    for ascii_, shown_ in _TYPESET:
        unit = unit.replace(ascii_, shown_)
    return unit


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
