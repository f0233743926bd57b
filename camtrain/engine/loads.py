"""Crank-train load diagrams: every big-end (rod axes) and every main bearing (block axes).

Big-end: Yang (1992) §1.2.1, eqs 1.1-1.5, from :mod:`camtrain.engine.crank`. Mains: §1.2.2,
the crankshaft cut into statically determinate bays (a simply supported rigid beam between two
mains); a force F at distance a from the front of a bay of length l puts F (1 - a/l) on the
front main and F a/l on the rear main, in x and in y. The forces on a bay are the pin force of
each of its rods (minus the big-end load, turned into block axes), the out-of-balance force
C = m r omega^2 of each crank component along its direction, and, on the last main, the
flywheel's weight. A main's load is the sum of its reactions from the two adjacent bays.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camtrain.errors import field_error

from . import crank as ck
from .model import STANDARD_GRAVITY, CrankTrain, Engine
from .pressure import PressureTable

__all__ = ["CylinderLoads", "MainLoads", "CrankLoads", "crank_grid", "cylinder_loads", "main_loads",
           "crank_train_loads"]


def crank_grid(cycle: float, step: float) -> np.ndarray:
    """Crank angles 0, step, ... over one cycle [rad]; the cycle must hold a whole number."""
    if not (step > 0 and math.isfinite(step)):
        raise field_error("engine.solver.crank_step", "must be > 0", math.degrees(step))
    n = cycle / step
    if abs(n - round(n)) > 1e-6 or round(n) < 8:
        raise field_error("engine.solver.crank_step", "must divide the cycle into a whole "
                          "number (>= 8) of steps", math.degrees(step),
                          f"a divisor of {math.degrees(cycle):g} deg")
    return np.arange(round(n)) * (cycle / round(n))


@dataclass(frozen=True)
class CylinderLoads:
    """Loads of one cylinder over the engine crank-angle grid (SI; arrays on ``angle``).

    ``local_angle`` is the cylinder's own angle from its firing TDC. ``pin_x``/``pin_y`` is the
    force of the rod on the crank pin in block axes (= minus the big-end load); ``load_x``/
    ``load_y`` is the big-end load (pin on bush) in rod axes; ``omega_journal`` the pin speed
    relative to the rod.
    """

    angle: np.ndarray
    local_angle: np.ndarray
    pressure: np.ndarray
    gas_force: np.ndarray
    reciprocating_force: np.ndarray
    axial_force: np.ndarray
    rod_force: np.ndarray
    side_thrust: np.ndarray
    psi: np.ndarray
    load_x: np.ndarray
    load_y: np.ndarray
    pin_x: np.ndarray
    pin_y: np.ndarray
    omega_journal: np.ndarray

    @property
    def load(self) -> np.ndarray:
        return np.hypot(self.load_x, self.load_y)


def cylinder_loads(crank: CrankTrain, pressure: PressureTable, firing_angle: float,
                   angle: np.ndarray, omega: float, *, interpolation: str = "periodic_cubic",
                   rod_speed: str = "small_angle") -> CylinderLoads:
    """Big-end load diagram of one cylinder (Yang eqs 1.1-1.5, rod axes, speed by eq. 2.1)."""
    theta = np.asarray(angle, dtype=float) - firing_angle
    local = np.mod(theta, crank.cycle)
    p = pressure(local, interpolation)
    R, L = crank.crank_radius, crank.rod_length
    psi = ck.rod_obliquity(theta, R, L)
    acc = ck.piston_acceleration_yang(theta, R, L, omega)
    fg = ck.gas_force(p, crank.bore)
    frec = ck.reciprocating_force(crank.piston_mass, crank.rod_mass, acc)
    fax = fg - frec
    frot = ck.rotating_force(crank.rod_mass, R, omega)
    lx, ly = ck.big_end_load_rod_frame(fax, psi, theta, frot)
    # back to block axes (rotate by -psi) and take the reaction on the pin
    c, s = np.cos(psi), np.sin(psi)
    bx, by = c * lx + s * ly, -s * lx + c * ly
    wj = ck.rod_frame_journal_speed(theta, R, L, omega, rod_speed)
    return CylinderLoads(angle=np.asarray(angle, dtype=float), local_angle=local, pressure=p,
                         gas_force=fg, reciprocating_force=frec, axial_force=fax,
                         rod_force=fax / c, side_thrust=ck.side_thrust(fax, psi), psi=psi,
                         load_x=lx, load_y=ly, pin_x=-bx, pin_y=-by, omega_journal=wj)


@dataclass(frozen=True)
class MainLoads:
    """Main-bearing loads in block axes [N], shape (n_mains, n_angles), mains front to rear.

    ``bay_x``/``bay_y`` hold each bay's applied force sum (n_bays, n_angles) and ``front``/
    ``rear`` its reactions (n_bays, 2, n_angles) for x and y, for the equilibrium checks.
    """

    angle: np.ndarray
    load_x: np.ndarray
    load_y: np.ndarray
    bay_x: np.ndarray
    bay_y: np.ndarray
    bay_moment_x: np.ndarray
    bay_moment_y: np.ndarray
    front: np.ndarray
    rear: np.ndarray

    @property
    def load(self) -> np.ndarray:
        return np.hypot(self.load_x, self.load_y)


def main_loads(engine: Engine, cylinders: list, omega: float) -> MainLoads:
    """Main-bearing load diagrams from the cylinders' pin forces (one CylinderLoads each)."""
    nb = len(engine.bay_lengths)
    angle = cylinders[0].angle
    n = angle.size
    front = np.zeros((nb, 2, n))
    rear = np.zeros((nb, 2, n))
    applied = np.zeros((nb, 2, n))
    moment = np.zeros((nb, 2, n))  # sum of a F about the bay's front main

    def put(bay: int, a: float, fx, fy):
        ell = engine.bay_lengths[bay]
        f = np.stack([np.broadcast_to(fx, (n,)), np.broadcast_to(fy, (n,))])
        front[bay] += f * (1.0 - a / ell)
        rear[bay] += f * (a / ell)
        applied[bay] += f
        moment[bay] += f * a

    for cyl, ld in zip(engine.cylinders, cylinders, strict=True):
        put(cyl.bay, cyl.position, ld.pin_x, ld.pin_y)
    w2 = omega ** 2
    for comp in engine.components:
        ang = angle + comp.angle
        c = comp.unbalance * w2
        put(comp.bay, comp.position, -c * np.sin(ang), c * np.cos(ang))
    lx = np.zeros((nb + 1, n))
    ly = np.zeros((nb + 1, n))
    lx[:-1] += front[:, 0]
    ly[:-1] += front[:, 1]
    lx[1:] += rear[:, 0]
    ly[1:] += rear[:, 1]
    ly[-1] -= engine.flywheel_mass * STANDARD_GRAVITY
    return MainLoads(angle=angle, load_x=lx, load_y=ly, bay_x=applied[:, 0],
                     bay_y=applied[:, 1], bay_moment_x=moment[:, 0], bay_moment_y=moment[:, 1],
                     front=front, rear=rear)


