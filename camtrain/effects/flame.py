"""FLAME effect: the friction of a whole engine at the run speed, by component (Yang 1992
Part IV, Table 7.1): crank bearings + valve trains + piston assemblies + accessories, the total
and the friction mean effective pressure (:mod:`camtrain.engine.flame`). A sweep over speed
gives Yang's table and the stacked plot.
"""
from __future__ import annotations


def missing(deck) -> list[str]:
    return [] if getattr(deck, "flame", None) is not None else ["[flame] section"]


def reason(deck, planned) -> str:
    have = [n for n, p in (("crank bearings", "EngineBearings"),
                           ("valve trains", "ValveTrainFriction"),
                           ("piston assemblies", "PistonFriction")) if p in planned]
    lack = [n for n, p in (("crank bearings", "EngineBearings"),
                           ("valve trains", "ValveTrainFriction"),
                           ("piston assemblies", "PistonFriction")) if p not in planned]
    text = "sum of " + (", ".join(have) or "no components")
    text += f" + accessories ({deck.flame.accessories.share * 100:g} % of the components)"
    if lack:
        text += "; left out (no data): " + ", ".join(lack)
    return text


def run(deck, inputs, result):
    import math

    from camtrain.engine.crank_bearings import EngineBearings
    from camtrain.engine.flame import EngineFriction, flame_total, treatment_totals
    from camtrain.engine.valve_trains import ValveTrainFriction
    from camtrain.piston.product import PistonFriction

    f = deck.flame
    e = deck.engine
    bearings = inputs.get(EngineBearings)
    valve = inputs.get(ValveTrainFriction)
    piston = inputs.get(PistonFriction)
    lacking = []
    b_power, treatments = 0.0, {}
    if bearings is not None:
        total = bearings.total(f.bearing_method)
        if total is None:
            lacking.append("bearings")
            result.warn(f"flame.bearing_method: the crank bearings were not solved by the "
                        f"{f.bearing_method!r} method; bearings left out of the total")
        else:
            b_power = total
            treatments = treatment_totals(bearings, f.bearing_method)
    else:
        lacking.append("bearings")
    v_power = valve.total if valve is not None else 0.0
    if valve is None:
        lacking.append("valve trains")
    p_power = piston.engine_power if piston is not None else 0.0
    if piston is None:
        lacking.append("piston assemblies")
    if lacking:
        result.warn("flame: " + ", ".join(lacking) + " not computed (no data in the deck); "
                    "the total leaves them out")
    # the swept volume of the fmep: a bare engine deck (no [[cylinders]]) counts its
    # cylinders in correlations.cylinders
    displacement = deck.cylinder_count * math.pi / 4.0 * e.bore ** 2 * 2.0 * e.crank_radius
    row = flame_total(b_power, v_power, p_power, displacement=displacement,
                      engine_speed=deck.speed.engine / (2.0 * math.pi), strokes=e.strokes,
                      accessory_share=f.accessories.share)
    met = result.add_metric
    met("flame_bearings", row.bearings, "W", f"crank bearings ({f.bearing_method}; partially "
        "grooved mains: mean of grooved and ungrooved)")
    for tag, value in treatments.items():
        met(f"flame_bearings_{tag}", value, "W", f"crank bearings, all {tag}")
    met("flame_valve_train", row.valve_train, "W", "valve trains (cams, bearings, guides)")
    met("flame_piston", row.piston, "W", "piston assemblies (rings, oil-control ring, skirt)")
    met("flame_accessories", row.accessories, "W",
        f"accessories ({f.accessories.share * 100:g} % of the components)")
    met("flame_total", row.total, "W", "engine friction power (FLAME total)")
    met("fmep", row.fmep, "Pa", "friction mean effective pressure")
    components = row.total - row.accessories
    for name in ("bearings", "valve_train", "piston"):
        share = getattr(row, name) / components if components > 0 else math.nan
        met(f"flame_share_{name}", share, "-", f"{name.replace('_', ' ')}: share of the "
            "components (without accessories)")
    return EngineFriction(deck.speed.engine, row, {} if valve is None else
                          {n: valve.power(n) for n in valve.parts},
                          {} if valve is None else valve.parts, treatments, tuple(lacking))
