"""Build the friction correlations' inputs from an engine deck: the engine as the correlations
see it, the oil viscosity (:mod:`camtrain.assemble.oil`), the intake pressure and peak pressure
at the run's load (:func:`camtrain.assemble.engine.load_factor`)."""
from __future__ import annotations

import math

from camtrain.assemble.engine import load_factor, pressure_table
from camtrain.assemble.oil import oil_viscosity  # noqa: F401  (the correlations' oil)
from camtrain.engine.correlations import ChenFlynnConstants, CorrelationEngine

#: atmospheric pressure [Pa] (the absolute peak of a gauge diagram for Chen-Flynn)
ATMOSPHERE = 101325.0


def correlation_engine(deck) -> CorrelationEngine:
    """The engine of the correlations: [correlations] values, else the full deck's."""
    c, e, b = deck.correlations, deck.engine, deck.bearings
    vt = c.valve_train
    cylinders = c.cylinders if c.cylinders is not None else len(deck.cylinders)
    return CorrelationEngine(
        bore=e.bore, stroke=2.0 * e.crank_radius, cylinders=cylinders,
        main_count=c.main_bearings if c.main_bearings is not None else len(e.bay_lengths) + 1,
        main_diameter=c.main_diameter if c.main_diameter is not None else b.main.diameter,
        main_length=c.main_length if c.main_length is not None else b.main.length,
        rod_diameter=c.rod_diameter if c.rod_diameter is not None else b.big_end.diameter,
        rod_length=c.rod_length if c.rod_length is not None else b.big_end.length,
        layout=vt.layout, follower=vt.follower, valves=vt.valves_per_cylinder * cylinders,
        camshaft_bearings=vt.camshaft_bearings, valve_lift=vt.valve_lift,
        compression_ratio=c.compression_ratio, strokes=e.strokes)


def peak_pressure(deck) -> float:
    """Absolute peak cylinder pressure [Pa] for Chen-Flynn: the deck's value, else the peak
    of the run's (scaled) diagram plus one atmosphere."""
    cf = deck.correlations.chen_flynn
    if cf.peak_pressure is not None:
        return cf.peak_pressure
    return float(max(pressure_table(deck).gauge())) + ATMOSPHERE


def chen_flynn_constants(deck) -> ChenFlynnConstants:
    cf = deck.correlations.chen_flynn
    return ChenFlynnConstants(cf.constant, cf.peak_pressure_coefficient,
                              cf.piston_speed_coefficient, cf.piston_speed_squared_coefficient)


def intake_ratio(deck) -> float:
    """p_i/p_a of the run: the deck's, times the load factor (an SI engine's IMEP follows its
    intake density at a given speed, so the throttled intake scales with the diagram)."""
    return deck.correlations.intake_pressure_ratio * (load_factor(deck) if deck.pressure
                                                      else 1.0)


def displacement(deck) -> float:
    e = deck.engine
    n = (deck.correlations.cylinders if deck.correlations is not None
         and deck.correlations.cylinders is not None else len(deck.cylinders))
    return n * math.pi / 4.0 * e.bore**2 * 2.0 * e.crank_radius
