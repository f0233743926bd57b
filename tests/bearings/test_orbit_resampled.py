"""The orbit marched on its own load grid (``march_points``, deck ``camshaft.orbit_points``):
it converges to the orbit marched on the diagram's grid, and leaves it alone when not coarser."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.bearings import JournalBearing, bearing_orbit
from camtrain.deck.load import load_deck_text
from camtrain.errors import InputError

BRG = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
N = 1440
TH = np.arange(N) * (2 * math.pi / N)
# a smooth cam-bearing-like diagram: a steady part and a lobe pulse once per revolution
FX = 300.0 * np.sin(TH)
FY = -2000.0 * (1.0 + 0.8 * np.exp(-8.0 * (1.0 - np.cos(TH - 1.0))))


def _orbit(points):
    return bearing_orbit(BRG, FX, FY, TH, 157.0, march_points=points)


@pytest.mark.convergence
def test_resampled_orbit_converges_to_the_full_grid_orbit():
    """Eccentricity on the full grid from orbits marched on 90, 180, 360, 720 angles: the error
    against the orbit marched on all 1440 angles falls by about 4 per halving (linear
    resampling and interpolation, second order)."""
    full = _orbit(None)
    errors = [np.max(np.hypot(o.eps_x - full.eps_x, o.eps_y - full.eps_y))
              for o in map(_orbit, (90, 180, 360, 720))]
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert errors[-1] < 1e-4
    assert np.all(orders > 1.5), (errors, orders)


def test_resampled_orbit_is_reported_on_the_diagram_grid():
    """Columns have the diagram's length, the loads are the diagram's own, and the power and
    film follow from the interpolated eccentricity."""
    o = _orbit(360)
    assert o.eccentricity.size == N
    np.testing.assert_array_equal(o.load_x, FX)
    np.testing.assert_allclose(o.h_min, BRG.clearance * (1.0 - o.eccentricity))
    assert abs(o.mean_power / _orbit(None).mean_power - 1.0) < 1e-3


@pytest.mark.parametrize("points", [0, N, 2 * N])
def test_no_resampling_unless_coarser(points):
    """0, the diagram's own size and more leave the march on the diagram's grid."""
    full = _orbit(None)
    o = _orbit(points)
    np.testing.assert_array_equal(o.eps_x, full.eps_x)
    assert o.cycles == full.cycles


def test_deck_rejects_too_few_orbit_angles():
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "decks" / "zeta_intake_camshaft.toml").read_text()
    bad = text.replace("[camshaft]\n", "[camshaft]\norbit_points = 12\n", 1)
    assert bad != text
    with pytest.raises(InputError, match="camshaft.orbit_points"):
        load_deck_text(bad)
