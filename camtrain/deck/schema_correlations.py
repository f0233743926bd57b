"""Deck sections of the engine friction correlations (engine decks): ``[correlations]`` (what
Patton-Nitschke-Heywood 1989, Sandoval-Heywood 2003 and Chen-Flynn need of the engine beyond
its bore and stroke), ``[oil]`` (grade or viscosity and temperature) and ``[load]`` (the
cylinder-pressure diagram scaled to a peak pressure or an IMEP). Part of the engine deck
schema; docs/engine.md.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import option, quantity, section
from camtrain.errors import Problem

#: the published correlation models a deck may list (camtrain.engine.correlations.MODELS)
MODEL_NAMES = ("pnh1989", "sandoval_heywood2003")
#: valve-train layouts with published constants (camtrain.formulas.engine_friction)
LAYOUTS = ("sohc_finger", "sohc_rocker", "sohc_direct", "dohc_finger", "dohc_direct", "ohv")


@dataclass(frozen=True, kw_only=True)
class CorrelationValveTrain:
    """The valve train as the correlations see it: layout, follower and counts."""

    layout: Literal["sohc_finger", "sohc_rocker", "sohc_direct", "dohc_finger",
                    "dohc_direct", "ohv"] = option(
        "Valve-train layout: single or double overhead camshaft with finger followers, "
        "rocker arms or direct-acting (bucket) tappets, or pushrod (ohv)",
        example="dohc_direct")
    follower: Literal["flat", "roller"] = option(
        "Follower: flat (sliding, boundary-mixed friction) or roller (rolling friction)",
        example="flat")
    valves_per_cylinder: int = quantity("Valves per cylinder", ge=1, le=8, example=4)
    camshaft_bearings: int = quantity("Camshaft bearings in the whole engine (every camshaft)",
                                      ge=1, le=64, example=10)
    valve_lift: float = quantity("Maximum valve lift", "mm", gt=0, lt=50, example=8.0)

    def problems(self, path: str) -> list[Problem]:
        if self.layout == "ohv" and self.follower == "roller":
            return [Problem(f"{path}.follower", "has no published constant for layout = ohv",
                            "roller", "flat, or another layout (the OHV roller constant is "
                            "printed 0.5 in the public copies, a suspected misprint: see "
                            "docs/engine.md)")]
        return []


@dataclass(frozen=True, kw_only=True)
class ChenFlynnSection:
    """Chen-Flynn: fmep = constant + a p_max + b S_p + c S_p^2. No universal constants exist:
    each published set is a fit to one engine, so every coefficient is the user's."""

    constant: float = quantity("Constant term", "bar", example=0.137)
    peak_pressure_coefficient: float = quantity("Coefficient of the peak cylinder pressure",
                                                "-", example=0.005)
    piston_speed_coefficient: float = quantity("Coefficient of the mean piston speed",
                                               "bar·s/m", example=0.162)
    piston_speed_squared_coefficient: float = quantity(
        "Coefficient of the mean piston speed squared", "bar·s²/m²", default=0.0)
    peak_pressure: float | None = quantity(
        "Peak cylinder pressure, absolute; unset: the peak of the run's pressure diagram (after "
        "[load]) plus 1 atm", "bar", default=None, gt=0, lt=1000)


