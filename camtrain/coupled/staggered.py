"""The staggered solver: within every time step the shaft under each contact's predicted load
first, then every train with the shaft's lobe motion prescribed (Felippa, Park and Farhat 2001;
:mod:`._partition`), marched revolution by revolution to the periodic state as the monolithic
march is. Its own iteration is the passes of a step (``coupling.iterations``, until the load a
pass produces agrees with its prediction); the steps whose passes did not agree are counted
(``CoupledResult.missed``)."""
from __future__ import annotations

from .problem import CoupledResult

LABEL = "staggered march"


def solve(problem) -> CoupledResult:
    from .monolithic import marched

    return marched(problem, staggered=True)
