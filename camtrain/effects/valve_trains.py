"""Valve-train effect of an engine deck: each valve-train deck the engine includes by path
([[flame.valve_trains]]) runs through its own plan at the engine's camshaft speed (the scene
composes them, camtrain.assemble.valve_trains makes the decks, the runner runs them before this
effect: EffectSpec.includes); the cams, camshaft bearings and guides of every camshaft are
summed (Yang 1992 Part IV, Fig. 4.7; :mod:`camtrain.engine.valve_trains`)."""
from __future__ import annotations


def missing(deck) -> list[str]:
    flame = getattr(deck, "flame", None)
    if flame is None or not flame.valve_trains:
        return ["[[flame.valve_trains]] (valve-train decks included by path)"]
    return []


def reason(deck, planned) -> str:
    names = ", ".join(v.name for v in deck.flame.valve_trains)
    return (f"{len(deck.flame.valve_trains)} valve-train decks ({names}) run at the camshaft "
            "speed: cams, camshaft bearings and guides")


def run(deck, inputs, result):
    from pathlib import Path

    from camtrain.engine.valve_trains import ValveTrainFriction, valve_train_parts
    from camtrain.units import from_si

    parts, speeds, notes = {}, {}, {}
    for vt in deck.flame.valve_trains:
        model, sub = inputs.included[vt.name]   # run through its own plan before this effect
        omega = model.speed.camshaft
        metrics = {k: m.value for k, m in sub.metrics.items()}
        lobes = None if model.camshaft is None else len(model.camshaft.lobes)
        parts[vt.name] = valve_train_parts(metrics, lobes, vt.trains)
        speeds[vt.name] = omega
        notes[vt.name] = tuple(sub.warnings)
        comp = vt.name.replace(" ", "_")
        for part, value in parts[vt.name].items():
            result.add_metric(f"{part}_power", value, "W",
                              f"{vt.name}: {part} friction power at "
                              f"{from_si(omega, 'rpm'):g} rpm camshaft", component=comp)
        result.add_metric("power", sum(parts[vt.name].values()), "W",
                          f"{vt.name}: friction power ({Path(vt.deck).name})", component=comp)
        if "guide_power_mean" not in metrics:
            result.warn(f"flame.valve_trains ({vt.name}): the included deck has no [guides]; "
                        "valve and follower guide friction left out")
    out = ValveTrainFriction(parts, speeds, notes)
    result.add_metric("valve_train_power_total", out.total, "W",
                      "every included valve train: friction power")
    return out
