"""Friction-correlation effect (engine decks): Patton-Nitschke-Heywood 1989, Sandoval-Heywood
2003 term by term and Chen-Flynn with the user's constants, at the run speed, load and oil
temperature (:mod:`camtrain.engine.correlations`). Beside FLAME on a full engine deck; alone on a
bare one (geometry, bearing sizes and valve-train layout only). docs/engine.md.
"""
from __future__ import annotations


def missing(deck) -> list[str]:
    return [] if getattr(deck, "correlations", None) is not None else [
        "[correlations] section (valve-train layout, compression ratio)"]


def _oil_text(deck) -> str:
    oil = getattr(deck, "oil", None)
    if oil is None:
        return "no [oil]: the reference oil nu_0 = 10.6 mm²/s (r = 1)"
    if oil.grade is None:
        return f"oil {oil.viscosity * 1e6:g} mm²/s"
    return f"oil {oil.grade} at {oil.temperature:g} °C ({oil.shear}-shear Vogel fit)"


def reason(deck, planned) -> str:
    c = deck.correlations
    models = list(c.models) + (["chen_flynn (user constants)"] if c.chen_flynn else [])
    vt = c.valve_train
    n0 = ("each model's N_0" if c.boundary_speed == "per_model"
          else f"N_0 of {c.boundary_speed} for both")
    load = (f"; load: diagram scaled to {deck.load.measure} {deck.load.value / 1e5:g} bar"
            if deck.load is not None else "")
    beside = " beside FLAME" if "EngineFriction" in planned else (
        " alone (no [flame])" if deck.flame is None else "")
    return (f"{', '.join(models)}{beside}: {vt.layout} {vt.follower} follower, {_oil_text(deck)}"
            f", {n0}{load}")


def run(deck, inputs, result):
    from camtrain.assemble import correlations as build
    from camtrain.engine.correlations import (
        GROUPS,
        MODELS,
        FrictionCorrelations,
        OperatingPoint,
        chen_flynn_fmep,
        correlation_terms,
        fmep_to_power,
    )

    c = deck.correlations
    engine = build.correlation_engine(deck)
    nu = build.oil_viscosity(deck)
    op = OperatingPoint(deck.speed.engine, build.intake_ratio(deck), nu)
    n0 = None if c.boundary_speed == "per_model" else MODELS[c.boundary_speed].n0
    terms, totals, notes = {}, {}, {}
    for name in c.models:
        model = MODELS[name]
        terms[name] = {k: float(v) for k, v in correlation_terms(model, engine, op, n0).items()}
        totals[name] = sum(terms[name].values())
        notes[name] = f"N_0 = {model.n0 if n0 is None else n0:g} rpm"
    if c.chen_flynn is not None:
        p_max = build.peak_pressure(deck)
        totals["chen_flynn"] = float(chen_flynn_fmep(build.chen_flynn_constants(deck), engine,
                                                     deck.speed.engine, p_max))
        notes["chen_flynn"] = f"p_max = {p_max / 1e5:.4g} bar absolute"
        result.add_metric("peak_pressure", p_max, "Pa", "peak cylinder pressure (absolute)",
                          component="chen_flynn")
    out = FrictionCorrelations(deck.speed.engine, engine.displacement, engine.strokes, terms,
                               totals, nu, notes)
    result.add_metric("correlation_oil_viscosity", nu, "m^2/s",
                      "oil kinematic viscosity of the correlations")
    result.add_metric("correlation_intake_ratio", op.intake_ratio, "-",
                      "intake over atmospheric pressure p_i/p_a of the correlations")
    for name, fmep in totals.items():
        label = MODELS[name].label if name in MODELS else "Chen-Flynn"
        rows = [("fmep", fmep, "Pa", f"{label}: friction mean effective pressure"),
                ("power", out.power(name), "W", f"{label}: friction power")]
        for term, value in terms.get(name, {}).items():
            rows.append((f"{term}_fmep", value, "Pa", f"{label}: {term.replace('_', ' ')} "
                         f"({GROUPS[term].replace('_', ' ')})"))
        for group in dict.fromkeys(GROUPS.values()):
            if name in terms:
                rows.append((f"{group}_power", float(fmep_to_power(
                    out.group(name, group), engine.displacement, deck.speed.engine,
                    engine.strokes)), "W", f"{label}: {group.replace('_', ' ')} friction power"))
        result.add_metrics(rows, component=name)
    return out
