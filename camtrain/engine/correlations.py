"""Whole-engine friction by correlation: Patton-Nitschke-Heywood (1989) and Sandoval-Heywood
(2003) term by term, and Chen-Flynn (1965) with the user's constants, on an engine described by
its geometry alone (:mod:`camtrain.formulas.engine_friction` holds one function per term).

Everything is vectorised over the speed (and any other argument given as an array), so a map
over speed, load and oil temperature is one call per model.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from camtrain.formulas import engine_friction as ef

__all__ = ["CorrelationEngine", "CorrelationModel", "MODELS", "OperatingPoint",
           "ChenFlynnConstants", "correlation_terms", "chen_flynn_fmep", "FrictionCorrelations",
           "fmep_to_power", "GROUPS"]


@dataclass(frozen=True)
class CorrelationModel:
    """A named correlation: its boundary speed N_0 [rev/min] and whether the hydrodynamic terms
    scale with the oil viscosity (r = sqrt(nu/nu_0)) or not (r = 1)."""

    name: str
    label: str
    n0: float
    viscosity_scaling: bool


#: The two published models (PNH 1989: r = 1, N_0 = 1000; Sandoval-Heywood: r, N_0 = 500).
MODELS = {
    "pnh1989": CorrelationModel("pnh1989", "Patton-Nitschke-Heywood 1989",
                                ef.BOUNDARY_SPEEDS["pnh1989"], False),
    "sandoval_heywood2003": CorrelationModel("sandoval_heywood2003", "Sandoval-Heywood 2003",
                                             ef.BOUNDARY_SPEEDS["sandoval_heywood2003"], True),
}

#: term -> group (the groups PNH report: crankshaft, reciprocating, valve train, auxiliaries)
GROUPS = {
    "crankshaft_seals": "crankshaft", "main_bearings": "crankshaft",
    "turbulent_dissipation": "crankshaft",
    "piston_skirt": "reciprocating", "piston_rings": "reciprocating",
    "ring_gas_loading": "reciprocating", "rod_bearings": "reciprocating",
    "camshaft_bearings": "valve_train", "valve_train_constant": "valve_train",
    "follower": "valve_train", "oscillating_hydrodynamic": "valve_train",
    "oscillating_mixed": "valve_train",
    "auxiliaries": "auxiliaries",
}


@dataclass(frozen=True)
class CorrelationEngine:
    """What the correlations need of an engine (SI): bore, stroke [m], cylinders; main bearings
    (count, diameter, length [m]); rod bearing (diameter, length [m]); valve train (layout,
    follower "flat"/"roller", valves in the engine, camshaft bearings in the engine, maximum
    valve lift [m]); compression ratio; strokes per cycle."""

    bore: float
    stroke: float
    cylinders: int
    main_count: int
    main_diameter: float
    main_length: float
    rod_diameter: float
    rod_length: float
    layout: str
    follower: str
    valves: int
    camshaft_bearings: int
    valve_lift: float
    compression_ratio: float
    strokes: int = 4

    @property
    def displacement(self) -> float:
        """Swept volume of the engine [m^3]."""
        return self.cylinders * math.pi / 4.0 * self.bore**2 * self.stroke


@dataclass(frozen=True)
class OperatingPoint:
    """Speed [rad/s], intake over atmospheric pressure [-], oil kinematic viscosity [m^2/s]
    (arrays broadcast together)."""

    omega: object
    intake_ratio: object = 1.0
    viscosity: object = ef.NU_REFERENCE


@dataclass(frozen=True)
class ChenFlynnConstants:
    """fmep = a + b p_max + c S_p + d S_p^2, SI: a [Pa], b [-], c [Pa s/m], d [Pa s^2/m^2]."""

    a: float
    b: float
    c: float
    d: float = 0.0


def correlation_terms(model: CorrelationModel, engine: CorrelationEngine,
                      op: OperatingPoint, n0: float | None = None) -> dict:
    """Every term's fmep [Pa] of ``model`` (``n0`` [rev/min] overrides its boundary speed):
    {term: array or float}, in the order of :data:`GROUPS`."""
    e, w = engine, op.omega
    r = ef.viscosity_ratio(op.viscosity) if model.viscosity_scaling else 1.0
    n0 = model.n0 if n0 is None else n0
    if e.follower == "flat":
        follower = ef.flat_follower(w, e.stroke, e.valves, e.cylinders, e.layout, n0)
    else:
        follower = ef.roller_follower(w, e.stroke, e.valves, e.cylinders, e.layout)
    return {
        "crankshaft_seals": ef.crankshaft_seals(e.bore, e.stroke, e.main_diameter, e.cylinders)
        + 0.0 * np.asarray(w, dtype=float),
        "main_bearings": ef.main_bearings(w, e.bore, e.stroke, e.main_diameter, e.main_length,
                                          e.main_count, e.cylinders, r),
        "turbulent_dissipation": ef.turbulent_dissipation(w, e.main_diameter, e.main_count,
                                                          e.cylinders),
        "piston_skirt": ef.piston_skirt(w, e.bore, e.stroke, r),
        "piston_rings": ef.piston_rings(w, e.bore, n0),
        "ring_gas_loading": ef.ring_gas_loading(w, e.stroke, op.intake_ratio,
                                                e.compression_ratio, r),
        "rod_bearings": ef.rod_bearings(w, e.bore, e.stroke, e.rod_diameter, e.rod_length, r),
        "camshaft_bearings": ef.camshaft_bearings(w, e.bore, e.stroke, e.camshaft_bearings,
                                                  e.cylinders, r),
        "valve_train_constant": ef.valve_train_constant() + 0.0 * np.asarray(w, dtype=float),
        "follower": follower,
        "oscillating_hydrodynamic": ef.oscillating_hydrodynamic(
            w, e.bore, e.stroke, e.valve_lift, e.valves, e.cylinders, e.layout, r),
        "oscillating_mixed": ef.oscillating_mixed(w, e.stroke, e.valve_lift, e.valves,
                                                  e.cylinders, e.layout, n0),
        "auxiliaries": ef.auxiliaries(w),
    }


def chen_flynn_fmep(constants: ChenFlynnConstants, engine: CorrelationEngine, omega,
                    peak_pressure):
    """Chen-Flynn fmep [Pa] at speed ``omega`` [rad/s] and peak cylinder pressure [Pa]."""
    c = constants
    return ef.chen_flynn(peak_pressure, ef.mean_piston_speed(engine.stroke, omega),
                         c.a, c.b, c.c, c.d)


def fmep_to_power(fmep, displacement: float, omega, strokes: int = 4):
    """Friction power [W] of an fmep [Pa]: P = fmep V_d n / n_R (n rev/s, n_R = 2 for a
    4-stroke, 1 for a 2-stroke)."""
    revs = 2 if strokes == 4 else 1
    return np.asarray(fmep) * displacement * np.asarray(omega) / (2.0 * math.pi) / revs


@dataclass(frozen=True)
class FrictionCorrelations:
    """The correlations of one run (SI). ``terms`` model name -> {term: fmep [Pa]};
    ``totals`` model name -> fmep [Pa] (Chen-Flynn: no terms, its total only); ``speed``
    [rad/s]; ``displacement`` [m^3]; ``strokes``; ``viscosity`` the oil's kinematic viscosity
    [m^2/s]; ``notes`` what each model took (text)."""

    speed: float
    displacement: float
    strokes: int
    terms: dict
    totals: dict
    viscosity: float
    notes: dict = field(default_factory=dict)

    def power(self, model: str, term: str | None = None) -> float:
        """Friction power [W] of a model's total (or one term)."""
        value = self.totals[model] if term is None else self.terms[model][term]
        return float(fmep_to_power(value, self.displacement, self.speed, self.strokes))

    def group(self, model: str, name: str) -> float:
        """fmep [Pa] of a group of terms (crankshaft, reciprocating, valve_train,
        auxiliaries)."""
        return float(sum(v for k, v in self.terms[model].items() if GROUPS[k] == name))
