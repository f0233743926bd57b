"""Yang (1992) engines as physics objects for the tests (SI): the Ruston 6VEB-X Mk III
(App. A, complete) and the Ford Zeta 1.8 crank bearings (App. B; crank-train data outside the
source, flagged)."""
from __future__ import annotations

import math

import numpy as np

from camtrain.engine import (
    BearingSpec,
    CrankComponent,
    CrankTrain,
    Cylinder,
    Engine,
    PressureTable,
    unbalance_from_weight_moment,
)

RPM = 2.0 * math.pi / 60.0

# Yang App. A.5, bar, every 10 deg from firing TDC (0-710 deg).
RUSTON_PRESSURE_BAR = [float(v) for v in """
47.37 64.12 48.61 34.82 25.51 18.62 14.48 11.52 9.03 7.59 6.59 5.90 5.41 5.00 4.72 4.10 3.14 2.45
1.76 1.41 1.35 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21
1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21 1.21
1.21 1.21 1.21 1.21 1.21 1.41 1.41 1.76 2.10 2.45 3.14 4.10 6.10 8.65 12.45 18.62 26.55 34.82
""".split()]


def table(values_bar, step_deg=10.0) -> PressureTable:
    ang = np.radians(np.arange(len(values_bar)) * step_deg)
    return PressureTable(tuple(ang), tuple(np.asarray(values_bar) * 1e5))


def ruston_crank(**change) -> CrankTrain:
    """App. A.1 (clean copy: bore 260.35 mm, rod 782.32 mm)."""
    data = dict(bore=0.26035, crank_radius=0.18415, rod_length=0.78232, piston_mass=82.07,
                rod_mass=81.62)
    data.update(change)
    return CrankTrain(**data)


def ruston_engine(**change) -> Engine:
    """App. A.1-A.3: 6 bays of 444.5 mm, cylinders at 222.25 mm, firing 0/120/600/240/480/360,
    one crank component per bay, 139.19 N m at the cylinder's axial position."""
    p = table(RUSTON_PRESSURE_BAR)
    firing = (0, 120, 600, 240, 480, 360)
    comp = (0, 240, 120, 120, 240, 0)
    cyl = tuple(Cylinder(i, 0.22225, math.radians(f), p) for i, f in enumerate(firing))
    mr = unbalance_from_weight_moment(139.19)
    comps = tuple(CrankComponent(i, 0.22225, mr, math.radians(a)) for i, a in enumerate(comp))
    return Engine(ruston_crank(**change), (0.4445,) * 6, cyl, comps, 0.0)


def ruston_bearing(**change) -> BearingSpec:
    """App. A.4: d 203.2 mm, b 57.15 mm, c 0.08255 mm, ungrooved; eta 15 cP (A.1)."""
    data = dict(diameter=0.2032, length=0.05715, clearance=82.55e-6, viscosity=0.015,
                name="big-end")
    data.update(change)
    return BearingSpec(**data)


RUSTON_OMEGA = 600 * RPM
