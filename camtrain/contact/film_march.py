"""The resolution options of a transient film march, with their defaults (no numpy).

A transient film law (:mod:`camtrain.contact.transient`) reads these from the contact's solver
options; a contact built without them (no deck) marches with these defaults. The deck's
``[solver]`` section declares the same fields with the same defaults (physics never imports the
deck, and loading a deck imports no physics; tests/floor/test_imports.py checks they agree)."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class FilmMarch:
    """Resolution of the transient film march (docs/transient_film.md)."""

    film_nodes: int = 401
    film_zone_width: float = 4.0
    film_angle_step: float | None = None
    film_tolerance: float = 1e-6
    film_march: str = "implicit_euler"
    film_cycles_max: int = 6
    film_period_tolerance: float = 1e-6
    # the elastic film (tribology.film_model = ehl; docs/ehl.md)
    ehl_nodes: int = 512
    ehl_inlet: float = 4.5
    ehl_angle_step: float = 0.008726646259971648    #: 0.5 deg [rad]
    ehl_tolerance: float = 1e-6
    ehl_march: str = "bdf2"
    ehl_linear_solver: str = "auto"


DEFAULTS = FilmMarch()
