"""Engine deck: the big-end and main bearings and the crank-bearing solver (Yang 1992 §1.3, §2).

Viscosity is given per engine speed (Yang App. B.6 lists an effective viscosity for each speed,
from the bearing maker's heat balance); between listed speeds it is interpolated linearly.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import option, quantity, section
from camtrain.deck.schema_bearing_model import (
    BearingCavitation,
    BearingModelName,
    cavitation_field,
    model_field,
    n_theta_field,
    n_z_field,
)
from camtrain.deck.schema_journal import clearance_field, diameter_field, length_field
from camtrain.errors import Problem
from camtrain.units import from_si


@dataclass(frozen=True, kw_only=True)
class CrankBearingSection:
    """One crankshaft bearing (every big-end alike, or every main alike)."""

    diameter: float = diameter_field(example=203.2)
    length: float = length_field(example=57.15)
    clearance: float = clearance_field(example=0.08255)
    grooving: Literal["none", "central", "partial"] = option(
        "none (full length), central (a full circumferential groove: two lands, each a short "
        "bearing carrying half the load) or partial (the mean of the two extremes, as Yang's "
        "FLAME program)", default="none")
    groove_width: float = quantity("Width of the central groove (central and partial)", "mm",
                                   default=0.0, ge=0)
    viscosity: tuple[float, ...] = quantity(
        "Effective oil viscosity; one value, or one per speed in viscosity_speeds", "Pa·s",
        gt=0, min_items=1, example=[0.015])
    viscosity_speeds: tuple[float, ...] = quantity(
        "Engine speeds of the viscosity values (empty with one viscosity)", "rpm", default=(),
        gt=0)

    def problems(self, path: str) -> list[Problem]:
        out = []
        if self.grooving != "none" and not self.groove_width > 0:
            out.append(Problem(f"{path}.groove_width", "a grooved bearing needs a groove width",
                               0, "> 0 mm"))
        if self.groove_width >= self.length:
            out.append(Problem(f"{path}.groove_width", "leaves no land",
                               f"{from_si(self.groove_width, 'mm'):g} mm",
                               f"< the length {from_si(self.length, 'mm'):g} mm"))
        n, m = len(self.viscosity), len(self.viscosity_speeds)
        if n > 1 and m != n:
            out.append(Problem(f"{path}.viscosity_speeds", f"has {m} speeds for {n} "
                               "viscosities", None, "one speed per viscosity value"))
        if m and n == 1 and m != 1:
            out.append(Problem(f"{path}.viscosity", "one value for several speeds", None,
                               "one viscosity per speed in viscosity_speeds"))
        sp = self.viscosity_speeds
        if any(b <= a for a, b in zip(sp, sp[1:], strict=False)):
            out.append(Problem(f"{path}.viscosity_speeds", "must increase", None,
                               "speeds in increasing order"))
        return out

    def viscosity_at(self, omega: float) -> float:
        """Effective viscosity [Pa s] at engine speed ``omega`` [rad/s] (linear in speed)."""
        if len(self.viscosity) == 1:
            return self.viscosity[0]
        import numpy as np

        return float(np.interp(omega, self.viscosity_speeds, self.viscosity))

    def speed_problems(self, rpm: float, path: str) -> list[Problem]:
        sp = [from_si(s, "rpm") for s in self.viscosity_speeds]
        if len(self.viscosity) > 1 and not (sp[0] * (1 - 1e-9) <= rpm <= sp[-1] * (1 + 1e-9)):
            return [Problem(f"{path}.viscosity_speeds", "do not cover the run speed",
                            f"{rpm:g} rpm", f"{sp[0]:g} to {sp[-1]:g} rpm (no extrapolation)")]
        return []


@dataclass(frozen=True, kw_only=True)
class EngineBearingsSection:
    """The big-end bearing (every rod) and the main bearing (every main)."""

    big_end: CrankBearingSection = section("Big-end bearing (the same on every rod)",
                                           required=True)
    main: CrankBearingSection = section("Main bearing (the same at every bay end)",
                                        required=True)

    def speed_problems(self, rpm: float, path: str) -> list[Problem]:
        return (self.big_end.speed_problems(rpm, f"{path}.big_end")
                + self.main.speed_problems(rpm, f"{path}.main"))


@dataclass(frozen=True, kw_only=True)
class EngineSolver:
    """Models and resolution knobs (see `camtrain accuracy`)."""

    crank_step: float = quantity("Crank-angle step of the load diagrams and orbits", "deg",
                                 default=0.5, gt=0, le=30)
    pressure_interpolation: Literal["periodic_cubic", "linear"] = option(
        "Cylinder pressure between table angles: periodic cubic spline (smooth loads) or "
        "linear (Yang's program)", default="periodic_cubic")
    rod_speed: Literal["small_angle", "exact"] = option(
        "Crank-pin speed relative to the rod: Yang's small-angle eq. 2.1 or the exact rod "
        "swing", default="small_angle")
    methods: tuple[str, ...] = option(
        "Which columns to compute: dynamic (mobility orbit), steady (quasi-static locus), "
        "petroff (concentric)", default=("dynamic", "steady", "petroff"))
    bearing_model: BearingModelName = model_field()
    bearing_cavitation: BearingCavitation = cavitation_field()
    bearing_n_theta: int = n_theta_field()
    bearing_n_z: int = n_z_field()
    mobility: Literal["exact", "booker"] = option(
        "Short-bearing mobility: exact pi-film inversion or Booker's closed form (Yang eqs "
        "1.15/1.16)", default="exact")
    mobility_factor: Literal["as_printed", "yang1992_program"] = option(
        "as_printed: the physics of Yang's printed equations (default); yang1992_program: "
        "half the mobility (= twice the viscosity), which his program must have used to give "
        "his printed films (compatibility option, docs/engine.md)", default="as_printed")
    film: Literal["2pi", "pi"] = option(
        "Shear film for power: 2pi = complete film (Yang's Tables 2.1-2.4) or pi",
        default="2pi")
    terms: Literal["shear", "all"] = option(
        "Power terms: shear only (Yang's tables) or shear plus the translatory term",
        default="shear")
    start: Literal["centre", "steady"] = option(
        "Start of the orbit march: the bush centre (Yang) or the steady position",
        default="centre")
    step_tolerance: float = quantity("Absolute error per time step on the eccentricity ratio",
                                     default=1e-7, gt=0, lt=0.01)
    period_tolerance: float = quantity(
        "Cycle-to-cycle change of the eccentricity ratio that counts as periodic",
        default=1e-5, gt=0, lt=0.1)
    max_cycles: int = quantity("Most engine cycles marched before giving up", default=20,
                               ge=2, le=1000)

    def problems(self, path: str) -> list[Problem]:
        known = ("dynamic", "steady", "petroff")
        bad = [m for m in self.methods if m not in known]
        if bad or not self.methods:
            return [Problem(f"{path}.methods", "unknown or empty method list", bad or "[]",
                            "some of " + ", ".join(known))]
        step = math.degrees(self.crank_step)
        n = 360.0 / step
        if abs(n - round(n)) > 1e-6 or round(n) < 8:
            return [Problem(f"{path}.crank_step", "does not divide a revolution into whole "
                            "steps", f"{step:g} deg", "a divisor of 360 deg (e.g. 0.5, 1, 2)")]
        return []
