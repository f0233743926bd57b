"""Summary tables an effect declares for the terminal and report.txt (``EffectSpec.summary``).

Each function takes a run's Result and its deck model and returns the tables an engineer reads
first from that effect: one row per bearing, ring or component, in the deck's units with the
unit in every heading. The catalogue names the function; the report calls the functions of the
effects the plan ran, in the plan's order, and never looks at column names to decide.
"""
from __future__ import annotations

import math

from camtrain.catalogue import components_of, planned_products
from camtrain.report.console import Table
from camtrain.report.display import fmt
from camtrain.result import Result

_DEG = 180.0 / math.pi


def _value(result: Result, component: str | None, name: str, scale: float = 1.0) -> str:
    m = result.component(component).metrics.get(name)
    return "—" if m is None else fmt(m.value * scale)


def _film(result: Result, component: str | None, name: str) -> str:
    """A ring film in µm, or "dry" at the film march's floor (no oil film: not a thickness)."""
    from camtrain.piston.film_floor import at_floor

    m = result.component(component).metrics.get(name)
    if m is None:
        return "—"
    return "dry" if at_floor(m.value) else fmt(m.value * 1e6)


def _angle(result: Result, component: str | None, name: str) -> str:
    m = result.component(component).metrics.get(name)
    return "" if m is None or m.angle is None else f"{m.angle * _DEG:.1f}"


def _components(result: Result, product: str) -> list[str]:
    """The result's components the effect making ``product`` writes (the rows of its table,
    EffectSpec.components)."""
    return components_of(result.plan, product, result.components)


def _right(*headers: str) -> list[tuple[str, str, str | None]]:
    return [(headers[0], "left", None)] + [(h, "right", None) for h in headers[1:]]


def crank_bearings(result: Result, deck) -> list[Table]:
    """Every big-end and main: smallest film of the orbit and where, peak load and specific
    load (peak load over the projected area d·b), cycle-mean power of the orbit and Petroff's."""
    names = _components(result, "EngineBearings")
    if not names:
        return []
    table = Table("crank bearings (orbit's h_min and where, crank deg; W/db = peak load / "
                  "(d b); cycle-mean power)", _right("bearing", "h_min [µm]", "at [deg]", "W/db [MPa]",
                                          "P [W]", "Petroff [W]"))
    for comp in names:
        kind = comp.rsplit("_", 1)[0]
        geometry = getattr(getattr(deck, "bearings", None), kind, None)
        peak = result.component(comp).metrics.get("max_load")
        specific = "—"
        if peak is not None and geometry is not None:
            specific = fmt(peak.value / (geometry.diameter * geometry.length) * 1e-6)
        table.add_row(f"{kind.replace('_', '-')} {comp.rsplit('_', 1)[1]}",
                      _value(result, comp, "min_film_dynamic", 1e6),
                      _angle(result, comp, "min_film_dynamic"), specific,
                      _value(result, comp, "power_dynamic"), _value(result, comp, "power_petroff"))
    table.add_row(("total", "bold"), "", "", "",
                  (_value(result, None, "total_power_dynamic"), "bold"),
                  _value(result, None, "total_power_petroff"))
    return [table]


def bearing_orbits(result: Result, deck) -> list[Table]:
    """Every camshaft bearing: largest load, smallest film of its orbit and where, largest
    eccentricity ratio and cycle-mean power."""
    names = _components(result, "BearingOrbits")
    # those with an orbit: none for a bearing of method petroff, nor for one whose orbit did
    # not converge (warned), which the run found, not the plan
    names = [c for c in names if "min_film" in result.component(c).metrics]
    if not names:
        return []
    table = Table("camshaft bearings (journal orbits; cam deg; cycle-mean power)", _right(
                      "bearing", "h_min [µm]", "at [deg]", "W_max [N]", "ε_max [-]", "P [W]"))
    for comp in names:
        table.add_row(comp.replace("_", " "), _value(result, comp, "min_film", 1e6),
                      _angle(result, comp, "min_film"), _value(result, comp, "max_load"),
                      _value(result, comp, "max_eccentricity"), _value(result, comp, "power_mean"))
    return [table]


def piston_rings(result: Result, deck) -> list[Table]:
    """Every compression ring: thinnest starved and flooded film, peak friction, mean power and
    the share of the cycle in boundary friction."""
    names = _components(result, "PistonFriction")
    if not names:
        return []
    table = Table("compression rings of one piston (thinnest film, dry = no oil film; crank "
                  "deg from firing TDC)", _right(
                      "ring", "starved [µm]", "at [deg]", "flooded [µm]", "F_max [N]", "P [W]",
                      "boundary [%]"))
    for comp in names:
        table.add_row(comp.replace("_", " "), _film(result, comp, "min_film"),
                      _angle(result, comp, "min_film"), _film(result, comp, "min_film_flooded"),
                      _value(result, comp, "peak_friction"), _value(result, comp, "power_mean"),
                      _value(result, comp, "boundary_share", 100.0))
    return [table]


#: the FLAME components in the order of Yang's (1992) Table 7.x breakdown
FLAME_PARTS = (("flame_bearings", "crank bearings"), ("flame_valve_train", "valve trains"),
               ("flame_piston", "pistons"), ("flame_accessories", "accessories"))


def flame_parts(result: Result) -> list[tuple[str, float]]:
    """(label, power [W]) of every FLAME component, when the plan made the FLAME total (its
    effect states all of them); none otherwise."""
    if "EngineFriction" not in planned_products(result.plan):
        return []
    return [(label, result.metrics[name].value) for name, label in FLAME_PARTS]


def flame(result: Result, deck) -> list[Table]:
    """The FLAME engine total: power and share of every component, total and fmep."""
    parts, total = flame_parts(result), result.metrics.get("flame_total")
    if not parts or total is None:
        return []
    table = Table("engine friction (FLAME total)", _right("component", "power [W]",
                                                          "of total [%]"))
    for label, power in parts:
        share = 100.0 * power / total.value if total.value else math.nan
        table.add_row(label, fmt(power), f"{share:.1f}")
    table.add_row(("total", "bold"), (fmt(total.value), "bold"), "100.0")
    fmep = result.metrics.get("fmep")
    if fmep is not None:
        table.add_row(("fmep [kPa]", "bold"), (fmt(fmep.value * 1e-3), "bold"), "")
    return [table]


#: the correlation models an engine deck may compute, with the names their metrics carry
CORRELATION_MODELS = (("pnh1989", "PNH 1989"),
                      ("sandoval_heywood2003", "S-H 2003"),
                      ("chen_flynn", "C-F"))
#: (group, its short heading: the table must read at 80 columns)
CORRELATION_GROUPS = (("crankshaft", "crank"), ("reciprocating", "recip."),
                      ("valve_train", "valves"), ("auxiliaries", "aux."))


def correlations(result: Result, deck) -> list[Table]:
    """Each friction correlation the run computed: fmep, power and its power by group."""
    ran = [(name, label) for name, label in CORRELATION_MODELS if name in result.components]
    if not ran:
        return []
    table = Table("friction correlations (PNH Patton-Nitschke-Heywood, S-H Sandoval-Heywood, "
                  "C-F Chen-Flynn)",
                  _right("model", "fmep [kPa]", "total [W]",
                         *(f"{short} [W]" for _, short in CORRELATION_GROUPS)))
    for name, label in ran:
        table.add_row(label, _value(result, name, "fmep", 1e-3), _value(result, name, "power"),
                      *(_value(result, name, f"{g}_power") for g, _ in CORRELATION_GROUPS))
    return [table]
