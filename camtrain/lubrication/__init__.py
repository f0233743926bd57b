"""Transient lubrication of a line contact: pure physics on per-angle arrays (no deck knowledge).

* :mod:`.squeeze` level 1, Teodorescu et al. (2005) film formula with the squeeze term,
  marched implicitly (traps the film at zero entrainment);
* :mod:`.averaged_reynolds` level 2, Göçmen (2013) averaged Reynolds contact with
  Greenwood-Tripp asperities, marched by :mod:`.march`;
* :mod:`.reynolds` the semi-analytic 1-D averaged Reynolds solver; :mod:`.flow_factors`,
  :mod:`.asperity` its ingredients;
* :mod:`.ehl_line` the steady isothermal elastohydrodynamic line contact (full numerical
  solution: :mod:`.ehl_newton` its discrete system, :mod:`.ehl_elastic` the half-space
  deflection by FFT, :mod:`.ehl_oil` the piezoviscous compressible oil, :mod:`.ehl_friction`).
"""
from .averaged_reynolds import (
    REGIMES,
    ContactSolution,
    FilmProperties,
    FilmResolution,
    TransientFilm,
    contact_load,
    contact_solution,
    hertz_zone_half_width,
    transient_film,
)
from .march import MARCH_SCHEMES, MarchResult, implicit_march, solve_positive_root
from .reynolds import PressureSolution, contact_grid, reynolds_pressure
from .squeeze import (
    LOAD_EXPONENTS,
    SqueezeFilm,
    relaxation_step,
    squeeze_film_march,
    teodorescu_steady_film,
)

__all__ = ["REGIMES", "ContactSolution", "FilmProperties", "FilmResolution", "TransientFilm",
           "contact_load", "contact_solution", "hertz_zone_half_width", "transient_film",
           "MARCH_SCHEMES", "MarchResult", "implicit_march", "solve_positive_root",
           "PressureSolution", "contact_grid", "reynolds_pressure", "LOAD_EXPONENTS",
           "SqueezeFilm", "relaxation_step", "squeeze_film_march", "teodorescu_steady_film"]
