"""The valve-train deck: every section and field, with its unit, range and prompt.

This module is the single description of a deck. Validation, the SI model, the commented
templates (`camtrain template`) and the JSON Schema (`camtrain schema`) are all derived from it.
Field docs are written as prompts, in the spirit of Ball's (1988) template input file.
Values in the model are SI; units below are the units written in the deck.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

from camtrain.catalogue import effect_names
from camtrain.deck.fields import ExactlyOne, When, option, quantity, section
from camtrain.deck.schema_lift import (  # noqa: F401
    DEFERRED_FORMS,
    LIFT_FORMS,
    FourPower,
    Lift,
    Ramps,
)
from camtrain.deck.schema_tribology import (  # noqa: F401
    Clearance,
    Limits,
    Lubricant,
    Masses,
    Materials,
    Solver,
    Spring,
    Tribology,
)
from camtrain.errors import Problem
from camtrain.lazy import resolve
from camtrain.units import from_si, mm_text

if TYPE_CHECKING:   # deferred sections (fields.section(schema=...)): imported when a deck has them
    from camtrain.deck.schema_camshaft import Camshaft
    from camtrain.deck.schema_design import Design
    from camtrain.deck.schema_desmodromic import ClosingPair
    from camtrain.deck.schema_dynamics import Dynamics
    from camtrain.deck.schema_follower import ArmContacts, Dyson, Layout, RollerFace
    from camtrain.deck.schema_guides import Guides
    from camtrain.deck.schema_pushrod import Pushrod
    from camtrain.deck.schema_roller import Roller

#: the classes of the deferred sections, still one schema namespace: ``schema.Camshaft`` imports
#: its module on first use (PEP 562)
DEFERRED = {name: f"camtrain.deck.{module}:{name}" for module, names in (
    ("schema_camshaft", ("CamBearing", "CamDamper", "CamDrive", "CamLobe", "Camshaft")),
    ("schema_design", ("Design",)), ("schema_desmodromic", ("ClosingPair",)),
    ("schema_dynamics", ("Dynamics",)), ("schema_guides", ("Guides",)),
    ("schema_pushrod", ("Pushrod",)),
    ("schema_follower", ("ArmContacts", "Dyson", "Layout", "RollerFace")),
    ("schema_roller", ("Roller",))) for name in names} | DEFERRED_FORMS


def __getattr__(name: str):
    if name in DEFERRED:
        return resolve(DEFERRED[name])
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

MECHANISMS = ("flat", "domed", "finger", "rocker", "pushrod", "desmodromic")
PIVOTED = ("finger", "rocker")
#: mechanisms whose follower on the cam may be a roller
ROLLER_CARRIERS = ("domed", "finger", "rocker", "pushrod")
DYSON_KEYS = ("A", "B", "D", "kappa", "lambda_")


# --------------------------------------------------------------------------- speed

@dataclass(frozen=True, kw_only=True)
class Speed:
    """Operating speed. Give the camshaft speed (as Ball's template) or the engine speed."""

    camshaft: float | None = quantity(
        "Camshaft rotational speed", "rpm", default=None, gt=0, example=2500.0)
    engine: float | None = quantity(
        "Engine (crankshaft) speed, instead of camshaft; camshaft speed = engine speed / 2",
        "rpm", default=None, gt=0)

    schema_rules = (ExactlyOne((("camshaft",), ("engine",))),)

    def problems(self, path: str) -> list[Problem]:
        given = [n for n in ("camshaft", "engine") if getattr(self, n) is not None]
        if len(given) != 1:
            return [Problem(path, "give exactly one of speed.camshaft or speed.engine",
                            given or None, "one speed in rpm")]
        return []

    @property
    def omega(self) -> float:
        """Camshaft angular speed [rad/s] (the model stores speeds in rad/s)."""
        if self.camshaft is not None:
            return self.camshaft
        return self.engine / 2.0


# --------------------------------------------------------------------------- mechanism

@dataclass(frozen=True, kw_only=True)
class Mechanism:
    """The follower and how it drives the valve. Pivot geometry follows Dyson's (1980) notation."""

    type: Literal["flat", "domed", "finger", "rocker", "pushrod", "desmodromic"] = option(
        "Follower type: flat (bucket tappet), domed (curved translating), finger (end-pivoted), "
        "rocker (centrally pivoted), pushrod (push rod and rocker), desmodromic (opening and "
        "closing cams)", example="flat")
    rotation: Literal["clockwise", "anticlockwise"] = option(
        "Direction of cam rotation, viewed with the pivot to the right of the cam centre "
        "(clockwise as Dyson and Lim)", default="clockwise")
    follower_radius: float | None = quantity(
        "Radius of curvature of the follower face in contact with the cam, r_f", "mm",
        default=None, gt=0, applies="domed, finger, rocker, pushrod")
    offset: float = quantity(
        "Offset of the follower axis from the cam centre (domed follower)", "mm", default=0.0,
        applies="domed")
    follower: Literal["sliding", "roller"] = option(
        "Face on the cam: sliding (a pad or dome) or roller (a roller of radius "
        "follower_radius: roller tappet, roller finger follower, roller rocker, push-rod roller "
        "lifter; a straight roller is a line contact, [mechanism.roller] crowns it)",
        default="sliding", applies="domed, finger, rocker, pushrod")
    follower_shape: Literal["spherical", "cylindrical"] = option(
        "Face of a domed sliding follower: spherical (point contact) or cylindrical (line "
        "contact); a roller is cylindrical whatever this says", default="spherical",
        applies="domed")
    face_length: float | None = quantity(
        "Usable length (flat: diameter) of the follower face; contact must stay on it", "mm",
        default=None, gt=0)
    A: float | None = quantity(
        "A: pivot to the centre of curvature of the follower face (UQ)", "mm", default=None,
        gt=0, applies="finger, rocker")
    B: float | None = quantity(
        "B: pivot to the centre of the valve-contact pad (UV)", "mm", default=None, gt=0,
        applies="finger, rocker")
    D: float | None = quantity(
        "D: cam centre to pivot (OU)", "mm", default=None, gt=0, applies="finger, rocker")
    kappa: float | None = quantity(
        "kappa (CHI): angle between OU and the direction of valve motion", "deg", default=None,
        gt=-360, lt=360, applies="finger, rocker")
    lambda_: float | None = quantity(
        "lambda: angle VUQ between the valve arm and the cam arm of the follower", "deg",
        default=None, gt=-360, lt=360, applies="finger, rocker", key="lambda")
    grinding_wheel_radius: float | None = quantity(
        "Largest grinding-wheel radius (Ball's minimum cam concavity); concave flanks must be "
        "less curved than this", "mm", default=None, gt=0)
    pushrod: Pushrod | None = section("Push rod and rocker geometry (Williams 2013 ch 11)",
                                      applies="pushrod", schema=DEFERRED["Pushrod"])
    closing: ClosingPair | None = section(
        "Closing cam and its end-pivoted follower; the fields above describe the opening pair "
        "(centrally pivoted)", applies="desmodromic", schema=DEFERRED["ClosingPair"])
    roller: RollerFace | None = section(
        "The roller of a roller follower (follower = \"roller\"): crown, mass",
        applies="follower = roller", schema=DEFERRED["RollerFace"])
    layout: Layout | None = section(
        "A finger follower or rocker drawn by positions (pivot, roller centre, pad centre, "
        "valve direction) instead of A, B, D, kappa, lambda", applies="finger, rocker",
        schema=DEFERRED["Layout"])
    arm: ArmContacts | None = section(
        "Valve pad and pivot of a finger follower or rocker: pad sliding, load, Hertz stress "
        "and friction, pivot friction torque", applies="finger, rocker",
        schema=DEFERRED["ArmContacts"])

    schema_rules = (
        When("type", ("domed", "finger", "rocker", "desmodromic"), require=("follower_radius",)),
        When("type", ("flat",), forbid=("follower_radius",)),
        When("type", ("pushrod",), require=("pushrod",)),
        When("type", ("pushrod",), negate=True, forbid=("pushrod",)),
        When("type", ("desmodromic",), require=("closing",)),
        When("type", ("desmodromic",), negate=True, forbid=("closing",)),
        When("type", ("desmodromic",), require=("A", "B", "D", "kappa", "lambda")),
        When("type", PIVOTED, require=("A", "B", "D", "kappa", "lambda"), or_given=("layout",)),
        When("type", PIVOTED, negate=True, forbid=("layout", "arm")),
        When("type", ROLLER_CARRIERS, negate=True, equal=(("follower", "sliding"),)),
        When("follower", ("sliding",), forbid=("roller",)),
        When("type", ("domed",), negate=True, equal=(("offset", 0),)))

    def dyson(self) -> Dyson | None:
        """Dyson's A, B, D, kappa, lambda of a pivoted follower [m, rad]: from the fields, or
        from [mechanism.layout]; None when neither is complete."""
        values = [getattr(self, k) for k in DYSON_KEYS]
        if self.layout is None and any(v is None for v in values):
            return None
        from camtrain.deck.schema_follower import Dyson, dyson_from_layout

        return dyson_from_layout(self.layout) if self.layout is not None else Dyson(*values)

    def problems(self, path: str) -> list[Problem]:
        out = []
        needs_rf = ("domed", "finger", "rocker", "desmodromic")
        if self.type in needs_rf and self.follower_radius is None:
            out.append(Problem(f"{path}.follower_radius",
                               f"is required for a {self.type} follower", None,
                               "a radius > 0 in mm"))
        if self.type == "flat" and self.follower_radius is not None:
            out.append(Problem(f"{path}.follower_radius", "does not apply to a flat follower",
                               mm_text(self.follower_radius), "no value",
                               "remove it, or choose type = \"domed\""))
        needs_pivot = PIVOTED + ("desmodromic",)
        if self.type == "pushrod" and self.pushrod is not None \
                and self.pushrod.layout == "four_bar":
            needs_pivot = needs_pivot + ("pushrod",)
            if self.follower_radius is None:
                out.append(Problem(f"{path}.follower_radius", "is required for a four-bar push "
                                   "rod (finger follower on the cam)", None, "a radius in mm"))
        for needed, name in (("pushrod", "pushrod"), ("desmodromic", "closing")):
            if self.type == needed and getattr(self, name) is None:
                out.append(Problem(f"{path}.{name}", f"is required for a {needed} mechanism",
                                   None, f"a [{path}.{name}] section"))
            if self.type != needed and getattr(self, name) is not None:
                out.append(Problem(f"{path}.{name}", f"applies to a {needed} mechanism only",
                                   None, "no such section", f"remove it or set type = {needed!r}"))
        out.extend(self._roller_problems(path))
        if self.layout is not None and self.type in PIVOTED:
            needs_pivot = ()
            out.extend(Problem(f"{path}.{'lambda' if k == 'lambda_' else k}",
                               "is given by [mechanism.layout]: give the positions or A, B, D, "
                               "kappa and lambda, not both", None, "no value")
                       for k in DYSON_KEYS if getattr(self, k) is not None)
        if self.type in needs_pivot:
            for name in ("A", "D") if self.type == "pushrod" else \
                    ("A", "B", "D", "kappa", "lambda_"):
                if getattr(self, name) is None:
                    key = "lambda" if name == "lambda_" else name
                    out.append(Problem(f"{path}.{key}",
                                       f"is required for a {self.type} follower (pivot geometry)",
                                       None, "a value"))
        if self.offset != 0.0 and self.type != "domed":
            out.append(Problem(f"{path}.offset", "applies to a domed follower only",
                               mm_text(self.offset), "0 or no value"))
        return out

    def _roller_problems(self, path: str) -> list[Problem]:
        """A roller only on a follower that can carry one, its section only with it; the
        layout and arm sections only on finger followers and rockers."""
        out = []
        if self.follower == "roller" and self.type not in ROLLER_CARRIERS:
            out.append(Problem(f"{path}.follower", f"a {self.type} follower cannot carry a "
                               "roller", "roller", "\"sliding\"",
                               "roller followers: " + ", ".join(ROLLER_CARRIERS)))
        if self.follower == "roller" and self.follower_radius is None:
            out.append(Problem(f"{path}.follower_radius", "is required for a roller follower "
                               "(the roller radius)", None, "a radius > 0 in mm"))
        if self.roller is not None and self.follower != "roller":
            out.append(Problem(f"{path}.roller", "applies to a roller follower only", None,
                               "no such section", "remove it or set follower = \"roller\""))
        if self.roller is not None and self.roller.mass > 0.0 and self.type not in PIVOTED:
            out.append(Problem(f"{path}.roller.mass", "applies to a finger follower or rocker "
                               "only", f"{self.roller.mass:g} kg", "0 or no value",
                               "put a tappet's roller in masses.valve_side"))
        for name in ("layout", "arm"):
            if getattr(self, name) is not None and self.type not in PIVOTED:
                out.append(Problem(f"{path}.{name}", "applies to a finger follower or rocker "
                                   "only", None, "no such section"))
        return out


# --------------------------------------------------------------------------- cam

@dataclass(frozen=True, kw_only=True)
class Cam:
    """The cam lobe."""

    base_radius: float = quantity("Base-circle radius r_B", "mm", gt=0, example=18.0)
    width: float | None = quantity(
        "Cam (lobe) width L; needed for contact loads, Hertz stress and friction", "mm",
        default=None, gt=0, example=12.0)
    taper_angle: float = quantity(
        "Taper angle of a tapered cam (with a domed follower, Yang 1992)", "deg", default=0.0,
        ge=0, lt=45, applies="domed")


# --------------------------------------------------------------------------- the deck

#: the effects a valve-train deck may list (registered in camtrain.catalogue)
EFFECT_NAMES = effect_names("valve_train")


@dataclass(frozen=True, kw_only=True)
class Deck:
    """A valve-train deck."""

    title: str = option("Name of the valve train", example="Cam and flat-faced follower")
    effects: Literal["auto"] | tuple[str, ...] = option(
        "Effects to run: \"auto\" (run what the data allow) or a list, e.g. "
        "[\"kinematics\", \"loads\"]", default="auto")
    speed: Speed = section("Operating speed", required=True)
    mechanism: Mechanism = section("Follower mechanism", required=True)
    cam: Cam = section("Cam lobe", required=True)
    lift: Lift = section("Lift law", required=True)
    spring: Spring | None = section("Valve spring (needed for loads)")
    masses: Masses | None = section("Moving masses (needed for loads)")
    clearance: Clearance | None = section("Valve clearance or lash adjuster")
    materials: Materials = section("Materials (defaults: steel on steel)", default=Materials())
    lubricant: Lubricant | None = section("Lubricant (needed for film and friction)")
    guides: Guides | None = section("Follower and valve guides (guide friction; needs lubricant)",
                                    schema=DEFERRED["Guides"])
    solver: Solver = section("Solver resolution", default=Solver())
    tribology: Tribology = section("Tribology model options", default=Tribology())
    limits: Limits | None = section("Design limits checked by run --check")
    camshaft: Camshaft | None = section(
        "The camshaft carrying copies of this valve train: lobes, bearings, drive (camshaft torque "
        "and bearing effects)", schema=DEFERRED["Camshaft"])
    dynamics: Dynamics | None = section(
        "Elastic valve train in time: contact loss, spring surge, valve seating (the dynamic "
        "contact load replaces the rigid train's)", schema=DEFERRED["Dynamics"])
    design: Design | None = section(
        "Valve events and limits from which camtrain design builds a lift law (a run ignores it)",
        schema=DEFERRED["Design"])
    roller: Roller | None = section(
        "The follower's roller turning on its pin: inertia, pin bearing, traction, solver "
        "(radius: mechanism.follower_radius)",
        applies="domed (follower_shape = cylindrical), finger, rocker, pushrod",
        schema=DEFERRED["Roller"])

    def problems(self, path: str) -> list[Problem]:
        out = []
        if isinstance(self.effects, tuple):
            for i, name in enumerate(self.effects):
                if name not in EFFECT_NAMES:
                    import difflib
                    close = difflib.get_close_matches(name, EFFECT_NAMES, n=1)
                    out.append(Problem(f"effects[{i}]", "is not a known effect", name,
                                       "one of " + ", ".join(EFFECT_NAMES),
                                       f"did you mean {close[0]!r}?" if close else ""))
        if self.lift.measured_at == "cam" and self.mechanism.type != "flat" \
                and self.lift.inspection_radius is None:
            out.append(Problem("lift.inspection_radius",
                               "is required when lift is measured at the cam", None,
                               "the inspection follower radius in mm"))
        if self.cam.taper_angle and self.mechanism.type != "domed":
            out.append(Problem("cam.taper_angle", "applies to a domed follower only",
                               f"{from_si(self.cam.taper_angle, 'deg'):g} deg", "0"))
        mech = self.mechanism
        if self.cam.taper_angle and mech.follower == "roller":
            out.append(Problem("cam.taper_angle", "a tapered cam runs on a spherical dome, not "
                               "on a roller", f"{from_si(self.cam.taper_angle, 'deg'):g} deg",
                               "0 with mechanism.follower = \"roller\""))
        if mech.layout is not None and mech.type in PIVOTED:
            from camtrain.deck.schema_follower import layout_problems

            out.extend(layout_problems(mech.layout, "mechanism.layout", self.cam.base_radius,
                                       mech.follower_radius))
        if self.dynamics is not None:   # its checks against the rest of the deck
            from camtrain.deck.schema_dynamics import dynamics_problems

            out.extend(dynamics_problems(self))
        if self.roller is not None:
            from camtrain.deck.schema_roller import roller_problems

            out.extend(roller_problems(self))
        return out
