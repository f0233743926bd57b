"""The film model of a journal bearing, one definition for every deck section that holds bearings.

A section declares the four fields with the factories below (a prefix such as ``bearing_`` where
the section holds more than bearings), and an effect reads them back with
:func:`film_model_options`::

    @dataclass(frozen=True, kw_only=True)
    class Crankshaft:
        bearing_model: BearingModelName = model_field()
        bearing_cavitation: BearingCavitation = cavitation_field()
        bearing_n_theta: int = n_theta_field()
        bearing_n_z: int = n_z_field()

    film_model_options(deck.crankshaft, "bearing_")  # -> FilmModelOptions

``auto`` is the default for new decks: the finite-length film unless every land is short
(b/d <= 0.05, where the short bearing is within 3.5 %; docs/bearings.md). Decks that reproduce
Ball's or Yang's printed numbers name ``short``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import option, quantity

__all__ = ["BearingModelName", "BearingCavitation", "FilmModelOptions", "model_field",
           "cavitation_field", "n_theta_field", "n_z_field", "film_model_options"]

BearingModelName = Literal["auto", "short", "finite"]
BearingCavitation = Literal["reynolds", "half_sommerfeld"]


def model_field() -> str:
    return option(
        "Film model: short (Ocvirk's short bearing, as Ball and Yang; optimistic above b/d "
        "0.05, x1.1-x3 on the film at engine loads), finite (Reynolds solution over the whole "
        "bearing) or auto (finite unless the land b/d is 0.05 or less)", default="auto")


def cavitation_field() -> str:
    return option(
        "Cavitation condition of the finite film: reynolds (Swift-Stieber, as Raimondi and "
        "Boyd) or half_sommerfeld (negative pressures dropped, Ocvirk's condition)",
        default="reynolds")


def n_theta_field() -> int:
    return quantity(
        "Finite film mesh: nodes around the circumference (the mobility map adds nodes as "
        "eps -> 1; see `camtrain accuracy`)", "-", default=72, ge=16, le=2000)


def n_z_field() -> int:
    return quantity("Finite film mesh: intervals from the mid-plane to the end of a land", "-",
                    default=6, ge=2, le=200)


@dataclass(frozen=True)
class FilmModelOptions:
    """The film model a deck asks for: model name, cavitation condition and mesh."""

    model: str = "auto"
    cavitation: str = "reynolds"
    n_theta: int = 72
    n_z: int = 6


def film_model_options(section, prefix: str = "") -> FilmModelOptions:
    """The four fields of ``section`` (named ``prefix + "model"`` etc.)."""
    return FilmModelOptions(*(getattr(section, prefix + name)
                              for name in ("model", "cavitation", "n_theta", "n_z")))