@dataclass(frozen=True, kw_only=True)
class CorrelationsSection:
    """Engine friction by correlation beside FLAME (or alone, on a bare engine deck)."""

    models: tuple[str, ...] = option(
        "Published models to compute: pnh1989 (Patton, Nitschke & Heywood 1989), "
        "sandoval_heywood2003 (Sandoval & Heywood 2003); Chen-Flynn runs when "
        "[correlations.chen_flynn] is given", default=MODEL_NAMES)
    boundary_speed: Literal["per_model", "pnh1989", "sandoval_heywood2003"] = option(
        "N_0 of the boundary factor (1 + N_0/N): each model's own (PNH 1000, Sandoval-Heywood "
        "500 rpm), or one of them for both", default="per_model")
    compression_ratio: float = quantity("Compression ratio r_c (ring gas loading)", gt=1,
                                        lt=40, example=10.0)
    intake_pressure_ratio: float = quantity(
        "Intake manifold over atmospheric pressure p_i/p_a at the deck's pressure diagram (a "
        "[load] scales it with the diagram); 1 at wide-open throttle", "-", default=1.0, gt=0,
        lt=10)
    cylinders: int | None = quantity(
        "Cylinders; unset: the [[cylinders]] listed (give it for a bare engine deck)",
        default=None, ge=1, le=32)
    main_bearings: int | None = quantity(
        "Main bearings; unset: one more than engine.bay_lengths", default=None, ge=1, le=33)
    main_diameter: float | None = quantity(
        "Main-bearing diameter; unset: bearings.main.diameter", "mm", default=None, gt=0)
    main_length: float | None = quantity(
        "Main-bearing length; unset: bearings.main.length", "mm", default=None, gt=0)
    rod_diameter: float | None = quantity(
        "Connecting-rod (big-end) bearing diameter; unset: bearings.big_end.diameter", "mm",
        default=None, gt=0)
    rod_length: float | None = quantity(
        "Connecting-rod (big-end) bearing length; unset: bearings.big_end.length", "mm",
        default=None, gt=0)
    valve_train: CorrelationValveTrain = section("Valve-train layout, follower and counts",
                                                 required=True)
    chen_flynn: ChenFlynnSection | None = section(
        "Chen-Flynn with the user's own constants (no defaults exist)")

    def problems(self, path: str) -> list[Problem]:
        out = []
        for name in self.models:
            if name not in MODEL_NAMES:
                out.append(Problem(f"{path}.models", "unknown model", name,
                                   " or ".join(MODEL_NAMES)))
        if len(set(self.models)) != len(self.models):
            out.append(Problem(f"{path}.models", "lists a model twice", list(self.models)))
        return out


OIL_GRADE_NAMES = ("5W20", "5W40", "10W30", "15W40", "20W50", "SAE10", "SAE30", "SAE50")


@dataclass(frozen=True, kw_only=True)
class OilSection:
    """The engine oil: a grade (Vogel fit) or a viscosity, at the oil temperature of the run."""

    grade: Literal["5W20", "5W40", "10W30", "15W40", "20W50", "SAE10", "SAE30",
                   "SAE50"] | None = option(
        "Oil grade, its kinematic viscosity from a Vogel fit at the temperature (give grade "
        "or viscosity)", default=None, example="10W30")
    viscosity: float | None = quantity(
        "Kinematic viscosity at the run's oil temperature (instead of a grade)", "mm²/s",
        default=None, gt=0, lt=1e5)
    temperature: float = quantity("Oil temperature of the run", "°C", default=90.0, gt=-40,
                                  lt=250)
    shear: Literal["low", "high"] = option(
        "Grade viscosity: the Vogel fit as printed (low shear), or times the grade's "
        "high-shear ratio", default="low")
    reference_temperature: float | None = quantity(
        "Oil temperature at which the deck's FLAME viscosities hold (bearings, ring-pack oil, "
        "valve-train decks); when set, FLAME's viscosities follow the grade's Vogel ratio "
        "nu(temperature) / nu(reference_temperature); unset: FLAME keeps the deck's",
        "°C", default=None, gt=-40, lt=250)

    def problems(self, path: str) -> list[Problem]:
        out = []
        if (self.grade is None) == (self.viscosity is None):
            out.append(Problem(path, "needs exactly one of grade and viscosity", None,
                               "grade = \"10W30\" (say) or viscosity in mm²/s"))
        if self.reference_temperature is not None and self.grade is None:
            out.append(Problem(f"{path}.reference_temperature", "needs an oil grade (its Vogel "
                               "fit moves the viscosities with temperature)", None,
                               "oil.grade"))
        return out


