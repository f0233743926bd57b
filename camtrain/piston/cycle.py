"""One cylinder's piston assembly over an engine cycle: gas, ring pack, oil-control ring and
skirt, each ring at the viscosity of the liner where it is (Yang 1992 Part III, §6.2).

The chain is Yang's: the inter-ring gas pressures (§5.2) from the cylinder-pressure table set the
radial load and the flank pressures of every compression ring (§5.3); the rings are marched
flooded, then starved pass by pass (§5.4, Table 6.1); the oil-control ring runs in boundary
friction and the skirt in Couette shear (§5.5). Powers are cycle means of F U.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camtrain.piston.assembly import cycle_mean_power, oil_control_ring_friction, skirt_friction
from camtrain.piston.gas import ATMOSPHERE, Labyrinth, solve_labyrinth
from camtrain.piston.pack import PackRing, solve_pack
from camtrain.piston.product import PistonFriction
from camtrain.piston.ring import Ring, composite_roughness, liner_speed, piston_position
from camtrain.piston.thermal import ViscosityLaw, liner_temperature

#: power divisors over a 4-stroke cycle: the time mean (4 pi) or Yang's printed eq. 5.32 (2 pi)
POWER_MEANS = {"time": 1.0, "yang1992": 2.0}


@dataclass(frozen=True)
class CompressionRing:
    """A compression ring of the pack: face, gap [m], depth below the top ring [m], groove
    temperature [degC]."""

    ring: Ring
    gap: float
    depth: float
    groove_temperature: float


@dataclass(frozen=True)
class PistonCase:
    """Everything one cylinder's piston assembly needs at one speed (SI; temperatures degC).

    ``volumes`` and ``areas`` of the labyrinth (None: Yang's reading, flagged: area = gap x
    radial clearance, volume = pi D c x ring separation); ``separations`` [m] between
    successive rings for that default volume; ``liner_temperatures`` (top, middle, bottom);
    ``skirt_depth`` [m] the skirt's middle below the top ring (its viscosity is taken there).
    """

    bore: float
    crank_radius: float
    rod_length: float
    rings: tuple
    radial_clearance: float
    separations: tuple
    chamber_temperature: float
    liner_temperatures: tuple
    viscosity: ViscosityLaw
    liner_roughness: float
    volumes: tuple | None = None
    areas: tuple | None = None
    k: float = 1.3
    discharge: float = 0.65
    gas_constant: float = 287.0
    crankcase_pressure: float = 0.0
    ocr_tension: float | None = None
    ocr_height: float | None = None
    ocr_friction: float = 0.08
    skirt_height: float | None = None
    skirt_depth: float = 0.0
    skirt_x: tuple | None = None
    skirt_clearance: tuple | None = None

    def labyrinth(self) -> Labyrinth:
        """The gas path of the ring pack (Yang §5.2)."""
        areas = self.areas or tuple(r.gap * self.radial_clearance for r in self.rings)
        volumes = self.volumes or tuple(math.pi * self.bore * self.radial_clearance * s
                                        for s in self.separations)
        temps = tuple(273.15 + 0.5 * (a.groove_temperature + b.groove_temperature)
                      for a, b in zip(self.rings[:-1], self.rings[1:], strict=True))
        return Labyrinth(areas=tuple(areas), volumes=tuple(volumes), temperatures=temps,
                         k=self.k, discharge=self.discharge, gas_constant=self.gas_constant,
                         p_below=ATMOSPHERE + self.crankcase_pressure)

    def eta(self, depth: float, theta):
        """Oil viscosity [Pa s] under a ring ``depth`` below the top ring at crank angles
        ``theta`` (liner temperature where the ring is)."""
        travel = piston_position(theta, self.crank_radius, self.rod_length) + depth
        t = liner_temperature(travel, 2.0 * self.crank_radius, *self.liner_temperatures)
        return self.viscosity(t)


@dataclass(frozen=True)
class PistonOptions:
    """Resolution knobs and model options: crank ``step`` [rad] (Yang 1 deg), gas march and
    tolerance, ring march and tolerance, the starved passes (``pass_mode`` ``converged``: until
    the pack's fixed point within ``pass_tolerance``, at most ``max_passes``; ``yang1992``:
    ``passes`` of them, Table 6.1), roughness rule, power mean."""

    step: float = math.radians(1.0)
    gas_march: str = "trapezoid"
    gas_tolerance: float = 1e-6
    ring_march: str = "trapezoid"
    ring_tolerance: float = 1e-4
    passes: int = 2
    pass_mode: str = "converged"
    pass_tolerance: float = 1e-3
    max_passes: int = 60
    roughness_rule: str = "rms"
    power_mean: str = "time"
    boundary_friction: float = 0.08


def solve_piston(case: PistonCase, pressure, omega: float, cylinders: int = 1,
                 options: PistonOptions | None = None) -> PistonFriction:
    """Gas, rings, OCR and skirt of one cylinder at engine speed ``omega`` [rad/s].

    ``pressure(theta)`` is the cylinder's gauge pressure [Pa] at crank angles [rad] from firing
    TDC (periodic over 4 pi).
    """
    opt = options or PistonOptions()
    if opt.power_mean not in POWER_MEANS:
        raise ValueError(f"unknown power mean {opt.power_mean!r}; expected one of "
                         f"{tuple(POWER_MEANS)}")
    period = 4.0 * math.pi
    n = int(round(period / opt.step))
    grid = np.linspace(0.0, period, n, endpoint=False)
    p_abs = np.asarray(pressure(grid), dtype=float) + ATMOSPHERE
    gas = solve_labyrinth(grid, p_abs, 273.15 + case.chamber_temperature, case.labyrinth(),
                          omega, period=period, step=period / n, method=opt.gas_march,
                          tolerance=opt.gas_tolerance)
    theta = gas.theta[:-1]
    gauge = gas.pressures[:, :-1] - ATMOSPHERE
    U = liner_speed(theta, case.crank_radius, case.rod_length, omega)
    pack = [PackRing(r.ring, r.depth, gauge[i], gauge[i + 1], case.eta(r.depth, theta),
                     composite_roughness(r.ring.roughness, case.liner_roughness,
                                         opt.roughness_rule))
            for i, r in enumerate(case.rings)]
    travel = piston_position(theta, case.crank_radius, case.rod_length)
    sol = solve_pack(pack, theta, U, travel, omega, passes=opt.passes, pass_mode=opt.pass_mode,
                     pass_tolerance=opt.pass_tolerance, max_passes=opt.max_passes,
                     scheme=opt.ring_march, tolerance=opt.ring_tolerance)
    circumference = math.pi * case.bore
    scale = POWER_MEANS[opt.power_mean]
    ring_force = tuple(rc.friction * circumference for rc in sol.starved)
    ring_power = tuple(scale * cycle_mean_power(f, U) for f in ring_force)
    ocr = skirt = None
    ocr_power, skirt_power = 0.0, None
    if case.ocr_tension is not None:
        ocr = oil_control_ring_friction(U, case.ocr_tension, case.ocr_height, case.bore,
                                        case.ocr_friction)
        ocr_power = scale * cycle_mean_power(ocr, U)
    if case.skirt_height is not None:
        eta_skirt = case.eta(case.skirt_depth, theta)   # liner temperature at mid-skirt
        skirt = skirt_friction(U, eta_skirt, case.bore, case.skirt_height, case.skirt_x,
                               case.skirt_clearance)
        skirt_power = scale * cycle_mean_power(skirt, U)
    return PistonFriction(theta, float(omega), U, gas, sol, ring_force, ocr, skirt, ring_power,
                          float(ocr_power), skirt_power, int(cylinders), period / scale)
