"""The valve-train deck: every section and field, with its unit, range and prompt.

This module is the single description of a deck. Validation, the SI model, the commented
templates (`camtrain template`) and the JSON Schema (`camtrain schema`) are all derived from it.
Field docs are written as prompts, in the spirit of Ball's (1988) template input file.
Values in the model are SI; units below are the units written in the deck.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import option, quantity, section
from camtrain.errors import Problem
from camtrain.units import from_si

MECHANISMS = ("flat", "domed", "finger", "rocker", "pushrod", "desmodromic")
PIVOTED = ("finger", "rocker")
LIFT_FORMS = ("four_power", "multipol", "table", "exp_poly", "polynomial",
              "williams_elementary", "williams_low_jerk")


def _mm(x: float) -> str:
    return f"{from_si(x, 'mm'):g} mm"


# --------------------------------------------------------------------------- speed

@dataclass(frozen=True, kw_only=True)
class Speed:
    """Operating speed. Give the camshaft speed (as Ball's template) or the engine speed."""

    camshaft: float | None = quantity(
        "Camshaft rotational speed", "rpm", default=None, gt=0, example=2500.0)
    engine: float | None = quantity(
        "Engine (crankshaft) speed, instead of camshaft; camshaft speed = engine speed / 2",
        "rpm", default=None, gt=0)

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
class Pushrod:
    """Rocker and push rod between the valve and the follower on the cam (Williams 2013 ch 11)."""

    layout: Literal["simple", "four_bar"] = option(
        "simple: push rod on a translating tappet; four_bar: push rod on a pivoted finger "
        "follower (mechanism.A, D, follower_radius describe that follower)", default="simple")
    rocker_pushrod_arm: float = quantity("Rocker arm on the push-rod side, D1", "mm", gt=0,
                                         example=35.0)
    rocker_valve_arm: float = quantity("Rocker arm on the valve side, D2", "mm", gt=0,
                                       example=50.0)
    rocker_arm_angle: float = quantity("Angle between the two rocker arms, alpha_0", "deg",
                                       default=0.0, gt=-90, lt=90, example=10.0)
    valve_axis_angle: float = quantity("Angle between the vertical and the valve axis, gamma",
                                       "deg", default=0.0, gt=-60, lt=60, example=15.0)
    perpendicular_lift_fraction: float = quantity(
        "Fraction of the maximum valve lift at which the valve arm is perpendicular to the "
        "valve axis", "-", default=0.5, ge=0, le=1)
    pushrod_length: float = quantity("Push-rod length D_PR", "mm", gt=0, example=200.0)
    pushrod_cg_fraction: float = quantity(
        "Distance of the push rod's centre of mass from its lower end, as a fraction of its "
        "length", "-", default=0.5, ge=0, le=1)
    tappet_axis_distance: float | None = quantity(
        "Horizontal distance from the rocker pivot to the tappet axis, x_bar", "mm",
        default=None, gt=0, example=43.3, applies="layout = simple")
    rocker_pivot_x: float | None = quantity(
        "Rocker pivot position relative to the follower pivot, horizontal (a)", "mm",
        default=None, applies="layout = four_bar")
    rocker_pivot_y: float | None = quantity(
        "Rocker pivot position relative to the follower pivot, vertical (b)", "mm",
        default=None, applies="layout = four_bar")
    follower_pushrod_arm: float | None = quantity(
        "Follower pivot to push-rod joint, e", "mm", default=None, gt=0,
        applies="layout = four_bar")
    closure: Literal[-1, 1] = option("Side of the line follower pivot - rocker tip on which "
                                     "the push-rod joint lies", default=-1)
    branch: Literal[-1, 1] = option("Assembly branch of the follower on the cam side",
                                    default=1)

    def problems(self, path: str) -> list[Problem]:
        if self.layout == "simple" and self.tappet_axis_distance is None:
            return [Problem(f"{path}.tappet_axis_distance", "is required for layout = simple",
                            None, "a distance in mm")]
        if self.layout == "four_bar":
            return [Problem(f"{path}.{n}", "is required for layout = four_bar", None, "mm")
                    for n in ("rocker_pivot_x", "rocker_pivot_y", "follower_pushrod_arm")
                    if getattr(self, n) is None]
        return []


@dataclass(frozen=True, kw_only=True)
class ClosingPair:
    """The closing cam of a desmodromic train and its end-pivoted follower (Ball 1988 App F)."""

    A: float = quantity("A: pivot to the centre of curvature of the follower face", "mm",
                        gt=0, example=17.32)
    B: float = quantity("B: pivot to the valve-contact pad", "mm", gt=0, example=32.39)
    D: float = quantity("D: cam centre to pivot", "mm", gt=0, example=39.32)
    kappa: float = quantity("kappa: angle between OU and the direction of valve motion", "deg",
                            gt=-360, lt=360, example=-7.31)
    lambda_: float = quantity("lambda: angle VUQ", "deg", gt=-360, lt=360, example=9.41,
                              key="lambda")
    follower_radius: float = quantity("Follower face radius r_f", "mm", gt=0, example=20.0)
    base_radius: float = quantity("Base-circle radius of the closing cam", "mm", gt=0,
                                  example=25.0)
    width: float | None = quantity("Closing cam width", "mm", default=None, gt=0)


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
                                      applies="pushrod")
    closing: ClosingPair | None = section(
        "Closing cam and its end-pivoted follower; the fields above describe the opening pair "
        "(centrally pivoted)", applies="desmodromic")

    def problems(self, path: str) -> list[Problem]:
        out = []
        needs_rf = ("domed", "finger", "rocker", "desmodromic")
        if self.type in needs_rf and self.follower_radius is None:
            out.append(Problem(f"{path}.follower_radius",
                               f"is required for a {self.type} follower", None,
                               "a radius > 0 in mm"))
        if self.type == "flat" and self.follower_radius is not None:
            out.append(Problem(f"{path}.follower_radius", "does not apply to a flat follower",
                               _mm(self.follower_radius), "no value",
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
                               _mm(self.offset), "0 or no value"))
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


