"""Deck sections of the piston assembly (engine decks): compression rings, the gas labyrinth, the
oil-control ring, the skirt, the liner temperatures and the oil's viscosity law (Yang 1992
Part III, App. D). Part of the engine deck schema; values in the model are SI (temperatures
degC, as the source gives them).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import option, quantity, section
from camtrain.errors import Problem


@dataclass(frozen=True, kw_only=True)
class PistonRingSection:
    """One compression ring, top ring first (Yang App. D.2)."""

    height: float = quantity("Ring face height (axial face width) b", "mm", gt=0, lt=20,
                             example=1.484)
    face_radius: float = quantity("Crown radius R_r of the parabolic (barrel) face", "m", gt=0,
                                  example=0.063)
    offset: float = quantity(
        "Offset of the crown O/(b/2): 0 symmetric barrel, > 0 towards the chamber, < 0 "
        "towards the crankcase (taper faces)", "-", default=0.0, ge=-1, le=1)
    tension: float = quantity("Elastic tension as a pressure on the face", "MPa", ge=0,
                              lt=100, example=0.200)
    roughness: float = quantity("Rms roughness of the ring face", "µm", ge=0, lt=100,
                                example=0.72)
    gap: float = quantity("Ring end gap (closed, in the bore)", "mm", gt=0, lt=10,
                          example=0.4628)
    groove_position: float = quantity(
        "Distance from the ring groove to the gudgeon-pin axis (Yang App. D.2)", "mm", gt=0,
        example=25.28)
    groove_temperatures: tuple[float, ...] = quantity(
        "Groove temperature at each of piston.temperatures.speeds", "°C", gt=-50, lt=600,
        min_items=1, example=[195.0])


@dataclass(frozen=True, kw_only=True)
class GasSection:
    """The ring pack's gas path (Yang §5.2): ring gaps as orifices into the inter-ring volumes.
    The source gives the gap, the radial clearance and the ring separation but neither the
    orifice area nor the volumes: by default area = gap x radial clearance and volume =
    pi D x radial clearance x separation (flagged in the run's warnings)."""

    radial_clearance: float = quantity("Mean piston radial clearance (land to liner)", "mm",
                                       gt=0, lt=5, example=0.22785)
    separations: tuple[float, ...] = quantity(
        "Axial separation between successive compression rings (N-1 values)", "mm", gt=0,
        lt=100, min_items=1, example=[4.046])
    volumes: tuple[float, ...] | None = quantity(
        "Inter-ring volumes (N-1 values); omit for pi D x clearance x separation (not in the "
        "source)", "mm³", default=None, gt=0, min_items=1)
    orifice_areas: tuple[float, ...] | None = quantity(
        "Gap orifice area per ring (N values); omit for gap x radial clearance (not in the "
        "source)", "mm²", default=None, gt=0, min_items=1)
    heat_ratio: float = quantity("Ratio of specific heats k", "-", default=1.3, gt=1, lt=2)
    discharge: float = quantity("Orifice discharge coefficient K_c", "-", default=0.65, gt=0,
                                le=1)
    gas_constant: float = quantity("Specific gas constant R of the blow-by gas", "J/(kg·K)",
                                   default=287.0, gt=0)
    crankcase_pressure: float = quantity("Crankcase pressure, gauge", "Pa", default=0.0,
                                         gt=-1e5, lt=1e6)


@dataclass(frozen=True, kw_only=True)
class OilControlRingSection:
    """The oil-control ring: boundary friction under its tension (Yang §5.5)."""

    height: float = quantity("Rail contact height b_ocr", "mm", gt=0, lt=20, example=0.5)
    tension: float = quantity("Elastic tension as a pressure on the face T_ocr", "MPa", gt=0,
                              lt=100, example=1.890)
    friction_coefficient: float = quantity("Boundary friction coefficient", "-", default=0.08,
                                           gt=0, lt=1)


@dataclass(frozen=True, kw_only=True)
class SkirtSection:
    """The piston skirt, a concentric Couette film (Yang eq. 5.37). The source gives no skirt
    geometry: every field is required; without the section the skirt is skipped (warning)."""

    height: float = quantity("Skirt height L_s", "mm", gt=0, lt=500, example=30.0)
    depth: float = quantity("Distance of the skirt's middle below the top ring (its oil "
                            "temperature is the liner's there)", "mm", ge=0, example=30.0)
    positions: tuple[float, ...] = quantity(
        "Positions along the skirt, 0 to the skirt height, where the clearance is given", "mm",
        ge=0, min_items=2, example=[0.0, 30.0])
    clearances: tuple[float, ...] = quantity("Radial clearance at each position", "µm", gt=0,
                                             min_items=2, example=[20.0, 20.0])

    def problems(self, path: str) -> list[Problem]:
        out = []
        if len(self.positions) != len(self.clearances):
            out.append(Problem(f"{path}.clearances", f"has {len(self.clearances)} values but "
                               f"positions has {len(self.positions)}", None,
                               "one clearance per position"))
        x = self.positions
        if x[0] != 0.0 or abs(x[-1] - self.height) > 1e-12 or any(
                b <= a for a, b in zip(x[:-1], x[1:], strict=True)):
            out.append(Problem(f"{path}.positions", "must increase from 0 to the skirt height",
                               [round(v * 1e3, 6) for v in x],
                               f"0 ... {self.height * 1e3:g} mm, increasing"))
        return out


@dataclass(frozen=True, kw_only=True)
class TemperatureSection:
    """Estimated temperatures against engine speed (Yang App. D.3), interpolated linearly in
    speed (held beyond the ends). The liner profile is the quadratic through its top, middle and
    bottom values (the top ring's TDC position, mid-stroke, BDC position)."""

    speeds: tuple[float, ...] = quantity("Engine speeds of the table, increasing", "rpm", gt=0,
                                         min_items=1, example=[3000.0])
    chamber: tuple[float, ...] = quantity("Mean combustion-chamber gas temperature", "°C",
                                          gt=-50, lt=3000, min_items=1, example=[750.0])
    liner_top: tuple[float, ...] = quantity("Liner temperature at the top ring's TDC position",
                                            "°C", gt=-50, lt=600, min_items=1, example=[185.0])
    liner_middle: tuple[float, ...] = quantity("Liner temperature at mid-stroke", "°C", gt=-50,
                                               lt=600, min_items=1, example=[170.0])
    liner_bottom: tuple[float, ...] = quantity(
        "Liner temperature at the top ring's BDC position", "°C", gt=-50, lt=600, min_items=1,
        example=[160.0])

    def problems(self, path: str) -> list[Problem]:
        n = len(self.speeds)
        out = [Problem(f"{path}.{name}", f"has {len(getattr(self, name))} values but speeds "
                       f"has {n}", None, "one value per speed")
               for name in ("chamber", "liner_top", "liner_middle", "liner_bottom")
               if len(getattr(self, name)) != n]
        if any(b <= a for a, b in zip(self.speeds[:-1], self.speeds[1:], strict=True)):
            out.append(Problem(f"{path}.speeds", "must increase", None, "increasing speeds"))
        return out


@dataclass(frozen=True, kw_only=True)
class RingOilSection:
    """The oil's viscosity against temperature (Yang App. D.4 prints two points, no law)."""

    law: Literal["exponential", "vogel"] = option(
        "exponential: ln eta linear in T through the first and last points; vogel: "
        "ln eta = A + B/(T + C) through three points", default="exponential")
    temperatures: tuple[float, ...] = quantity("Temperatures of the measured viscosities",
                                               "°C", gt=-50, lt=400, min_items=2, max_items=3,
                                               example=[95.0, 135.0])
    viscosities: tuple[float, ...] = quantity("Dynamic viscosity at each temperature", "Pa·s",
                                              gt=0, min_items=2, max_items=3,
                                              example=[0.009865, 0.005123])

    def problems(self, path: str) -> list[Problem]:
        out = []
        if len(self.temperatures) != len(self.viscosities):
            out.append(Problem(f"{path}.viscosities", f"has {len(self.viscosities)} values but "
                               f"temperatures has {len(self.temperatures)}", None,
                               "one viscosity per temperature"))
        if self.law == "vogel" and len(self.temperatures) != 3:
            out.append(Problem(f"{path}.temperatures", "the vogel law needs three points",
                               len(self.temperatures), "3 temperatures"))
        t = self.temperatures
        if any(b <= a for a, b in zip(t[:-1], t[1:], strict=True)):
            out.append(Problem(f"{path}.temperatures", "must increase", None,
                               "increasing temperatures"))
        return out


@dataclass(frozen=True, kw_only=True)
class PistonSolverSection:
    """Resolution knobs and model options of the piston assembly (see `camtrain accuracy`)."""

    crank_step: float = quantity("Crank-angle step of the gas and ring marches (Yang: 1)",
                                 "deg", default=1.0, gt=0.05, le=5)
    gas_march: Literal["trapezoid", "lsoda"] = option(
        "Gas march: trapezoid (Yang eq. 6.1, implicit, conserves mass) or lsoda (scipy, "
        "adaptive reference)", default="trapezoid")
    gas_tolerance: float = quantity("Gas iteration and cyclic tolerance (relative)", "-",
                                    default=1e-6, gt=0, lt=0.1)
    ring_march: Literal["trapezoid", "backward_euler"] = option(
        "Ring film march: trapezoid (Yang eq. 5.29, order 2) or backward_euler (order 1)",
        default="trapezoid")
    ring_tolerance: float = quantity("Cyclic tolerance on the ring film (relative)", "-",
                                     default=1e-4, gt=0, lt=0.1)
    pass_mode: Literal["converged", "yang1992"] = option(
        "Starved passes of the ring pack: converged (repeated until the pack's fixed point, "
        "within pass_tolerance) or yang1992 (exactly `passes` of them, Table 6.1)",
        default="converged")
    pass_tolerance: float = quantity(
        "Converged passes: largest change of a ring's films and of the layer it leaves between "
        "two passes (relative to their largest value)", "-", default=1e-3, gt=0, lt=0.5)
    max_passes: int = quantity("Converged passes: most starved passes before giving up", "-",
                               default=60, ge=2, le=500)
    passes: int = quantity("yang1992 passes: starved passes after the flooded one (Yang "
                           "Table 6.1: 2)", "-",
                           default=2, ge=0, le=10)
    roughness_rule: Literal["rms", "sum"] = option(
        "Composite ring/liner roughness for the boundary switch: rms or sum", default="rms")
    power_mean: Literal["time", "yang1992"] = option(
        "Cycle-mean power: time (divide by the 4 pi cycle) or yang1992 (the printed 2 pi of "
        "eq. 5.32, twice the time mean)", default="time")
    boundary_friction: float = quantity("Ring friction coefficient below the roughness", "-",
                                        default=0.08, gt=0, lt=1)


@dataclass(frozen=True, kw_only=True)
class PistonSection:
    """The piston assembly of every cylinder (Yang 1992 Part III)."""

    rings: tuple[PistonRingSection, ...] = section(
        "Compression rings, top first, one [[piston.rings]] each", required=True)
    gas: GasSection = section("Gas path through the ring gaps", required=True)
    oil_control_ring: OilControlRingSection | None = section(
        "Oil-control ring (boundary friction); omit to leave it out")
    skirt: SkirtSection | None = section(
        "Skirt geometry (not in the source); omit to skip the skirt with a warning")
    temperatures: TemperatureSection = section("Chamber and liner temperatures against speed",
                                               required=True)
    oil: RingOilSection = section("Viscosity-temperature law of the oil", required=True)
    liner_roughness: float = quantity("Rms roughness of the liner", "µm", ge=0, lt=100,
                                      example=0.70)
    solver: PistonSolverSection = section("Resolution and options",
                                          default=PistonSolverSection())

    def problems(self, path: str) -> list[Problem]:
        out = []
        n = len(self.rings)
        if n < 2:
            out.append(Problem(f"{path}.rings", f"has {n} ring", n, "at least 2 compression "
                               "rings (one inter-ring volume)"))
            return out
        if len(self.gas.separations) != n - 1:
            out.append(Problem(f"{path}.gas.separations", f"has {len(self.gas.separations)} "
                               f"values for {n} rings", None, f"{n - 1} (one per pair)"))
        for name, want in (("volumes", n - 1), ("orifice_areas", n)):
            got = getattr(self.gas, name)
            if got is not None and len(got) != want:
                out.append(Problem(f"{path}.gas.{name}", f"has {len(got)} values for {n} rings",
                                   None, f"{want} values"))
        nt = len(self.temperatures.speeds)
        for i, ring in enumerate(self.rings):
            if len(ring.groove_temperatures) != nt:
                out.append(Problem(f"{path}.rings[{i}].groove_temperatures",
                                   f"has {len(ring.groove_temperatures)} values but "
                                   f"temperatures.speeds has {nt}", None, "one per speed"))
            if i and not ring.groove_position < self.rings[i - 1].groove_position:
                out.append(Problem(f"{path}.rings[{i}].groove_position", "is not below the "
                                   "ring above (nearer the pin)",
                                   f"{ring.groove_position * 1e3:g} mm",
                                   f"< {self.rings[i - 1].groove_position * 1e3:g} mm"))
        return out
