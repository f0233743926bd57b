"""The compiled orbit march: same orbits as the pure-Python march it replaced, pluggable
mobility (tabulated maps), numba imported only for decks that march an orbit.

tests/bearings/data/orbit_reference.json holds orbits computed by the pure-Python march of
camtrain 0.1 (interpreted Dormand-Prince, same algorithm) before it was compiled; it is a
regression file and is not regenerated from the compiled kernel. The compiled march with the
same steps (``steps="grid"``: every step ends on a grid angle, the load linear between them)
must agree to 1e-12 in eps (the march's own step tolerance is 1e-7:
any larger difference is a change of algorithm, not round-off).
"""
from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from camtrain.bearings import JournalBearing, bearing_orbit
from camtrain.bearings.mobility_map import MobilityMap
from camtrain.errors import ConvergenceError

ROOT = Path(__file__).resolve().parents[2]
REFERENCE = json.loads((Path(__file__).parent / "data" / "orbit_reference.json").read_text())
TH = np.arange(36) * (2 * math.pi / 36)


def _march(name: str, case: dict):
    brg = JournalBearing(*case["bearing"])
    if name == "exact_crank_4pi":  # four-stroke period, journal speed varying, bush turning
        th = np.arange(72) * (4 * math.pi / 72)
        fx = 4000 * np.cos(th)
        fy = -6000 - 8000 * np.exp(-(((th - 2 * math.pi) / 0.5) ** 2))
        return bearing_orbit(brg, fx, fy, th, 300.0 + 20 * np.sin(th), 10.0, angle_rate=300.0,
                             period=4 * math.pi, terms="all", steps="grid")
    fx = 0.3 * case["load"] * np.sin(2 * TH)
    fy = -case["load"] * (1.2 + np.cos(TH))
    return bearing_orbit(brg, fx, fy, TH, 157.0, steps="grid", **case["options"])


@pytest.mark.parametrize("name", sorted(REFERENCE))
def test_compiled_march_reproduces_the_python_march(name):
    case = REFERENCE[name]
    orbit = _march(name, case)
    assert orbit.cycles == case["cycles"]
    np.testing.assert_allclose(orbit.eps_x, case["eps_x"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(orbit.eps_y, case["eps_y"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(orbit.power, case["power"], rtol=1e-11)


def _camshaft_case():
    brg = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
    return brg, 0.3 * 2000.0 * np.sin(2 * TH), -2000.0 * (1.2 + np.cos(TH))


def test_tabulated_booker_map_converges_to_the_closed_form():
    """A tabulated map of Booker's closed form gives Booker's orbit, the difference shrinking
    with the table spacing like bilinear interpolation (second order: /4 per halving)."""
    brg, fx, fy = _camshaft_case()
    exact = bearing_orbit(brg, fx, fy, TH, 157.0, mobility="booker")
    ratio = brg.length / brg.diameter
    errors = []
    for n_eps, n_ang in ((100, 36), (200, 72), (400, 144)):
        table = MobilityMap.booker(ratio, np.linspace(0.0, 0.995, n_eps), n_ang)
        o = bearing_orbit(brg, fx, fy, TH, 157.0, mobility=table)
        assert o.method.startswith("mobility-booker-table")
        errors.append(np.max(np.hypot(o.eps_x - exact.eps_x, o.eps_y - exact.eps_y)))
    assert errors[-1] < 1e-3
    order = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(order > 1.5), (errors, order)


def test_leaving_the_map_is_a_convergence_error():
    brg, fx, fy = _camshaft_case()
    table = MobilityMap.booker(brg.length / brg.diameter, np.linspace(0.0, 0.5, 20), 36)
    with pytest.raises(ConvergenceError, match="left the mobility map"):
        bearing_orbit(brg, fx, fy, TH, 157.0, mobility=table)


def test_bad_map_is_a_field_error():
    from camtrain.errors import InputError

    with pytest.raises(InputError, match="mobility.eps"):
        MobilityMap(np.array([0.1, 0.5]), np.zeros((2, 8)), np.zeros((2, 8)))


@pytest.mark.parametrize(("deck", "marches"), [("harrison_flat.toml", False),
                                               ("zeta_intake_camshaft.toml", True)])
def test_numba_is_imported_only_for_decks_that_march(deck, marches):
    code = ("import sys; from camtrain import api; api.run(api.load(sys.argv[1]));"
            "print('numba' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code, str(ROOT / "decks" / deck)],
                         capture_output=True, text=True, check=True, cwd=ROOT).stdout
    assert out.strip() == str(marches)