# --------------------------------------------------------------------------- lift

@dataclass(frozen=True, kw_only=True)
class Ramps:
    """Constant-velocity ramps before and after the event (lift at the end of the ramp)."""

    opening_height: float = quantity("Opening ramp height", "mm", default=0.0, ge=0,
                                     example=0.5)
    opening_length: float | None = quantity(
        "Opening ramp length; a multipol may omit it (derived from its start velocity); "
        "required when the ramp has a height otherwise", "deg", default=None, ge=0, lt=180,
        example=25.0)
    closing_height: float | None = quantity("Closing ramp height; omit for the opening value",
                                            "mm", default=None, ge=0, example=0.5)
    closing_length: float | None = quantity("Closing ramp length; omit for the opening value",
                                            "deg", default=None, ge=0, lt=180, example=25.0)


@dataclass(frozen=True, kw_only=True)
class FourPower:
    """Ball's four-power polynomial: l = Y_R + l_max + sum C_n (phi/phi_T)^n over |phi| <= phi_T."""

    half_period: float = quantity("Cam half period phi_T (action period)", "deg", gt=0, lt=180,
                                  example=60.0)
    max_lift: float = quantity("Maximum lift above the ramp, l_max", "mm", gt=0, example=8.9)
    exponents: tuple[float, ...] = quantity(
        "Exponents p, q, r, s", "-", gt=0, le=200, min_items=4, max_items=4,
        example=[2, 9, 78, 80])
    coefficients: tuple[float, ...] = quantity(
        "Coefficients Cp, Cq, Cr, Cs (their sum is -max_lift)", "mm", min_items=4, max_items=4,
        example=[-11.6918407, 2.8498942, -0.5894568, 0.5314033])


@dataclass(frozen=True, kw_only=True)
class Segment:
    """One multipol segment: l = l_start + sum_{k=1..5} C_k (theta/theta_T)^k."""

    length: float = quantity("Segment length theta_T", "deg", gt=0, lt=360)
    coefficients: tuple[float, ...] = quantity("Coefficients C1..C5", "mm", min_items=1,
                                               max_items=5)
    start_lift: float | None = quantity(
        "Lift at the start of the segment; omit to continue from the previous segment (the "
        "first starts at the ramp height)", "mm", default=None, ge=0)


