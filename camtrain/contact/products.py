"""Products of the contact physics: frozen per-pair fields and their per-train collections.

A valve train has one cam/follower pair, or two for a desmodromic train (the opening pair is the
train's ``main`` component, the closing pair its ``closing`` component). The train-level
products hold one field per pair, in that order.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.components import ByPair


@dataclass(frozen=True)
class HertzField:
    """Per-angle Hertz contact of one pair: ``pmax`` [Pa], ``half_width`` [m] (rolling
    direction), ``half_length`` [m] (transverse: half the cam width for a line contact), ``bad``
    (loaded but not Hertzian: NaN there) and whether the contact is a line."""

    pmax: np.ndarray
    half_width: np.ndarray
    half_length: np.ndarray
    bad: np.ndarray
    line: bool


@dataclass(frozen=True)
class FilmField:
    """Per-angle film of one pair: minimum and central thickness [m] (central None for the
    load-free Blok film) and the formulas that gave them.

    A transient film law (docs/transient_film.md) also gives the steady film of the same angles
    (``steady`` [m]), the regime label per angle (``regime``: hydrodynamic, mixed, boundary,
    separated; None where the law does not label), the friction force [N] of its own solution
    (``friction``, None: the deck's friction law applies) and its solution (``solution``: the
    law's own record, e.g. pressures and loads per angle)."""

    min: np.ndarray
    central: np.ndarray | None
    method: str
    central_method: str | None
    steady: np.ndarray | None = None
    regime: np.ndarray | None = None
    friction: np.ndarray | None = None
    solution: object = None

    @property
    def for_shear(self) -> np.ndarray:
        """The film the shear integral uses: central where known, else the minimum."""
        return self.central if self.central is not None else self.min


@dataclass(frozen=True)
class FrictionField:
    """Per-angle friction of one pair: force [N] on the loaded angles (0 elsewhere), the
    Hertz field and film it was computed with, and where the contact carried load."""

    force: np.ndarray
    hertz: HertzField
    film: FilmField
    used: np.ndarray


@dataclass(frozen=True)
class ContactHertz(ByPair[HertzField]):
    """Hertz field of every loaded pair of the train."""


@dataclass(frozen=True)
class ContactFilm(ByPair[FilmField]):
    """Film of every pair of the train (load-free Blok film when no contact load is planned)."""

    with_load: bool = True


@dataclass(frozen=True)
class ContactFriction(ByPair[FrictionField]):
    """Friction of every loaded pair of the train (``tribology.friction_model``)."""

    model: str = ""


@dataclass(frozen=True)
class CamTorque:
    """Camshaft torque of the main pair W e + F r [N m], its friction part F r, and the
    friction power per angle [W]; ``total_power`` sums the pairs' cycle means."""

    cam_torque: np.ndarray
    friction_torque: np.ndarray
    power: np.ndarray
    total_power: float
