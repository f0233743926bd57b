"""Observed orders of the level-2 film march in the angle step (Done-when: first order for
implicit Euler, second for BDF2, fitted slopes +-0.2).

The level-2 film on a smooth periodic cycle (load, entrainment and radius varying, no reversal),
half-Sommerfeld cavitation: its load is a smooth function of the film, so the march error is not
masked. With the Reynolds condition the rupture point crossing a node adds an O(N^-2) kink to the
load (tests/lubrication/test_reynolds_limits.py::test_node_convergence_with_rupture) that, at
41 nodes, is larger than the BDF2 error (docs/transient_film.md, "Resolution").
"""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.lubrication import FilmProperties, FilmResolution, transient_film

SMOOTH = FilmProperties(viscosity=0.014, width=0.02, modulus=1.8446e11,
                        cavitation="half_sommerfeld")


def film(n: int, march: str) -> np.ndarray:
    theta = np.linspace(-np.pi, np.pi, n, endpoint=False)
    rho = 0.018 * (1.0 + 0.3 * np.cos(theta))
    u_e = 0.9425 * (1.0 + 0.5 * np.sin(theta))
    load = 650.0 * (1.0 + 0.6 * np.sin(2.0 * theta))
    res = FilmResolution(nodes=41, march=march, period_tol=1e-12, cycles_max=20,
                         tolerance=1e-10)
    return transient_film(theta, 104.72, rho, u_e, load, 3.6e-4, SMOOTH, res).film


@pytest.mark.convergence
@pytest.mark.parametrize(("march", "order"), [("implicit_euler", 1.0), ("bdf2", 2.0)])
def test_level2_march_order_in_the_angle_step(march, order):
    """Successive differences of the film at 24, 48, 96, 192 angles per cycle (common angles,
    max relative): the fitted slope is the march's order."""
    ns = np.array([24, 48, 96, 192])
    films = {n: film(int(n), march) for n in ns}
    diffs = [np.max(np.abs(films[a] - films[2 * a][::2]) / films[2 * a][::2]) for a in ns[:-1]]
    slope = -np.polyfit(np.log(ns[:-1]), np.log(diffs), 1)[0]
    assert slope == pytest.approx(order, abs=0.2)