@dataclass(frozen=True, kw_only=True)
class Multipol:
    """Ball's multipol: up to 5 polynomial segments from the end of the opening ramp to the nose."""

    segments: tuple[Segment, ...] = section("Segments, from the end of the opening ramp "
                                            "toward the nose", required=True)
    closing_segments: tuple[Segment, ...] | None = section(
        "Segments of the closing half, from the end of the closing ramp toward the nose (only "
        "when the lift is not symmetric)")
    max_order: int = quantity("Maximum order of the polynomials", "-", default=5, ge=1, le=5)
    check_continuity: bool = option(
        "Stop when lift, velocity or acceleration jump at a joint (the jumps are always "
        "reported)", default=True)
    tolerance: float = quantity(
        "Allowed velocity or acceleration step at a joint, as a fraction of its peak (lift steps "
        "are limited to 1 µm)", "-", default=0.005, gt=0, lt=1)

    def problems(self, path: str) -> list[Problem]:
        out = []
        for name in ("segments", "closing_segments"):
            segs = getattr(self, name)
            if segs is not None and not 1 <= len(segs) <= 5:
                out.append(Problem(f"{path}.{name}", f"has {len(segs)} segments", None,
                                   "1 to 5 segments"))
        return out


@dataclass(frozen=True, kw_only=True)
class Table:
    """Lift given as discrete data points (angle from maximum lift, lift)."""

    angle_unit: Literal["deg", "rad"] = option("Unit of the inline angles: deg or rad",
                                               default="deg")
    angles: tuple[float, ...] | None = quantity(
        "Cam angles from the maximum-lift position, increasing (in angle_unit)", "-",
        default=None, min_items=8)
    lifts: tuple[float, ...] | None = quantity("Lift at each angle", "mm", default=None,
                                               min_items=8)
    file: str | None = option(
        "CSV file with a header 'angle_deg,lift_mm' (or angle_rad / lift_m) instead of "
        "angles and lifts; a path relative to the deck", default=None)
    dataset: Literal["pinto_inlet_cam", "pinto_inlet_valve", "zeta_intake",
                     "zeta_exhaust"] | None = option(
        "A lift table shipped with camtrain instead: pinto_inlet_cam (Ball 1988 App E), "
        "pinto_inlet_valve (App E converted to valve lift through the datum geometry), "
        "zeta_intake, zeta_exhaust (Yang 1992 App C)", default=None)
    symmetric: bool = option("Mirror the data about the maximum-lift position", default=False)
    derivative: Literal["smoothing_spline", "central_difference"] = option(
        "How derivatives are taken: smoothing_spline (robust to 4-decimal data) or "
        "central_difference (as Ball 1988, sensitive to data error)",
        default="smoothing_spline")
    smoothing: float | None = quantity(
        "Smoothing level of the spline relative to the data precision; omit for the automatic "
        "choice (1)", "-", default=None, ge=0)
    noise: float | None = quantity(
        "Measurement noise (standard deviation) of the lifts; omit for printed step / sqrt(12)", "mm",
        default=None, gt=0)

    def problems(self, path: str) -> list[Problem]:
        has_inline = self.angles is not None or self.lifts is not None
        sources = [has_inline, self.file is not None, self.dataset is not None]
        if sum(sources) != 1:
            return [Problem(path, "give exactly one source of data points", None,
                            "angles and lifts, or file, or dataset")]
        if has_inline and (self.angles is None or self.lifts is None):
            return [Problem(path, "angles and lifts must be given together")]
        if has_inline and len(self.angles) != len(self.lifts):
            return [Problem(f"{path}.lifts", f"has {len(self.lifts)} values but angles has "
                            f"{len(self.angles)}", None, "one lift per angle")]
        return []


@dataclass(frozen=True, kw_only=True)
class ExpPoly:
    """Exponential-polynomial fit (Lim et al. 1983): l = exp(a0 + a1 phi + ...), phi in rad, l in mm."""

    coefficients: tuple[float, ...] = quantity("Coefficients a0, a1, ... (phi in rad, lift in mm)",
                                               "-", min_items=3, max_items=20)
    cutoff: float = quantity("Lift below which the valve is taken as closed (base circle)", "mm",
                             default=1e-4, gt=0)
    blend: Literal["shift", "hard"] = option(
        "Cut-off treatment: shift (lift continuous, nose exact) or hard (raw fit above the "
        "cut-off, a small step at it)", default="shift")


