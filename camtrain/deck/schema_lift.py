"""Deck sections of the lift law ([lift] and its forms). Part of the deck schema (schema.py)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import ExactlyOne, Together, When, option, quantity, section
from camtrain.errors import Problem

LIFT_FORMS = ("four_power", "multipol", "table", "exp_poly", "polynomial",
              "williams_elementary", "williams_low_jerk", "spline")


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

    schema_rules = (ExactlyOne((("angles", "lifts"), ("file",), ("dataset",))),
                    Together(("angles", "lifts")))

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
class Spline:
    """Lift as a B-spline over the event (the form camtrain design writes; docs/design.md)."""

    degree: int = quantity("Degree of the B-spline (5: quintic lift, cubic acceleration, "
                           "continuous jerk)", "-", default=5, ge=1, le=9)
    knots: tuple[float, ...] = quantity(
        "Full knot vector, cam angles from the nose, non-decreasing, each end repeated "
        "degree + 1 times (coefficients + degree + 1 values)", "deg", min_items=4)
    coefficients: tuple[float, ...] = quantity(
        "B-spline coefficients; the first and last are 0 (the base circle)", "mm", min_items=2)

    def problems(self, path: str) -> list[Problem]:
        if len(self.knots) != len(self.coefficients) + self.degree + 1:
            return [Problem(f"{path}.knots", f"has {len(self.knots)} values for "
                            f"{len(self.coefficients)} coefficients of degree {self.degree}",
                            None, f"{len(self.coefficients) + self.degree + 1} knots")]
        return []


@dataclass(frozen=True, kw_only=True)
class Lift:
    """The lift law. Angles are cam degrees from the maximum-lift (nose) position."""

    form: Literal["four_power", "multipol", "table", "exp_poly", "polynomial",
                  "williams_elementary", "williams_low_jerk", "spline"] = option(
        "Lift form: four_power, multipol, table, exp_poly, polynomial, williams_elementary, "
        "williams_low_jerk, spline", example="four_power")
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
    spline: Spline | None = section("B-spline lift (written by camtrain design)",
                                    applies="form = spline")

    schema_rules = tuple(When("form", (form,), require=(form,),
                              forbid=tuple(f for f in LIFT_FORMS if f != form))
                         for form in LIFT_FORMS)

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
