"""The valve-train decks an engine deck includes by path ([[flame.valve_trains]]), turned into
the decks that run: each at the engine's camshaft speed, its viscosities moved with the
engine's oil temperature when the deck has [oil] (Yang 1992 Part IV, Fig. 4.7). The scene
composes them as plans of their own; the runner runs them before the effect that reads them."""
from __future__ import annotations

import dataclasses


def included_valve_trains(deck) -> list[tuple[str, object]]:
    """(name, valve-train deck model as it runs) of every included valve train, in deck order."""
    from camtrain.assemble.oil import flame_oil_factor
    from camtrain.deck.load import load_deck

    factor = flame_oil_factor(deck)
    out = []
    for vt in deck.flame.valve_trains:
        model = load_deck(vt.deck).model
        omega = vt.speed_ratio * deck.speed.engine
        model = dataclasses.replace(model, speed=dataclasses.replace(
            model.speed, camshaft=omega, engine=None))
        if factor != 1.0:   # [oil] moves FLAME's viscosities with the oil temperature
            model = _with_viscosity_factor(model, factor)
        out.append((vt.name, model))
    return out


def _with_viscosity_factor(model, factor: float):
    """The valve-train deck with its lubricant viscosity (and the camshaft bearings' own, when
    given) times ``factor``."""
    lub = model.lubricant
    model = dataclasses.replace(model, lubricant=dataclasses.replace(
        lub, viscosity=lub.viscosity * factor))
    shaft = getattr(model, "camshaft", None)
    if shaft is not None and shaft.viscosity is not None:
        model = dataclasses.replace(model, camshaft=dataclasses.replace(
            shaft, viscosity=shaft.viscosity * factor))
    return model