@dataclass(frozen=True, kw_only=True)
class Polynomial:
    """General polynomial (polydyne): l = max_lift (1 - sum C_n (phi/phi_T)^n) over |phi| <= phi_T."""

    half_period: float = quantity("Half period phi_T", "deg", gt=0, lt=180)
    max_lift: float = quantity("Lift at the nose above the ramp", "mm", gt=0)
    exponents: tuple[float, ...] = quantity("Exponents n (e.g. 2, 8, 14, 20, 26)", "-", gt=0,
                                            le=200, min_items=1, max_items=20)
    coefficients: tuple[float, ...] | None = quantity(
        "Dimensionless coefficients C_n (sum 1); omit for the polydyne (zero lift, velocity "
        "and higher derivatives at the ends)", "-", default=None, min_items=1, max_items=20)

    def problems(self, path: str) -> list[Problem]:
        if self.coefficients is not None and len(self.exponents) != len(self.coefficients):
            return [Problem(f"{path}.coefficients", f"has {len(self.coefficients)} values but "
                            f"exponents has {len(self.exponents)}", None, "one per exponent")]
        return []


@dataclass(frozen=True, kw_only=True)
class ElementaryHalf:
    """One half of Williams' elementary curve (Williams 2013 ch 2)."""

    durations: tuple[float, ...] = quantity(
        "Section lengths T0..T4: ramp, rise to A, constant A, fall to 0, quarter sine", "deg",
        ge=0, min_items=5, max_items=5)
    ramp_lift: float = quantity("Lift at the end of the ramp", "mm", ge=0)


@dataclass(frozen=True, kw_only=True)
class WilliamsElementary:
    """Williams' elementary acceleration-based lift curve; A and F are solved for."""

    max_lift: float = quantity("Maximum valve lift", "mm", gt=0)
    opening: ElementaryHalf = section("Opening half", required=True)
    closing: ElementaryHalf | None = section("Closing half; omit for a symmetric curve")


@dataclass(frozen=True, kw_only=True)
class LowJerkHalf:
    """One half of Williams' low-jerk curve (Williams 2013 ch 3, Fig 3.2, App 1)."""

    durations: tuple[float, ...] = quantity("Section lengths T0..T12 (T11, the polynomial, > 0)",
                                            "deg", ge=0, min_items=13, max_items=13)
    fractions: tuple[float, ...] = quantity(
        "Fractions eps0..eps6 (eps0 of the ramp acceleration, eps1..eps6 of A)", "-",
        min_items=7, max_items=7)
    lam: float = quantity("lambda: fraction of F at the start of the polynomial", "-")
    p: float = quantity("First index of the polynomial section (> 1)", "-", gt=1)
    q: float = quantity("Second index of the polynomial section (> 1, not p)", "-", gt=1)
    ramp_lift: float = quantity("Lift at the end of the ramp (end of T1)", "mm", ge=0)


@dataclass(frozen=True, kw_only=True)
class WilliamsLowJerk:
    """Williams' low-jerk acceleration-based lift curve; A and F are solved for."""

    max_lift: float = quantity("Maximum valve lift", "mm", gt=0)
    nose_deceleration: float = quantity("Deceleration F0 at the nose", "mm/deg²", gt=0)
    opening: LowJerkHalf = section("Opening half", required=True)
    closing: LowJerkHalf | None = section("Closing half; omit for a symmetric curve")


@dataclass(frozen=True, kw_only=True)
class Lift:
    """The lift law. Angles are cam degrees from the maximum-lift (nose) position."""

    form: Literal["four_power", "multipol", "table", "exp_poly", "polynomial",
                  "williams_elementary", "williams_low_jerk"] = option(
        "Lift form: four_power, multipol, table, exp_poly, polynomial, williams_elementary, "
        "williams_low_jerk", example="four_power")
    measured_at: Literal["valve", "cam"] = option(
        "Lift given at the valve, or at the cam on an inspection follower", default="valve")
    inspection_radius: float | None = quantity(
        "Radius of the inspection follower the cam lift was measured with", "mm", default=None,
        gt=0, applies="measured_at = \"cam\" with a pivoted follower")
    ramps: Ramps | None = section("Opening and closing ramps",
                                  applies="four_power, multipol, polynomial")
    four_power: FourPower | None = section("Four-power polynomial", applies="form = four_power")
    multipol: Multipol | None = section("Multipol segments", applies="form = multipol")
    table: Table | None = section("Data points", applies="form = table")
    exp_poly: ExpPoly | None = section("Exponential fit", applies="form = exp_poly")
    polynomial: Polynomial | None = section("Polynomial", applies="form = polynomial")
    williams_elementary: WilliamsElementary | None = section(
        "Williams elementary curve", applies="form = williams_elementary")
    williams_low_jerk: WilliamsLowJerk | None = section(
        "Williams low-jerk curve", applies="form = williams_low_jerk")

    def problems(self, path: str) -> list[Problem]:
        out = []
        if getattr(self, self.form) is None:
            out.append(Problem(f"{path}.{self.form}", "is missing", None,
                               f"a [{path}.{self.form}] section for form = {self.form!r}"))
        for other in LIFT_FORMS:
            if other != self.form and getattr(self, other) is not None:
                out.append(Problem(f"{path}.{other}", f"is given but form = {self.form!r}",
                                   None, "only the section of the chosen form",
                                   f"remove it or set form = {other!r}"))
        return out


