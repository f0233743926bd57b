"""The elastic camshaft assembled once and answered for any set of loads: the model of
:mod:`.flexible` (bending, torsion) with its stations, and the periodic response of
:mod:`.flexible_response` turned into the bearing loads, lobe deflections and twist of an
:class:`~.product.ElasticCamshaft` (Teodorescu et al. 2005 §2.6)."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .flexible import BeamShaft, ShaftSection, TorsionShaft, beam_shaft, stations, torsion_shaft
from .flexible_response import (
    bearing_split,
    bending_response,
    drive_acceleration,
    torsion_response,
)
from .product import ElasticCamshaft

__all__ = ["ElasticShaft", "elastic_shaft", "shaft_answer"]


@dataclass(frozen=True)
class ElasticShaft:
    """Bending and torsion models of one shaft and where its lobes, bearings and drive sit.

    The force stations are the lobes, then the drive (``lobe_nodes``, ``drive_node``);
    ``bearing_positions``/``lobe_positions``/``drive_position`` [m] as given."""

    beam: BeamShaft
    torsion: TorsionShaft
    lobe_nodes: np.ndarray
    drive_node: int
    bearing_positions: tuple[float, ...]
    lobe_positions: tuple[float, ...]
    drive_position: float


def elastic_shaft(bearing_positions, lobe_positions, drive_position: float,
                  section: ShaftSection, *, bearing_stiffness=math.inf, bearing_damping=0.0,
                  damping_ratio: float = 0.0, lobe_mass: float = 0.0, lobe_inertia: float = 0.0,
                  drive_stiffness: float = math.inf, drive_inertia: float = 0.0,
                  nodes_per_span: int = 0) -> ElasticShaft:
    """Stations at the bearings, the lobes and the drive (plus ``nodes_per_span`` per interval),
    the bending model on the bearing springs and the torsion model turned by the drive."""
    lobes = [float(z) for z in lobe_positions]
    st = stations(bearing_positions, lobes + [float(drive_position)], nodes_per_span)
    lobe_nodes = st.force_nodes[:len(lobes)]
    drive_node = int(st.force_nodes[-1])
    masses = np.zeros(st.positions.size)
    np.add.at(masses, lobe_nodes, lobe_mass)
    beam = beam_shaft(st, section, bearing_stiffness, bearing_damping, damping_ratio, masses)
    inertias = np.zeros(st.positions.size)
    np.add.at(inertias, lobe_nodes, lobe_inertia)
    inertias[drive_node] += drive_inertia
    torsion = torsion_shaft(st, section, drive_node, inertias, damping_ratio, drive_stiffness)
    return ElasticShaft(beam, torsion, lobe_nodes, drive_node,
                        tuple(float(z) for z in bearing_positions), tuple(lobes),
                        float(drive_position))


def shaft_answer(shaft: ElasticShaft, positions, fx, fy, lobe_torques, omega: float, *,
                 split: str = "elastic", response: str = "dynamic", overhang: str = "nearest",
                 speed_amplitude: float = 0.0, speed_order: int = 0,
                 theta=None) -> ElasticCamshaft:
    """The shaft's periodic answer to the forces ``fx``, ``fy`` (n_forces, n) [N] at
    ``positions`` [m] (the lobes first, in the order of ``shaft.lobe_positions``, then e.g. the
    drive's hub load) and the lobes' torques (n_lobes, n) [N m] (the torque each lobe takes to
    turn; it loads the shaft against the rotation). A drive speed oscillation (Williams eq.
    A6.5) has its phase from the first angle of ``theta`` (default: 0)."""
    fx = np.atleast_2d(np.asarray(fx, dtype=float))
    fy = np.atleast_2d(np.asarray(fy, dtype=float))
    n = fx.shape[-1]
    n_lobes = len(shaft.lobe_positions)
    quasi = response == "quasi_static"
    # the shaft model's force stations: lobes, then the drive; forces beyond the lobes (the hub
    # load) act at the drive station
    at_stations_x = np.zeros((n_lobes + 1, n))
    at_stations_y = np.zeros((n_lobes + 1, n))
    at_stations_x[:n_lobes], at_stations_y[:n_lobes] = fx[:n_lobes], fy[:n_lobes]
    at_stations_x[n_lobes] = fx[n_lobes:].sum(axis=0)
    at_stations_y[n_lobes] = fy[n_lobes:].sum(axis=0)
    bend = bending_response(shaft.beam, at_stations_x, at_stations_y, omega, quasi_static=quasi)
    dx, dy = bend.deflection_x[shaft.lobe_nodes], bend.deflection_y[shaft.lobe_nodes]
    bx, by = bend.bearing_x, bend.bearing_y
    if split != "elastic":
        limit = bearing_split(split, shaft.bearing_positions, list(positions), fx, fy, overhang)
        bx, by = limit.bearing_x, limit.bearing_y
    torques = np.zeros((n_lobes + 1, n))
    if len(lobe_torques):
        torques[:n_lobes] = -np.asarray(lobe_torques, dtype=float)
    accel = None
    if speed_amplitude > 0:
        grid = np.arange(n) * 2.0 * math.pi / n if theta is None else theta - theta[0]
        accel = drive_acceleration(grid, omega, speed_amplitude, speed_order)
    twist = torsion_response(shaft.torsion, torques, omega, drive_accel=accel)
    return ElasticCamshaft(bx, by, dx, dy, twist[shaft.lobe_nodes], split)
