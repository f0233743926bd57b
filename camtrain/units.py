"""Units at the boundary: the one place engineering units become SI and back.

Decks, tables and plots speak the units a valve-train engineer writes (mm, deg, rpm, GPa, µm);
everything inside camtrain is SI (m, rad, rad/s, Pa, Pa·s, 1/Pa, N, kg). Each deck field has
exactly one unit, named here by its label.
"""
from __future__ import annotations

import math

#: label -> (factor to SI, SI label). value_SI = value_deck * factor.
UNITS: dict[str, tuple[float, str]] = {
    "-": (1.0, "-"),
    "%": (0.01, "-"),
    "mm": (1e-3, "m"),
    "m": (1.0, "m"),
    "µm": (1e-6, "m"),
    "deg": (math.pi / 180.0, "rad"),
    "rad": (1.0, "rad"),
    "rpm": (2.0 * math.pi / 60.0, "rad/s"),
    "N": (1.0, "N"),
    "N/mm": (1e3, "N/m"),
    "N/mm²": (1e6, "N/m^2"),  # progressive spring: force per compression squared
    "N/mm³": (1e9, "N/m^3"),  # progressive spring: force per compression cubed
    "kg": (1.0, "kg"),
    "g": (1e-3, "kg"),
    "kg·m²": (1.0, "kg*m^2"),
    "GPa": (1e9, "Pa"),
    "MPa": (1e6, "Pa"),
    "Pa": (1.0, "Pa"),
    "Pa·s": (1.0, "Pa*s"),
    "1/GPa": (1e-9, "1/Pa"),
    "°C": (1.0, "degC"),  # temperatures stay in °C: only differences and fits use them
    "K": (1.0, "K"),
    "W": (1.0, "W"),
    "N·m": (1.0, "N*m"),
    "kg/m³": (1.0, "kg/m^3"),
    "N·m/rad": (1.0, "N*m/rad"),
    "N·s/m": (1.0, "N*s/m"),
    "mm/deg": (1e-3 / (math.pi / 180.0), "m/rad"),
    "mm/deg²": (1e-3 / (math.pi / 180.0) ** 2, "m/rad^2"),
    "mm/deg³": (1e-3 / (math.pi / 180.0) ** 3, "m/rad^3"),
    "mm·deg": (1e-3 * (math.pi / 180.0), "m*rad"),
    "mm²": (1e-6, "m^2"),
    "mm³": (1e-9, "m^3"),
    "J/(kg·K)": (1.0, "J/(kg*K)"),
    "kW": (1e3, "W"),
    "kPa": (1e3, "Pa"),
    "bar": (1e5, "Pa"),
    "m/s": (1.0, "m/s"),
    "mm²/s": (1e-6, "m^2/s"),  # kinematic viscosity; 1 mm²/s = 1 cSt
    "bar·s/m": (1e5, "Pa*s/m"),  # Chen-Flynn piston-speed coefficient
    "bar·s²/m²": (1e5, "Pa*s^2/m^2"),
}


def to_si(value: float, unit: str) -> float:
    """Convert a deck value in ``unit`` to SI."""
    return value * UNITS[unit][0]


def from_si(value, unit: str):
    """Convert an SI value (scalar or array) to ``unit``."""
    return value / UNITS[unit][0]


def si_label(unit: str) -> str:
    """SI unit label of a deck unit."""
    return UNITS[unit][1]


def rpm_to_rad_s(rpm: float) -> float:
    return rpm * UNITS["rpm"][0]


def rad_s_to_rpm(omega: float) -> float:
    return omega / UNITS["rpm"][0]


def mm_text(length: float) -> str:
    """A length [m] as a deck user writes it, e.g. '18 mm' (for messages)."""
    return f"{from_si(length, 'mm'):g} mm"