# --------------------------------------------------------------------------- loads

@dataclass(frozen=True, kw_only=True)
class Spring:
    """Valve spring. Omit the section and no contact loads are computed (Ball: Blok film only)."""

    rate: float = quantity("Spring rate k", "N/mm", gt=0, example=38.254)
    preload_compression: float = quantity(
        "Initial spring compression delta at zero valve lift", "mm", ge=0, example=6.4)
    progressive_quadratic: float = quantity(
        "Progressive spring, quadratic term c2: force += c2 x^2 (x = total compression)",
        "N/mm²", default=0.0)
    progressive_cubic: float = quantity(
        "Progressive spring, cubic term c3: force += c3 x^3 (x = total compression)", "N/mm³",
        default=0.0)


@dataclass(frozen=True, kw_only=True)
class Masses:
    """Moving masses, reduced as in Ball (1988) Table 3.1."""

    valve_side: float = quantity(
        "Equivalent mass at the valve: valve + retainer + collets + 1/3 spring (+ bucket for a "
        "flat follower)", "kg", gt=0, example=0.172)
    follower: float = quantity(
        "Follower (rocker) equivalent mass referred to radius B", "kg", default=0.0, ge=0,
        applies="finger, rocker")
    rocker_inertia: float = quantity("Rocker moment of inertia about its pivot", "kg·m²",
                                     default=0.0, ge=0, applies="finger, rocker, pushrod")


@dataclass(frozen=True, kw_only=True)
class Clearance:
    """Valve clearance (lash) or a hydraulic lash adjuster."""

    valve_clearance: float = quantity("Valve clearance at the base-circle position", "mm",
                                      default=0.0, ge=0)
    lash_adjuster: bool = option("A hydraulic lash adjuster keeps zero clearance",
                                 default=False)
    adjuster_load: float = quantity("Base-circle load of the lash adjuster", "N", default=0.0,
                                    ge=0, applies="lash_adjuster = true")


@dataclass(frozen=True, kw_only=True)
class Guides:
    """Follower and valve-stem guides: full-film Couette shear losses (Yang 1992 §3.3.2)."""

    follower_diameter: float | None = quantity(
        "Follower (bucket) diameter in its bore; omit for a follower without a guide", "mm",
        default=None, gt=0, example=28.4, applies="flat, domed")
    follower_guide_length: float | None = quantity("Follower guide (bore) length", "mm",
                                                   default=None, gt=0, example=22.0,
                                                   applies="flat, domed")
    follower_guide_clearance: float | None = quantity(
        "Radial clearance between follower and bore", "mm", default=None, gt=0, example=0.024,
        applies="flat, domed")
    valve_stem_diameter: float = quantity("Valve stem diameter", "mm", gt=0, example=6.043)
    valve_guide_length: float = quantity("Valve guide length", "mm", gt=0, example=36.0)
    valve_guide_clearance: float = quantity("Radial clearance between valve stem and guide",
                                            "mm", gt=0, example=0.02)

    def problems(self, path: str) -> list[Problem]:
        given = [self.follower_diameter, self.follower_guide_length,
                 self.follower_guide_clearance]
        if any(v is None for v in given) and any(v is not None for v in given):
            return [Problem(f"{path}.follower_diameter", "the follower guide needs diameter, "
                            "guide length and clearance together", None, "all three or none")]
        return []


