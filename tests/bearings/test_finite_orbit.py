"""Orbits with the finite-length mobility map (derived tests: consistency with the steady finite
solve, the short-bearing limit, and the direction of the finite-length correction)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain import api
from camtrain.bearings import JournalBearing, bearing_orbit
from camtrain.bearings.finite import finite_steady
from camtrain.bearings.finite_map import _correction_table, bearing_mobility_map, correction_table
from tests.conftest import DECKS

RPM = 2.0 * math.pi / 60.0
N = 36
TH = np.arange(N) * (2.0 * math.pi / N)


@pytest.fixture(autouse=True, scope="module")
def _private_cache(tmp_path_factory):
    mp = pytest.MonkeyPatch()
    mp.setenv("CAMTRAIN_CACHE", str(tmp_path_factory.mktemp("maps")))
    yield
    mp.undo()


@pytest.mark.parametrize("load", [100.0, 500.0, 3000.0])
def test_constant_load_orbit_settles_on_the_steady_finite_solution(load):
    """The map is tabulated on a coarser mesh (72 x 6, refined with eps) and interpolated; its
    orbit under a constant load must settle on the steady Reynolds solution of the default mesh
    (120 x 12) within 0.3 % in eps and 0.2 deg in attitude (eps 0.50, 0.81, 0.95)."""
    brg = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
    w = 1500 * RPM
    o = bearing_orbit(brg, np.zeros(N), -load * np.ones(N), TH, w,
                      mobility=bearing_mobility_map(brg), max_cycles=60)
    s = finite_steady(brg, load, w)
    assert o.converged
    assert o.eccentricity == pytest.approx(np.full(N, s.eccentricity), rel=3e-3)
    assert np.degrees(o.attitude) == pytest.approx(np.full(N, math.degrees(s.attitude)),
                                                   abs=0.2)


def _dynamic_load(scale):
    """A rotating plus pulsating load (an engine-like diagram, one revolution)."""
    return (scale * (0.6 * np.cos(TH) + 0.2 * np.cos(2 * TH)),
            scale * (-1.0 - 0.5 * np.sin(TH) + 0.3 * np.sin(3 * TH)))


def test_short_bearing_limit_of_the_dynamic_orbit():
    """b/d = 0.1 (D 50 mm, b 5 mm) under a dynamic load: the finite orbit approaches the exact
    pi-film short-bearing orbit: largest eccentricity within 1.5 %, thinnest film within 5 %
    (the finite film is the thinner one: Ocvirk overstates the load capacity)."""
    brg = JournalBearing(50e-3, 5e-3, 25e-6, 0.01)
    lx, ly = _dynamic_load(400.0)
    w = 3000 * RPM
    short = bearing_orbit(brg, lx, ly, TH, w)
    fin = bearing_orbit(brg, lx, ly, TH, w, mobility=bearing_mobility_map(brg))
    assert fin.max_eccentricity == pytest.approx(short.max_eccentricity, rel=0.015)
    assert fin.min_film == pytest.approx(short.min_film, rel=0.05)
    assert fin.min_film <= short.min_film


def test_ocvirk_check_deck_finite_orbit():
    """decks/bearing_ocvirk_check.toml (b/d 0.72): the finite orbit is periodic and its film is
    thinner than the short bearing's 7.09 um (the steady finite solve gives 4.78 um)."""
    deck = api.load(DECKS / "bearing_ocvirk_check.toml").model
    g, s, ld = deck.bearing, deck.speed, deck.load
    brg = JournalBearing(g.diameter, g.length, g.clearance, g.viscosity, g.groove_width)
    args = (np.asarray(ld.load_x), np.asarray(ld.load_y), np.asarray(ld.angles), s.journal)
    short = bearing_orbit(brg, *args, period=ld.period)
    fin = bearing_orbit(brg, *args, period=ld.period, mobility=bearing_mobility_map(brg))
    assert fin.converged and fin.periodicity_error <= 1e-5
    assert short.min_film == pytest.approx(7.09e-6, abs=5e-9)
    assert fin.min_film < short.min_film
    assert fin.min_film == pytest.approx(4.78e-6, rel=0.005)


def test_zeta_camshaft_bearing_finite_orbit():
    """Zeta intake camshaft bearing 3 (Yang App. C: d 25.97 mm, two 7.5 mm lands, c 22.5 um) under
    its load diagram from the camshaft run: the finite orbit is periodic and its thinnest film is
    below the short bearing's."""
    res = api.run(DECKS / "zeta_intake_camshaft.toml")
    deck = api.load(DECKS / "zeta_intake_camshaft.toml").model
    b = deck.camshaft.bearings[2]
    brg = JournalBearing(b.diameter, b.length, b.clearance, deck.camshaft.viscosity,
                         b.groove_width)
    theta, lx, ly = res["cam_angle"], res["bearing_3_load_x"], res["bearing_3_load_y"]
    w = 1500 * RPM
    short = bearing_orbit(brg, lx, ly, theta, w)
    fin = bearing_orbit(brg, lx, ly, theta, w, mobility=bearing_mobility_map(brg))
    assert fin.converged and fin.periodicity_error <= 1e-5
    assert fin.min_film < short.min_film
    assert fin.max_eccentricity > short.max_eccentricity


def test_map_tables_are_cached_in_process_and_on_disk(tmp_path, monkeypatch):
    """A second request is served from memory; a fresh process reads the disk copy (same
    values, no Reynolds solution)."""
    monkeypatch.setenv("CAMTRAIN_CACHE", str(tmp_path))
    a = correction_table(0.05)
    assert correction_table(0.05) is a
    files = list((tmp_path / "bearing_maps").glob("*.npz"))
    assert len(files) == 1
    b = _correction_table.__wrapped__(0.05, "reynolds", 72, 6, True)
    assert np.array_equal(a[2], b[2])


def test_finite_steady_locus_matches_the_steady_solve():
    """The quasi-static finite locus interpolates a cached F(eps) curve: within 0.3 % in eps and
    0.3 deg of the full eccentricity search at each angle (loads 100-3000 N)."""
    from camtrain.bearings.models import finite_steady_orbit

    brg = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
    w = 1500 * RPM
    loads = np.array([100.0, 500.0, 1500.0, 3000.0])
    th = np.arange(4) * (math.pi / 2)
    o = finite_steady_orbit(brg, np.zeros(4), -loads, th, w)
    for i, load in enumerate(loads):
        s = finite_steady(brg, load, w)
        assert o.eccentricity[i] == pytest.approx(s.eccentricity, rel=3e-3)
        assert math.degrees(o.attitude[i]) == pytest.approx(math.degrees(s.attitude), abs=0.3)


def test_model_choice_and_reasons():
    from camtrain.bearings.models import choose_model

    long_ = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
    tiny = JournalBearing(50e-3, 2.0e-3, 25e-6, 0.01)
    assert choose_model(long_)[0] == "finite" and "0.72" in choose_model(long_)[1]
    assert choose_model(tiny)[0] == "short"
    assert choose_model(long_, "short")[0] == "short"
    assert choose_model(tiny, "finite")[0] == "finite"
    with pytest.raises(Exception, match="model"):
        choose_model(long_, "long")
