"""The engine oil of a deck: its kinematic viscosity at the run's temperature (the
correlations) and the factor that moves FLAME's viscosities with the oil temperature."""
from __future__ import annotations

from camtrain.formulas.engine_friction import NU_REFERENCE, oil_grade_viscosity


def oil_viscosity(deck, temperature: float | None = None) -> float:
    """Kinematic viscosity [m^2/s] of the deck's oil at ``temperature`` [degC] (default: the
    run's); no [oil]: the correlations' reference oil nu_0 (r = 1)."""
    oil = getattr(deck, "oil", None)
    if oil is None:
        return NU_REFERENCE
    if oil.grade is None:
        return oil.viscosity
    t = oil.temperature if temperature is None else temperature
    return float(oil_grade_viscosity(oil.grade, t, high_shear=oil.shear == "high"))


def flame_oil_factor(deck) -> float:
    """Factor on FLAME's viscosities: the grade's nu(temperature) / nu(reference_temperature)
    when [oil] sets a reference temperature, else 1 (the deck's viscosities as given)."""
    oil = getattr(deck, "oil", None)
    if oil is None or oil.reference_temperature is None:
        return 1.0
    return oil_viscosity(deck) / oil_viscosity(deck, oil.reference_temperature)