@dataclass(frozen=True, kw_only=True)
class Materials:
    """Elastic properties of cam and follower."""

    cam_modulus: float = quantity("Young's modulus of the cam", "GPa", default=207.0, gt=0)
    cam_poisson: float = quantity("Poisson's ratio of the cam", "-", default=0.29, gt=0, lt=0.5)
    follower_modulus: float = quantity("Young's modulus of the follower", "GPa", default=207.0,
                                       gt=0)
    follower_poisson: float = quantity("Poisson's ratio of the follower", "-", default=0.29,
                                       gt=0, lt=0.5)


@dataclass(frozen=True, kw_only=True)
class Lubricant:
    """The oil at the contact: its viscosity given directly, or from a fit at the oil temperature."""

    viscosity: float | None = quantity(
        "Dynamic viscosity at ambient pressure and oil temperature; omit to take it from "
        "viscosity_fit at temperature", "Pa·s", default=None, gt=0, example=0.05)
    pressure_viscosity: float = quantity("Pressure-viscosity coefficient alpha", "1/GPa", ge=0,
                                         example=22.0)
    roughness: float = quantity("Composite RMS surface roughness sigma (for lambda = h/sigma)",
                                "µm", default=0.2, gt=0)
    temperature: float | None = quantity("Oil temperature at the contact", "°C", default=None,
                                         gt=-60, lt=400)
    viscosity_fit: Literal["vogel", "two_point"] | None = option(
        "Viscosity-temperature law through the fit points: vogel (three or more points, Vogel "
        "1921) or two_point (exponential, Reynolds 1886)", default=None)
    fit_temperatures: tuple[float, ...] | None = quantity(
        "Temperatures of the fit points", "°C", default=None, gt=-60, lt=400,
        applies="viscosity_fit")
    fit_viscosities: tuple[float, ...] | None = quantity(
        "Dynamic viscosities at the fit temperatures", "Pa·s", default=None, gt=0,
        applies="viscosity_fit")

    def __post_init__(self) -> None:
        # the run chain reads ``viscosity``: fill it from the fit (bad fit data -> problems())
        if self.viscosity is None and not self._fit_problems("lubricant"):
            object.__setattr__(self, "viscosity", self.fitted_viscosity())

    def fitted_viscosity(self) -> float:
        """eta(temperature) [Pa s] from the fit points (Vogel 1921 or Reynolds 1886 two-point)."""
        from camtrain.formulas.viscosity import reynolds_two_point, vogel, vogel_fit
        T = [t + 273.15 for t in self.fit_temperatures]
        eta = list(self.fit_viscosities)
        T0 = self.temperature + 273.15
        if self.viscosity_fit == "vogel":
            return float(vogel(T0, *vogel_fit(T, eta)))
        return float(reynolds_two_point(T0, T[0], eta[0], T[1], eta[1]))

    def _fit_problems(self, path: str) -> list[Problem]:
        if self.viscosity_fit is None:
            return [] if self.viscosity is not None else [Problem(
                f"{path}.viscosity", "is missing", None,
                "a viscosity in Pa·s, or viscosity_fit with temperature and fit points")]
        out = []
        if self.temperature is None:
            out.append(Problem(f"{path}.temperature", "is required with viscosity_fit", None,
                               "the oil temperature in °C"))
        t, e = self.fit_temperatures or (), self.fit_viscosities or ()
        need = 3 if self.viscosity_fit == "vogel" else 2
        if len(t) != len(e) or len(t) < need or (self.viscosity_fit == "two_point"
                                                   and len(t) != 2):
            out.append(Problem(f"{path}.fit_temperatures", "and fit_viscosities must be pairs",
                               f"{len(t)} temperatures, {len(e)} viscosities",
                               f"{'at least 3' if need == 3 else 'exactly 2'} of each"))
        elif len(set(t)) != len(t) or any((b - a) * (y - x) >= 0 for a, b, x, y in
                                            zip(t, t[1:], e, e[1:], strict=False)):
            out.append(Problem(f"{path}.fit_viscosities", "must fall as the temperature rises",
                               list(e), "distinct temperatures, viscosity falling with them"))
        return out

    def problems(self, path: str) -> list[Problem]:
        out = self._fit_problems(path)
        if self.viscosity_fit is not None and not out:
            try:
                eta = self.fitted_viscosity()
            except Exception as exc:  # a Vogel fit that has no solution for these points
                return [Problem(f"{path}.fit_viscosities", "cannot be fitted", None, "",
                                str(exc))]
            if self.viscosity is not None and abs(self.viscosity - eta) > 1e-9 * eta:
                out.append(Problem(f"{path}.viscosity", "conflicts with viscosity_fit",
                                   self.viscosity, f"omit it (the fit gives {eta:.6g} Pa·s)"))
        return out