@dataclass(frozen=True)
class CrankLoads:
    """The crank-train load diagrams of one engine at one speed (the ``CrankLoads`` product).

    ``engine`` the crank train (SI), ``omega`` the engine speed [rad/s], ``angle`` the crank
    angle grid [rad] over one cycle (4 pi for a 4-stroke), ``cylinders`` one
    :class:`CylinderLoads` per cylinder (big-end loads in rod axes [N]), ``mains`` the
    :class:`MainLoads` (block axes [N]).
    """

    engine: Engine
    omega: float
    angle: np.ndarray
    cylinders: tuple
    mains: MainLoads


def crank_train_loads(engine: Engine, omega: float, crank_step: float, *,
                      interpolation: str = "periodic_cubic",
                      rod_speed: str = "small_angle") -> CrankLoads:
    """Every big-end and main-bearing load diagram at engine speed ``omega`` [rad/s] on a grid
    of ``crank_step`` [rad] (Yang 1992 §1.2.1-1.2.2)."""
    if not (omega > 0 and math.isfinite(omega)):
        raise field_error("speed.engine", "engine speed must be > 0", omega)
    angle = crank_grid(engine.crank.cycle, crank_step)
    cyl = tuple(cylinder_loads(engine.crank, c.pressure, c.firing_angle, angle, omega,
                               interpolation=interpolation, rod_speed=rod_speed)
                for c in engine.cylinders)
    return CrankLoads(engine, float(omega), angle, cyl, main_loads(engine, list(cyl), omega))
