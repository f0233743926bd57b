"""What a coupled shaft-and-trains solver is given and what it returns (:mod:`camtrain.coupled`):
plain frozen data, built from the deck by :func:`camtrain.assemble.coupled.coupled_problem`, so no
solver sees the deck."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Coupling", "ShaftOptions", "CoupledProblem", "CoupledResult"]


@dataclass(frozen=True)
class Coupling:
    """The two-way coupling's options (docs/camshaft_dynamics.md): ``solver`` (a name of
    :data:`camtrain.coupled.SOLVERS`), ``tolerance`` (relative change of the periodic state),
    ``passes`` (waveform passes at most), ``relaxation``, ``method`` and ``preconditioner`` of
    the waveform iteration, its ``start`` (rigid or monolithic), the staggered step's
    ``predictor`` and ``iterations``."""

    solver: str
    tolerance: float
    passes: int
    relaxation: float
    method: str
    preconditioner: str
    start: str
    predictor: str
    iterations: int


@dataclass(frozen=True)
class ShaftOptions:
    """How the shaft answers its loads (:func:`camtrain.camshaft.elastic.shaft_answer`): the
    bearings' ``split``, the ``response`` (dynamic or static), the ``overhang`` rule, the
    drive's speed oscillation (``speed_amplitude`` [-], ``speed_order``) and the belt drive
    (position [m], pitch radius [m], hub-load angle [rad], preload [N]) or None."""

    split: str
    response: str
    overhang: str
    speed_amplitude: float
    speed_order: int
    drive: tuple | None


@dataclass(frozen=True)
class CoupledProblem:
    """Every lobe's elastic train on the elastic camshaft.

    ``kin`` the main pair's kinematics (one lobe's own angle frame, maximum lift at its
    ``phases`` angle), ``contact`` its :class:`~camtrain.contact.model.CamContact`; the lumped
    ``train``, its rigid ``cam`` input, time ``base`` and march ``settings``
    (:mod:`camtrain.dynamics`); the elastic ``shaft``
    (:class:`~camtrain.camshaft.elastic.ElasticShaft`) and its answer's ``options``; every
    lobe's angle of maximum lift ``phases`` [rad] and follower axis ``axes`` [rad]; the rocker
    ``ratio`` on the grid ``theta`` [rad]; the shaft speed ``omega`` [rad/s] and ``turn`` (+1
    anticlockwise, -1 clockwise); the rigid train's contact load ``rigid_load`` [N] (the
    waveform iteration's rigid start); ``coupling`` the solver's options."""

    kin: object
    contact: object
    train: object
    cam: object
    base: object
    settings: object
    shaft: object
    options: ShaftOptions
    phases: np.ndarray
    axes: np.ndarray
    ratio: np.ndarray
    theta: np.ndarray
    omega: float
    turn: float
    rigid_load: np.ndarray
    coupling: Coupling

    @property
    def lobes(self) -> int:
        return len(self.phases)


@dataclass(frozen=True)
class CoupledResult:
    """The coupled periodic state on the grid: every lobe's cam contact ``loads`` [N] and
    ``valve_acceleration`` [m/s^2] (lobes, n; shaft frame), the shaft's answer ``shaft``
    (:class:`~camtrain.camshaft.product.ElasticCamshaft`) to them, the ``solver`` (its words
    for the outputs), its ``passes`` (iterations or revolutions), last relative ``change``,
    ``converged``; what only some solvers give, else None: ``missed`` staggered steps whose
    passes did not agree, every contact's level-1 ``film`` [m], ``start_gap`` (largest
    difference to the monolithic march a waveform iteration started from, over its largest
    load) and ``separations`` (per lobe, the shaft angles [rad] where the cam loses the
    follower)."""

    loads: np.ndarray
    valve_acceleration: np.ndarray
    shaft: object
    solver: str
    passes: int
    change: float
    converged: bool
    missed: int | None = None
    film: np.ndarray | None = None
    start_gap: float | None = None
    separations: tuple | None = None
