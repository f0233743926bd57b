"""Deck sections of the lift law ([lift] and its forms). Part of the deck schema (schema.py).

The ramps and the four-power form are here; every other form is a deferred section in a module
of its own (``schema_lift_<form>.py``), imported when a deck has it.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

from camtrain.deck.fields import When, option, quantity, section
from camtrain.errors import Problem

if TYPE_CHECKING:
    from camtrain.deck.schema_lift_exp_poly import ExpPoly
    from camtrain.deck.schema_lift_multipol import Multipol
    from camtrain.deck.schema_lift_polynomial import Polynomial
    from camtrain.deck.schema_lift_spline import Spline
    from camtrain.deck.schema_lift_table import Table
    from camtrain.deck.schema_lift_williams import WilliamsElementary, WilliamsLowJerk

LIFT_FORMS = ("four_power", "multipol", "table", "exp_poly", "polynomial",
              "williams_elementary", "williams_low_jerk", "spline")

#: the deferred forms' classes: name -> "module:Class" (fields.section(schema=...))
DEFERRED_FORMS = {name: f"camtrain.deck.schema_lift_{module}:{name}" for module, names in (
    ("multipol", ("Segment", "Multipol")), ("table", ("Table",)), ("exp_poly", ("ExpPoly",)),
    ("polynomial", ("Polynomial",)), ("spline", ("Spline",)),
    ("williams", ("ElementaryHalf", "WilliamsElementary", "LowJerkHalf", "WilliamsLowJerk")))
    for name in names}


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
    multipol: Multipol | None = section("Multipol segments", applies="form = multipol",
                                        schema=DEFERRED_FORMS["Multipol"])
    table: Table | None = section("Data points", applies="form = table",
                                  schema=DEFERRED_FORMS["Table"])
    exp_poly: ExpPoly | None = section("Exponential fit", applies="form = exp_poly",
                                       schema=DEFERRED_FORMS["ExpPoly"])
    polynomial: Polynomial | None = section("Polynomial", applies="form = polynomial",
                                            schema=DEFERRED_FORMS["Polynomial"])
    williams_elementary: WilliamsElementary | None = section(
        "Williams elementary curve", applies="form = williams_elementary",
        schema=DEFERRED_FORMS["WilliamsElementary"])
    williams_low_jerk: WilliamsLowJerk | None = section(
        "Williams low-jerk curve", applies="form = williams_low_jerk",
        schema=DEFERRED_FORMS["WilliamsLowJerk"])
    spline: Spline | None = section("B-spline lift (written by camtrain design)",
                                    applies="form = spline", schema=DEFERRED_FORMS["Spline"])

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