@dataclass(frozen=True, kw_only=True)
class Solver:
    """Resolution knobs (each trades accuracy for time; see `camtrain accuracy`)."""

    angle_points: int = quantity("Number of cam angles over one revolution", "-", default=720,
                                 ge=16, le=1_000_000)
    friction_tolerance: float = quantity(
        "Relative tolerance of the friction/load iteration of pivoted followers", "-",
        default=1e-6, gt=0, lt=0.1)
    friction_max_iterations: int = quantity("Maximum friction/load iterations", "-", default=50,
                                            ge=1, le=10_000)


@dataclass(frozen=True, kw_only=True)
class Tribology:
    """Tribology model options (Ball 1988 ch. 4; the choices behind his printed results)."""

    entrainment: Literal["mean", "sum"] = option(
        "Entrainment speed in the film formulas: mean (V_c + V_f)/2, or sum V_c + V_f as Ball's "
        "'entraining velocity'", default="mean")
    film_formula: Literal["auto", "dowson_higginson_1977", "dowson_dunn_taylor_1983",
                          "hamrock_dowson_1977_min", "chittenden_1985_min"] = option(
        "Minimum-film formula: auto (Dowson-Higginson for line, Hamrock-Dowson for point "
        "contact with loads; Blok rigid-piezoviscous without loads) or a named formula",
        default="auto")
    friction_model: Literal["cap", "lambda", "lambda_cap", "greenwood_tripp"] = option(
        "Friction: cap (lesser of viscous shear and boundary friction), lambda (boundary "
        "friction where h/sigma < 1), lambda_cap (both), greenwood_tripp (asperity load share "
        "with boundary shear plus viscous shear of the rest, Teodorescu et al. 2005)",
        default="cap")
    boundary_friction: float = quantity(
        "Boundary friction coefficient (cap and start of the friction/load iteration)", "-",
        default=0.08, ge=0, le=1)
    hertz: Literal["exact", "ball_1988"] = option(
        "Point-contact Hertz: exact ellipticity, or Ball's eq. 3.7", default="exact")
    # Greenwood-Tripp / Teodorescu et al. (2005) parameters. The paper prints none of them;
    # the defaults are typical values for run-in steel surfaces (see docs/tribology.md).
    asperity_density_product: float = quantity(
        "Greenwood-Tripp roughness parameter zeta beta sigma (asperity density x tip radius x "
        "rms roughness)", "-", default=0.04, gt=0, lt=1, applies="friction_model = "
        "greenwood_tripp")
    roughness_slope: float = quantity(
        "Greenwood-Tripp ratio sigma / beta (rms roughness over asperity tip radius)", "-",
        default=1e-3, gt=0, lt=1, applies="friction_model = greenwood_tripp")
    eyring_stress: float = quantity(
        "Eyring (limiting) shear stress tau_0 of the oil (Teodorescu eq. 12)", "MPa",
        default=2.0, ge=0, applies="friction_model = greenwood_tripp")
    shear_pressure_coefficient: float = quantity(
        "Rise of the limiting shear stress with mean pressure, gamma (Teodorescu eq. 12)", "-",
        default=0.08, ge=0, lt=1, applies="friction_model = greenwood_tripp")
    boundary_shear_coefficient: float = quantity(
        "Pressure coefficient m of the asperity boundary shear strength (Teodorescu eq. 8)",
        "-", default=0.17, ge=0, lt=1, applies="friction_model = greenwood_tripp")


# --------------------------------------------------------------------------- design limits

