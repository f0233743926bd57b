"""Whole engines, part 1: crank-train loads and crankshaft bearings (Yang 1992 Part I).

Pure physics on SI arrays (no deck, report or CLI imports):

* :mod:`.crank` - slider-crank kinematics and one cylinder's forces (Yang eqs 1.1-1.5, 2.1;
  Williams 2013 App. A5 as the exact cross-check);
* :mod:`.pressure` - cylinder-pressure tables, periodic interpolation;
* :mod:`.model` - the crank train as data (cylinders, bays, crank components, flywheel);
* :mod:`.loads` - big-end load diagrams in rod axes, main-bearing loads by the statically
  determinate bay split (Yang §1.2.2);
* :mod:`.crank_bearings` - orbits (existing mobility kernel), steady-load and Petroff columns,
  power per bearing and in total, grooving treatments and Yang's mobility factor.
"""
from .crank_bearings import (
                             GROOVINGS,
                             METHODS,
                             MODELS,
                             YANG1992_MOBILITY_SCALE,
                             BearingResult,
                             BearingSpec,
                             EngineBearings,
                             SolverOptions,
                             solve_crank_bearings,
                             solve_engine_bearings,
)
from .loads import (
                             CrankLoads,
                             CylinderLoads,
                             MainLoads,
                             crank_grid,
                             crank_train_loads,
                             cylinder_loads,
                             main_loads,
)
from .model import (
                             STANDARD_GRAVITY,
                             CrankComponent,
                             CrankTrain,
                             Cylinder,
                             Engine,
                             unbalance_from_weight_moment,
)
from .pressure import INTERPOLATIONS, PressureTable

__all__ = ["CrankTrain", "Cylinder", "CrankComponent", "Engine", "PressureTable",
           "CylinderLoads", "MainLoads", "crank_grid", "cylinder_loads", "main_loads",
           "BearingSpec", "SolverOptions", "BearingResult", "EngineBearings",
           "solve_engine_bearings", "solve_crank_bearings", "CrankLoads", "crank_train_loads",
           "GROOVINGS", "METHODS", "MODELS", "INTERPOLATIONS",
           "YANG1992_MOBILITY_SCALE", "STANDARD_GRAVITY", "unbalance_from_weight_moment"]
