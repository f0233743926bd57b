"""Engine runs in the report: the header rows and the bearing table laid out like Yang's (1992)
Tables 2.1-2.4 (per bearing: Petroff power | steady-load power / h_min | dynamic-load power /
h_min; engine totals), in kW and µm as he printed them."""
from __future__ import annotations

from camtrain.catalogue import components_of
from camtrain.result import Result
from camtrain.units import from_si


def engine_header_rows(deck, result: Result | None) -> list[tuple[str, str]]:
    e, s = deck.engine, deck.solver
    c = deck.correlations
    cylinders = len(deck.cylinders) if deck.cylinders else c.cylinders
    rows = [("Engine speed (rpm)", f"{deck.rpm:g}"),
            ("Cylinders / strokes", f"{cylinders} / {e.strokes}"),
            ("Bore / stroke (mm)", f"{from_si(e.bore, 'mm'):g} / "
                                   f"{from_si(2 * e.crank_radius, 'mm'):g}")]
    if not deck.has_crank_train:   # a bare engine deck: the correlations alone
        return rows + [("Crank train", "not described (correlations only)")]
    rows += [("Rod length (mm)", f"{from_si(e.rod_length, 'mm'):g}"),
             ("Piston / rod mass (kg)", f"{e.piston_mass:g} / {e.rod_mass:g}")]
    for name in ("big_end", "main") if deck.bearings is not None else ():
        b = getattr(deck.bearings, name)
        rows.append((f"{name.replace('_', '-').capitalize()} d / b / c (mm)",
                     f"{from_si(b.diameter, 'mm'):g} / {from_si(b.length, 'mm'):g} / "
                     f"{from_si(b.clearance, 'mm'):g}, grooving {b.grooving}, "
                     f"η {b.viscosity_at(deck.speed.omega):.4g} Pa·s"))
    rows.append(("Bearing model / film", f"{s.bearing_model}, {s.mobility} mobility, "
                 f"{s.mobility_factor}, {s.film} film"))
    if result is not None:
        m = result.metrics.get("total_power_dynamic")
        rows.append(("Crank bearings power (W)", "not computed" if m is None
                     else f"{m.value:.2f}"))
    return rows


def _cell(result: Result, name: str, scale: float, digits: int) -> str:
    m = result.metrics.get(name)
    return "-" if m is None else f"{m.value * scale:.{digits}f}"


def bearing_table_lines(result: Result, width: int = 100) -> list[str]:
    """The crank-bearing table of a run (empty when the run has no crank bearings)."""
    names = components_of(result.plan, "EngineBearings", result.components)
    if not names:
        return []
    out = ["--- CRANK BEARINGS (as Yang 1992 Tables 2.1-2.4: power kW / minimum film µm) "
           .ljust(width, "-"),
           f"  {'bearing':<12} {'Petroff':>9}   {'steady-load eqs':>19}   {'dynamic-load eqs':>19}"
           f"   {'at [deg]':>8}",
           f"  {'':<12} {'(kW)':>9}   {'(kW)':>9} {'(µm)':>9}   {'(kW)':>9} {'(µm)':>9}"]
    for c in names:
        at = result.metrics.get(f"{c}_min_film_dynamic")
        where = "" if at is None or at.angle is None else f"{at.angle * 57.29577951308232:.1f}"
        out.append(f"  {c.replace('_', ' '):<12} {_cell(result, f'{c}_power_petroff', 1e-3, 4):>9}"
                   f"   {_cell(result, f'{c}_power_steady', 1e-3, 4):>9} "
                   f"{_cell(result, f'{c}_min_film_steady', 1e6, 4):>9}"
                   f"   {_cell(result, f'{c}_power_dynamic', 1e-3, 4):>9} "
                   f"{_cell(result, f'{c}_min_film_dynamic', 1e6, 4):>9}   {where:>8}")
    out.append(f"  {'Total (kW)':<12} {_cell(result, 'total_power_petroff', 1e-3, 4):>9}"
               f"   {_cell(result, 'total_power_steady', 1e-3, 4):>9} {'':>9}"
               f"   {_cell(result, 'total_power_dynamic', 1e-3, 4):>9}")
    out.append("")
    return out
