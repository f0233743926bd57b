"""Deck section [roller]: the follower's roller turns on its pin (docs/rollers.md).

The roller is the curved follower face of the mechanism: its radius is the mechanism's
``follower_radius`` (the kinematics' contact radius, so the contact geometry and the roller
cannot disagree) and the contact length stays ``cam.width``. This section adds what makes it
turn: its inertia, the pin (frictionless, locked, needle bearing or plain bushing), the traction
law of the cam contact and the solver of its speed.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import option, quantity
from camtrain.errors import Problem

#: density of a steel roller [kg/m^3] (the inertia from the width when no mass is given)
STEEL_DENSITY = 7850.0


@dataclass(frozen=True, kw_only=True)
class Roller:
    """A roller on the follower: inertia, pin, traction and solver. Radius: mechanism.follower_radius."""

    width: float | None = quantity(
        "Roller width, for its inertia as a solid steel disc when neither mass nor inertia is "
        "given (the contact length stays cam.width)", "mm", default=None, gt=0, example=10.0)
    mass: float | None = quantity(
        "Roller mass (inertia m r^2 / 2 of a solid disc of the follower radius)", "kg",
        default=None, gt=0)
    inertia: float | None = quantity(
        "Roller moment of inertia about its pin; overrides mass and width", "kg·m²",
        default=None, gt=0)
    pin: Literal["needle", "bushing", "frictionless", "locked"] = option(
        "The roller's bearing on its pin: needle (catalogue friction torque M0 + M1), bushing "
        "(plain journal bearing, Ocvirk short bearing), frictionless, or locked (the roller "
        "does not turn: camtrain's non-rotating curved follower)", default="needle")
    needle_pitch_diameter: float | None = quantity(
        "Pitch diameter d_m of the needle bearing (pin diameter + needle diameter)", "mm",
        default=None, gt=0, example=8.0, applies="pin = needle")
    needle_f0: float = quantity(
        "Load-independent factor f0 of the needle bearing's friction torque (catalogue value "
        "for your bearing and lubrication; the default is a typical value, not checked against "
        "a published table)", "-", default=3.0, ge=0, le=100, applies="pin = needle")
    needle_f1: float = quantity(
        "Load factor f1 of the needle bearing's friction torque M1, f1 F d_m (default a typical "
        "catalogue value, not checked against a published table)", "-", default=0.0005, ge=0,
        le=0.1, applies="pin = needle")
    pin_diameter: float | None = quantity(
        "Pin (journal) diameter of the plain bushing", "mm", default=None, gt=0,
        applies="pin = bushing")
    pin_length: float | None = quantity(
        "Length of the plain bushing", "mm", default=None, gt=0, applies="pin = bushing")
    pin_clearance: float | None = quantity(
        "Radial clearance of the plain bushing", "µm", default=None, gt=0,
        applies="pin = bushing")
    pin_model: Literal["short", "finite"] = option(
        "Film model of the plain bushing: short (Ocvirk, closed form) or finite (the finite-length "
        "Reynolds film's steady curve, solved once per length/diameter)", default="short",
        applies="pin = bushing")
    pin_friction: Literal["hydrodynamic", "mixed"] = option(
        "Friction of the plain bushing: hydrodynamic (Couette shear of the film only) or mixed "
        "(plus Greenwood-Tripp asperity friction where the minimum film c (1 - eps) falls below "
        "3 pin_roughness, with the tribology section's asperity and boundary parameters)",
        default="hydrodynamic", applies="pin = bushing")
    pin_terms: Literal["all", "shear"] = option(
        "Friction torque of the plain bushing's film: all (Couette shear plus the pressure term "
        "W e sin(attitude)/2 on the turning roller, the standard journal-bearing friction, "
        "Raimondi & Boyd 1958; Yang 1992 eq. 1.20) or shear (the Couette term alone)",
        default="all", applies="pin = bushing")
    pin_roughness: float | None = quantity(
        "Composite RMS roughness of pin and bore, for mixed pin friction; omit for "
        "lubricant.roughness", "µm", default=None, gt=0, applies="pin = bushing")
    pin_viscosity: float | None = quantity(
        "Oil viscosity in the pin bearing; omit for lubricant.viscosity", "Pa·s", default=None,
        gt=0, applies="pin = needle, bushing")
    oil_density: float = quantity(
        "Oil density, for the needle bearing's kinematic viscosity", "kg/m³", default=850.0,
        gt=0, applies="pin = needle")
    traction: Literal["limiting_shear", "eyring", "contact"] = option(
        "Cam-roller traction: limiting_shear (Newtonian shear below tau_0 + gamma p, plus "
        "Greenwood-Tripp asperity friction, capped at the boundary coefficient), eyring (Eyring "
        "shear below the same limit), or contact (the deck's tribology.friction_model)",
        default="limiting_shear")
    rolling_resistance: Literal["goksem_hargreaves", "none"] = option(
        "Hydrodynamic rolling resistance of the cam-roller contact charged to the cam "
        "(Goksem & Hargreaves 1978), or none", default="goksem_hargreaves")
    solver: Literal["quasi_static", "inertial"] = option(
        "Roller speed: quasi_static (no inertia: traction x radius equals the pin torque per "
        "angle) or inertial (the equation of motion marched over revolutions to a periodic "
        "state)",
        default="quasi_static")
    periodic_tolerance: float = quantity(
        "Periodic state: change of the roller speed over a revolution, relative to the largest "
        "rolling speed", "-", default=1e-6, gt=0, lt=0.1, applies="solver = inertial")
    revolutions: int = quantity("Most revolutions marched to the periodic state", "-",
                                default=50, ge=1, le=10000, applies="solver = inertial")
    substeps: int = quantity("Implicit-Euler time steps per step of the cam-angle grid", "-",
                             default=4, ge=1, le=1000, applies="solver = inertial")
    table_points: int = quantity(
        "Points of the traction and pin-torque tables of the inertial march (clustered at zero "
        "sliding)", "-", default=401, ge=21, le=100001, applies="solver = inertial")
    skid_slip: float = quantity(
        "Slip above which the roller counts as skidding (the rolls/skids column)", "-",
        default=0.05, gt=0, lt=1)

    def problems(self, path: str) -> list[Problem]:
        out = []
        if self.pin == "needle" and self.needle_pitch_diameter is None:
            out.append(Problem(f"{path}.needle_pitch_diameter", "is required with pin = needle",
                               None, "the needle bearing's pitch diameter in mm"))
        if self.pin == "bushing":
            for name, what in (("pin_diameter", "the pin diameter in mm"),
                               ("pin_length", "the bushing length in mm"),
                               ("pin_clearance", "the radial clearance in µm")):
                if getattr(self, name) is None:
                    out.append(Problem(f"{path}.{name}", "is required with pin = bushing", None,
                                       what))
            if None not in (self.pin_diameter, self.pin_clearance) \
                    and self.pin_clearance >= 0.5 * self.pin_diameter:
                out.append(Problem(f"{path}.pin_clearance", "is larger than the pin radius",
                                   f"{self.pin_clearance * 1e6:g} µm", "a few µm to tens of µm"))
        return out

    def moment_of_inertia(self, radius: float, face_mass: float = 0.0) -> float:
        """J [kg m^2]: given, or m r^2/2 (m this section's mass, else face_mass, the
        mechanism.roller.mass a finger's inertia already counts), or a solid steel disc of the
        width; 0 without data."""
        if self.inertia is not None:
            return self.inertia
        mass = self.mass if self.mass is not None else (face_mass or None)
        if mass is not None:
            return 0.5 * mass * radius ** 2
        if self.width is not None:
            return 0.5 * STEEL_DENSITY * 3.141592653589793 * radius ** 4 * self.width
        return 0.0


#: mechanisms whose follower face can be a roller (a curved face with a line contact)
ROLLER_MECHANISMS = ("domed", "finger", "rocker", "pushrod")


def roller_problems(deck) -> list[Problem]:
    """Checks of [roller] against the rest of a valve-train deck."""
    r = deck.roller
    if r is None:
        return []
    out = []
    m = deck.mechanism
    if m.type not in ROLLER_MECHANISMS or m.follower_radius is None:
        out.append(Problem("mechanism.type", "a roller needs a curved follower face", m.type,
                           "domed (follower_shape = cylindrical), finger, rocker or pushrod "
                           "with mechanism.follower_radius"))
    elif m.type == "domed" and m.follower_shape != "cylindrical" and m.follower != "roller":
        out.append(Problem("mechanism.follower_shape", "a roller's face is a cylinder (a line "
                           "contact; mechanism.follower = roller with mechanism.roller."
                           "crown_radius crowns it)", m.follower_shape, "cylindrical"))
    face = getattr(m, "roller", None)
    face_mass = face.mass if face is not None else 0.0
    if r.solver == "inertial" and r.pin != "locked" and not face_mass \
            and (r.inertia, r.mass, r.width) == (None, None, None):
        out.append(Problem("roller.inertia", "the inertial solver needs the roller's inertia",
                           None, "roller.inertia, roller.mass, roller.width or "
                           "mechanism.roller.mass"))
    if deck.tribology.film_model != "steady":
        out.append(Problem("tribology.film_model", "the roller's traction uses the steady film",
                           deck.tribology.film_model, "steady (with a [roller] section)"))
    if deck.lubricant is None or deck.cam.width is None:
        out.append(Problem("roller", "needs the lubricant and the contact length", None,
                           "[lubricant] and cam.width"))
    return out