@dataclass(frozen=True, kw_only=True)
class LoadSection:
    """Engine load: the run's cylinder-pressure diagram scaled (above the crankcase) so that its
    peak pressure or its net IMEP takes the value."""

    measure: Literal["peak_pressure", "imep"] = option(
        "What value sets: the peak gauge pressure of the diagram, or its net indicated mean "
        "effective pressure over the cycle", example="imep")
    value: float = quantity("Target peak gauge pressure or net IMEP", "bar", gt=0, lt=1000,
                            example=8.0)


_CRANK_TRAIN = (("engine.rod_length", "rod_length"), ("engine.piston_mass", "piston_mass"),
                ("engine.rod_mass", "rod_mass"), ("engine.bay_lengths", "bay_lengths"))


def bare_engine_problems(deck) -> list[Problem]:
    """Rules of an engine deck that may be bare: without [correlations] the crank train is
    required as before; with it, the correlations must find every number they need, and
    [load], [piston] and a Chen-Flynn without peak_pressure need a pressure diagram."""
    out: list[Problem] = []
    c, e = deck.correlations, deck.engine
    if c is None:
        for where, what in (("cylinders", deck.cylinders), ("pressure", deck.pressure)):
            if not what:
                out.append(Problem(where, "required section is missing", None,
                                   f"[[{where}]] (only a deck with [correlations] may leave "
                                   "the crank train out)"))
        if deck.bearings is None:
            out.append(Problem("bearings", "required section is missing", None,
                               "[bearings.big_end] and [bearings.main] (only a deck with "
                               "[correlations] may leave them out)"))
        for where, name in _CRANK_TRAIN:
            if getattr(e, name) is None:
                out.append(Problem(where, "required field is missing", None,
                                   "a value (only a deck with [correlations] may leave the "
                                   "crank train out)"))
        return out
    out += _correlation_data_problems(deck)
    needs_diagram = [(deck.load is not None, "load"), (deck.piston is not None, "piston"),
                     (c.chen_flynn is not None and c.chen_flynn.peak_pressure is None,
                      "correlations.chen_flynn.peak_pressure")]
    for needed, where in needs_diagram:
        if needed and not deck.pressure:
            out.append(Problem(where, "needs a cylinder-pressure diagram", None,
                               "[[pressure]] tables (or, for Chen-Flynn, a peak_pressure)"))
    if deck.load is not None and e.rod_length is None and deck.load.measure == "imep":
        out.append(Problem("load.measure", "imep needs the piston's stroke volume over the "
                           "crank angle", "imep", "engine.rod_length, or measure = "
                           "\"peak_pressure\""))
    if deck.piston is not None and (e.rod_length is None or not deck.cylinders):
        out.append(Problem("piston", "needs the crank train", None,
                           "engine.rod_length and [[cylinders]]"))
    return out


def _correlation_data_problems(deck) -> list[Problem]:
    c, out = deck.correlations, []
    if c.cylinders is None and not deck.cylinders:
        out.append(Problem("correlations.cylinders", "is required without [[cylinders]]",
                           None, "the number of cylinders"))
    elif c.cylinders is not None and deck.cylinders and c.cylinders != len(deck.cylinders):
        out.append(Problem("correlations.cylinders", "differs from the [[cylinders]] listed",
                           c.cylinders, f"{len(deck.cylinders)} (or unset)"))
    if c.main_bearings is None and deck.engine.bay_lengths is None:
        out.append(Problem("correlations.main_bearings", "is required without "
                           "engine.bay_lengths", None, "the number of main bearings"))
    for field, bearing, attr in (("main_diameter", "main", "diameter"),
                                 ("main_length", "main", "length"),
                                 ("rod_diameter", "big_end", "diameter"),
                                 ("rod_length", "big_end", "length")):
        if getattr(c, field) is None and deck.bearings is None:
            out.append(Problem(f"correlations.{field}", "is required without [bearings]",
                               None, f"mm (or bearings.{bearing}.{attr})"))
    return out
