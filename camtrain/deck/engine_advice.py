"""Advice on an engine deck that is valid but suspicious (printed by `check` and by a run).

The out-of-balance moment is the classic unit slip: Yang (1992) prints "N m" for both engines,
but his Zeta values (134.10, 116.40, 53.20) are plausible only in N·mm, his Ruston value
(139.19) only in N·m (reference notes §3.1, C-M2). A crank component's mass-radius product
m r = M_o / g is compared with the rotating mass-radius product of the crank train it sits in,
(m_p + m_c) R: a real web, pin or counterweight is within a factor 30 of it. A value 1000 times
too large or too small, that the other unit would bring into range, is flagged with that unit.
"""
from __future__ import annotations

from camtrain.deck.engine_units import MOMENT_UNITS
from camtrain.units import from_si

#: a component's m r may lie this factor above or below (m_p + m_c) R before check says so
PLAUSIBLE_FACTOR = 30.0
#: Ocvirk's short bearing is trusted up to this land b/d (Yang's own limit)
SHORT_BEARING_LIMIT = 0.7
#: steel, for the mass-radius scale of an engine whose masses are not given
_STEEL = 7800.0


def _reference_unbalance(deck) -> float:
    e = deck.engine
    mass = e.piston_mass + e.rod_mass
    if mass <= 0.0:  # no masses given: a steel throw of the bore's size
        mass = _STEEL * e.bore ** 2 * e.crank_radius
    return mass * e.crank_radius


def unit_advice(deck) -> list[str]:
    """A warning per crank component whose moment looks like the other unit."""
    ref = _reference_unbalance(deck)
    out = []
    for i, comp in enumerate(deck.crank_components):
        if comp.moment == 0.0:
            continue
        ratio = comp.unbalance / ref
        if 1.0 / PLAUSIBLE_FACTOR <= ratio <= PLAUSIBLE_FACTOR:
            continue
        other = next(u for u in MOMENT_UNITS if u != comp.moment_unit)
        scale = MOMENT_UNITS[other] / MOMENT_UNITS[comp.moment_unit]
        hint = (f"; it would be plausible in {other}" if 1.0 / PLAUSIBLE_FACTOR
                <= ratio * scale <= PLAUSIBLE_FACTOR else "")
        out.append(f"crank_components[{i}].moment = {comp.moment:g} {comp.moment_unit} gives "
                   f"m r = {comp.unbalance:.4g} kg m, {ratio:.3g} x the crank train's "
                   f"(m_p + m_c) R = {ref:.4g} kg m: check moment_unit{hint}")
    return out


def engine_advisories(deck) -> list[str]:
    e = deck.engine
    out = unit_advice(deck) if None not in (e.piston_mass, e.rod_mass) else []
    for name in ("big_end", "main") if deck.bearings is not None else ():
        b = getattr(deck.bearings, name)
        land = (b.length - b.groove_width) / (2.0 if b.grooving != "none" else 1.0)
        ratio = land / b.diameter
        if deck.solver.bearing_model == "short" and ratio > SHORT_BEARING_LIMIT:
            out.append(f"bearings.{name}: land b/d = {ratio:.3g} > {SHORT_BEARING_LIMIT}; the "
                       "short-bearing film overstates the film there (solver.bearing_model = "
                       "\"finite\")")
    for i, t in enumerate(deck.pressure):
        if t.reference == "gauge" and min(t.pascal) > 0.5e5 and max(t.pascal) > 0.0:
            out.append(f"pressure[{i}]: every gauge value is above 0.5 bar (lowest "
                       f"{min(t.values):g} {t.unit}); if the table is absolute, say "
                       "reference = \"absolute\"")
    if deck.solver.mobility_factor == "yang1992_program":
        out.append("solver.mobility_factor = yang1992_program: the mobility is halved to match "
                   "Yang's printed films (not the physics; docs/engine.md)")
    if e.rod_length is not None and e.rod_length / e.crank_radius < 2.5:
        out.append(f"engine.rod_length: L/R = {e.rod_length / e.crank_radius:.3g} is unusually "
                   f"short ({from_si(e.rod_length, 'mm'):g} mm)")
    return out