@dataclass(frozen=True, kw_only=True)
class Limits:
    """Design limits, checked over the cycle by `camtrain run --check`; omit a limit to skip it."""

    max_hertz: float | None = quantity("Largest allowed maximum Hertz stress p_max", "MPa",
                                       default=None, gt=0, example=650.0)
    min_film: float | None = quantity(
        "Smallest allowed minimum film thickness h_min anywhere in contact (zero-entrainment "
        "points give zero film in a quasi-static analysis)", "µm", default=None, ge=0, example=0.05)
    min_film_at_max_lift: float | None = quantity(
        "Smallest allowed h_min at the maximum-lift position (Ball's representative nose film)",
        "µm", default=None, ge=0, example=0.1)
    min_lambda: float | None = quantity("Smallest allowed film parameter lambda = h_min/sigma",
                                        "-", default=None, ge=0, example=0.3)
    min_bounce_margin: float | None = quantity(
        "Smallest allowed margin of the run speed below the valve-bounce speed, "
        "100 (1 - n/n_bounce)", "%", default=None, gt=-100, lt=100, example=10.0)
    max_power_loss: float | None = quantity("Largest allowed cycle-mean frictional power loss",
                                            "W", default=None, gt=0, example=60.0)
    max_load: float | None = quantity("Largest allowed cam/follower contact load", "N",
                                      default=None, gt=0, example=2000.0)
    max_friction_torque: float | None = quantity("Largest allowed peak friction torque", "N·m",
                                                 default=None, gt=0, example=2.0)


# --------------------------------------------------------------------------- the deck

EFFECT_NAMES = ("kinematics", "loads", "hertz", "film", "friction", "power", "camshaft_torque",
                "bearings")


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
    guides: Guides | None = section("Follower and valve guides (guide friction; needs lubricant)")
    solver: Solver = section("Solver resolution", default=Solver())
    tribology: Tribology = section("Tribology model options", default=Tribology())
    limits: Limits | None = section("Design limits checked by run --check")
    camshaft: Camshaft | None = section(
        "The camshaft carrying copies of this valve train: lobes, bearings, drive (camshaft torque "
        "and bearing effects)")

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
        return out


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
    """One plain camshaft bearing (short-bearing theory; a full central groove makes two lands)."""

    position: float = quantity("Axial position of the bearing centre", "mm", example=0.0)
    diameter: float = quantity("Journal diameter d", "mm", gt=0, example=25.97)
    length: float = quantity("Overall bearing length b, groove included", "mm", gt=0,
                             example=17.0)
    clearance: float = quantity("Radial clearance c", "mm", gt=0, example=0.0225)
    groove_width: float = quantity(
        "Width of a full circumferential central groove; 0 = ungrooved", "mm", default=0.0,
        ge=0)

    def problems(self, path: str) -> list[Problem]:
        out = []
        if self.groove_width >= self.length:
            out.append(Problem(f"{path}.groove_width", "is not shorter than the bearing",
                               _mm(self.groove_width), f"< length ({_mm(self.length)})"))
        if self.clearance >= 0.5 * self.diameter:
            out.append(Problem(f"{path}.clearance", "is larger than the journal radius",
                               _mm(self.clearance), "a radial clearance << d/2"))
        return out


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
        "Shear film for bearing power: pi (loaded half, Ball) or 2pi (full film, Yang's grooved "
        "pressure-fed bearings)", default="pi")
    method: Literal["mobility", "steady", "petroff"] = option(
        "Bearing model: mobility (Booker orbit), steady (quasi-static Ocvirk) or petroff "
        "(concentric power only)", default="mobility")
    mobility: Literal["exact", "booker"] = option(
        "Mobility: exact pi-film inversion or Booker's closed form", default="exact")
    bearing_tolerance: float = quantity(
        "Cycle-to-cycle change of the eccentricity ratio that counts as periodic", "-",
        default=1e-5, gt=0, lt=0.1)
    max_cycles: int = quantity("Most load cycles marched before giving up", "-", default=20,
                               ge=2, le=1000)

    def problems(self, path: str) -> list[Problem]:
        out = []
        if not self.lobes:
            out.append(Problem(f"{path}.lobes", "has no lobes", None, "at least one lobe"))
        pos = [b.position for b in self.bearings or ()]
        for i in range(1, len(pos)):
            if not pos[i] > pos[i - 1]:
                out.append(Problem(f"{path}.bearings[{i}].position", "is not after the previous "
                                   "bearing", _mm(pos[i]), "bearings in increasing axial order"))
        if self.v_angle is None and any(lobe.bank == 2 for lobe in self.lobes):
            out.append(Problem(f"{path}.v_angle", "is required when a lobe has bank = 2", None,
                               "the V angle in crank degrees"))
        return out
