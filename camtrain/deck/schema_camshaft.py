"""Deck sections of the camshaft: lobes, bearings, drive, dampers. Part of the deck schema."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import WhenItem, option, quantity, section
from camtrain.deck.schema_bearing_model import (
    BearingCavitation,
    BearingModelName,
    cavitation_field,
    model_field,
    n_theta_field,
    n_z_field,
)
from camtrain.deck.schema_flexibility import CamshaftFlexibility
from camtrain.deck.schema_journal import (
    bearing_geometry_problems,
    clearance_field,
    diameter_field,
    groove_width_field,
    length_field,
)
from camtrain.errors import Problem
from camtrain.units import mm_text

# --------------------------------------------------------------------------- camshaft

@dataclass(frozen=True, kw_only=True)
class CamLobe:
    """One lobe on the shaft. It drives a copy of this deck's valve train (same lift law and
    mechanism), phased by its angle of maximum lift (Yang 1992 App C.5; Ball 1988 §6.3)."""

    position: float = quantity("Axial position of the lobe along the shaft (same datum as the "
                               "bearings)", "mm", example=50.4)
    max_lift_angle: float = quantity(
        "Camshaft angle at which this lobe is at maximum lift (from firing order and valve "
        "timing); 0 = the deck's lift law as given", "deg", default=0.0, ge=-360, le=360)
    follower_axis_angle: float = quantity(
        "Direction from the shaft axis to this lobe's follower in the bearing frame (x normal to "
        "the bore axis, y along it): 90 = straight up the bore, less/more by the valve "
        "inclination or the V half angle", "deg", default=90.0, ge=-360, le=360)
    bank: Literal[1, 2] = option(
        "Bank of a V engine; bank-2 lobes sit on the other bank's shaft (torque only, shifted by "
        "half the V angle)", default=1)


@dataclass(frozen=True, kw_only=True)
class CamBearing:
    """One plain camshaft bearing (a full central groove makes two lands)."""

    position: float = quantity("Axial position of the bearing centre", "mm", example=0.0)
    diameter: float = diameter_field(example=25.97)
    length: float = length_field(example=17.0)
    clearance: float = clearance_field(example=0.0225)
    groove_width: float = groove_width_field()

    def problems(self, path: str) -> list[Problem]:
        return bearing_geometry_problems(self, path)


@dataclass(frozen=True, kw_only=True)
class CamDrive:
    """Belt, chain or gear drive of the camshaft: its hub load goes to the bearings."""

    type: Literal["belt", "chain", "gear"] = option(
        "Drive type (all modelled by the same hub-load balance)", default="belt")
    position: float = quantity("Axial position of the pulley, sprocket or gear", "mm",
                               example=-40.0)
    radius: float = quantity("Pitch radius of the pulley, sprocket or gear", "mm", gt=0,
                             example=60.0)
    hub_load_angle: float = quantity(
        "Direction of the hub load (the pull of the spans) in the bearing frame", "deg",
        default=90.0, ge=-360, le=360)
    preload: float = quantity("Slack-side (tensioner) preload; hub load = |T|/r + 2 preload",
                              "N", default=0.0, ge=0)


@dataclass(frozen=True, kw_only=True)
class CamDamper:
    """Centrifugal pendulum dampers tuned to torque orders (Williams 2013 ch 10)."""

    orders: tuple[float, ...] = quantity("Orders to cancel (whole numbers)", "-", gt=0, le=100,
                                         min_items=1, max_items=8, example=[4, 8])
    count: int = quantity("Pendulums per order", "-", default=2, ge=1, le=64)
    mass: float = quantity("Mass of one pendulum", "kg", gt=0, example=0.1)
    pivot_radius: float = quantity("Radius of the pendulum pivot from the shaft axis, R", "mm",
                                   gt=0, example=30.0)
    tuning_margin: float = quantity(
        "Tuning margin: pendulum length r from R/r = n^2 (1 + margin), slightly above exact "
        "tuning (Williams eq. 10.57)", "%", default=5.0, gt=0, lt=100)

    def problems(self, path: str) -> list[Problem]:
        return [Problem(f"{path}.orders[{i}]", "must be a whole number", n, "1, 2, 3, ...")
                for i, n in enumerate(self.orders) if n != int(n)]


@dataclass(frozen=True, kw_only=True)
class Camshaft:
    """The camshaft (issue 8): lobes, bearings, drive, banks, torque orders, bearing orbits."""

    lobes: tuple[CamLobe, ...] = section("Lobes on the shaft, one [[camshaft.lobes]] each",
                                         required=True)
    bearings: tuple[CamBearing, ...] | None = section(
        "Bearings in axial order, one [[camshaft.bearings]] each (needed for bearing loads)")
    drive: CamDrive | None = section("Drive pulley, sprocket or gear (hub load on the bearings)")
    damper: CamDamper | None = section("Pendulum dampers for chosen torque orders")
    flexibility: CamshaftFlexibility | None = section(
        "The shaft as elastic in bending and torsion (bearing reactions, deflections, twist)")
    rotation: Literal["anticlockwise", "clockwise"] = option(
        "Direction of shaft rotation in the bearing frame (x, y)", default="anticlockwise")
    v_angle: float | None = quantity(
        "V angle between the banks (crank degrees); omit for one bank", "deg", default=None,
        gt=0, lt=360)
    orders: int = quantity("Highest harmonic order reported as a metric", "-", default=12, ge=1,
                           le=100)
    overhang: Literal["nearest", "lever"] = option(
        "Forces beyond the end bearings: nearest (wholly on the end bearing, as Ball and Yang) "
        "or lever (overhung-beam statics)", default="nearest")
    viscosity: float | None = quantity(
        "Effective viscosity of the bearing oil; omit to use lubricant.viscosity", "Pa·s",
        default=None, gt=0)
    film: Literal["pi", "2pi"] = option(
        "Shear film for bearing power: 2pi = complete film (Martin 1985, Yang eq. 1.22; Ball's "
        "eq. 6.7, used by Yang for his grooved pressure-fed bearings) or pi = shear over the "
        "loaded pi film only (Booker 1965, Yang eq. 1.21; about half)", default="pi")
    method: Literal["mobility", "steady", "petroff"] = option(
        "Bearing method: mobility (Booker orbit), steady (quasi-static locus) or petroff "
        "(concentric power only)", default="mobility")
    bearing_model: BearingModelName = model_field()
    bearing_cavitation: BearingCavitation = cavitation_field()
    bearing_n_theta: int = n_theta_field()
    bearing_n_z: int = n_z_field()
    mobility: Literal["exact", "booker"] = option(
        "Mobility of the short model: exact pi-film inversion or Booker's closed form",
        default="exact")
    bearing_tolerance: float = quantity(
        "Cycle-to-cycle change of the eccentricity ratio that counts as periodic", "-",
        default=1e-5, gt=0, lt=0.1)
    max_cycles: int = quantity("Most load cycles marched before giving up", "-", default=20,
                               ge=2, le=1000)
    orbit_points: int = quantity(
        "Load-diagram angles per revolution the bearing orbits are marched on: a finer run grid "
        "is resampled onto them and the orbit interpolated back (0: march on the run's grid; "
        "check a coarser grid with camtrain accuracy --knob orbit_points)",
        "-", default=0, ge=0, le=100000)

    schema_rules = (WhenItem("lobes", "bank", (2,), require=("v_angle",)),)

    def problems(self, path: str) -> list[Problem]:
        out = []
        if not self.lobes:
            out.append(Problem(f"{path}.lobes", "has no lobes", None, "at least one lobe"))
        pos = [b.position for b in self.bearings or ()]
        for i in range(1, len(pos)):
            if not pos[i] > pos[i - 1]:
                out.append(Problem(f"{path}.bearings[{i}].position", "is not after the previous "
                                   "bearing", mm_text(pos[i]), "bearings in increasing axial order"))
        if 0 < self.orbit_points < 36:
            out.append(Problem(f"{path}.orbit_points", "is too few angles for an orbit",
                               self.orbit_points, "0 (the run's grid) or at least 36"))
        if self.v_angle is None and any(lobe.bank == 2 for lobe in self.lobes):
            out.append(Problem(f"{path}.v_angle", "is required when a lobe has bank = 2", None,
                               "the V angle in crank degrees"))
        return out
