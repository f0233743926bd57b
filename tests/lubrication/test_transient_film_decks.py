"""Transient films as film laws of the contact model, run from decks (docs/transient_film.md).

The Göçmen deck (decks/gocmen_table31.toml, Table 3.1 with a substitute lift, flagged) is run at
a coarse resolution (360 angles, 101 nodes) except where a test names the shipped resolution:
the properties tested hold at any resolution, and the golden file holds the shipped run.
Published and derived values: docs/references/gocmen2013.md §2.2 and §4 (G1, G3, G4, G5, G6,
D1, D2, D4).
"""
from __future__ import annotations

import math
import re
from dataclasses import replace

import numpy as np
import pytest

from camtrain import api
from camtrain import mechanisms as M
from camtrain.assemble.lift_law import build_lift_law
from camtrain.contact.film import entrainment
from camtrain.contact.model import CamContact
from camtrain.deck.load import load_deck_text
from camtrain.effects.loads import solve_loads
from camtrain.errors import InputError
from camtrain.lift import angle_grid
from camtrain.lubrication import teodorescu_steady_film
from tests.conftest import DECKS

GOCMEN = (DECKS / "gocmen_table31.toml").read_text()
COARSE = "\n[solver]\nangle_points = 360\nfilm_nodes = 101\n"
FAST = "\n[solver]\nangle_points = 180\nfilm_nodes = 61\n"


def deck_text(model="averaged_reynolds", camshaft=None, viscosity=None, extra=COARSE):
    text = GOCMEN.replace('film_model = "averaged_reynolds"', f'film_model = "{model}"')
    if camshaft is not None:
        text = re.sub(r"camshaft = 1000\.0", f"camshaft = {camshaft}", text)
    if viscosity is not None:
        text = re.sub(r"viscosity = 0\.014 ", f"viscosity = {viscosity} ", text)
    return text + extra


def run(**kw):
    return api.run(load_deck_text(deck_text(**kw)).model)


def pair(**kw):
    """(contact, kinematics, load) of the deck's pair (the film laws' inputs)."""
    deck = load_deck_text(deck_text(**kw)).model
    curve = build_lift_law(deck.lift).evaluate(angle_grid(deck.solver.angle_points))
    kin = M.flat_faced(curve, base_radius=deck.cam.base_radius, omega=deck.speed.omega)
    return CamContact.from_deck(deck), kin, solve_loads(deck, kin).load


@pytest.fixture(scope="module")
def level2():
    return run()


@pytest.fixture(scope="module")
def level2_film():
    """(contact, kinematics, load, film) of the coarse Göçmen run, from the film law itself."""
    contact, kin, load = pair()
    return contact, kin, load, contact.film(kin, load)


def base_circle(r):
    return r["valve_lift"] == 0.0


@pytest.mark.literature
def test_gocmen_base_circle_entrainment_and_film(level2):
    """Göçmen (2013) §4 D1/D2 with G1: base-circle entrainment U = omega R_b / 2 = 0.9425 m/s
    and the eq. 2.1 film 0.0938 um ("around 0.1 um"; the literal |U/2| and E' = 184.46 GPa
    conventions, flagged in the deck), constant over the base circle (1e-6); tolerances half a
    unit in the last printed digit."""
    b = base_circle(level2)
    assert b.sum() > 100
    np.testing.assert_allclose(level2["entrainment"][b], 0.9425, atol=5e-5)
    np.testing.assert_allclose(level2["film_min"][b] * 1e6, 0.0938, atol=5e-5)
    h = level2["film_min"][b]
    assert np.ptp(h) <= 1e-6 * h.max()
    # there the steady film governs: the reported film is the steady one (Göçmen G6)
    np.testing.assert_array_equal(level2["film_min"][b], level2["film_steady"][b])


@pytest.mark.derived
def test_doubled_viscosity_multiplies_the_ehl_film_by_1_6245(level2):
    """Göçmen §4 D4: eta 0.014 -> 0.028 Pa s gives h x 2^0.7 = 1.6245 wherever the steady EHL
    film governs (1e-4, the printed digits)."""
    thick = run(viscosity=0.028)
    ehl = ((level2["film_min"] == level2["film_steady"]) & (thick["film_min"] ==
                                                           thick["film_steady"])
           & np.isfinite(level2["film_min"]) & (level2["film_steady"] > 0.0))
    assert ehl.sum() > 200
    np.testing.assert_allclose(thick["film_min"][ehl] / level2["film_min"][ehl], 1.6245,
                               atol=1e-4)


@pytest.mark.literature
def test_transient_film_at_or_above_the_steady_film_and_above_it_on_the_flanks(level2):
    """Göçmen G6 (Fig. 3.7): the model film is the Dowson-Higginson film on the base circle and
    the nose and above it on the flanks, where the film forms hydrodynamically."""
    h, hs = level2["film_min"], level2["film_steady"]
    loaded = np.isfinite(hs)
    assert loaded.all()
    assert np.all(h[loaded] >= hs[loaded])
    above = h > hs * (1.0 + 1e-6)
    flank = (level2["valve_lift"] > 0.0) & (np.abs(level2["entrainment"]) > 2.0)
    assert np.any(above & flank)
    # the hydrodynamic flank film is what the averaged Reynolds march gives there
    np.testing.assert_array_equal(h[above], level2["film_transient"][above])


@pytest.mark.literature
def test_zero_entrainment_angles_keep_a_positive_film(level2):
    """Göçmen G3 (and Teodorescu R3): where the entrainment passes through zero the steady film
    vanishes while the transient film stays positive (squeeze)."""
    keys = [k for k in level2.metrics if k.startswith("film_at_zero_entrainment_")]
    assert len(keys) == 2
    for k in keys:
        assert level2.metrics[k].value > 0.0
    assert "squeeze film carries the load" in " ".join(level2.warnings)
    assert all("squeeze film carries" in e.description
               for e in level2.events_of("zero_entrainment"))


@pytest.mark.parametrize("model", ["squeeze", "averaged_reynolds"])
def test_exact_zero_entrainment_steady_zero_transient_positive(model):
    """With the entrainment exactly zero at a node, the steady film there is exactly 0 and the
    transient film of either level is positive."""
    contact, kin, load = pair(model=model, extra=FAST)
    i = int(np.argmin(np.abs(kin.entrainment[:90])))
    vf = np.array(kin.v_follower)
    vf[i] = -kin.v_cam[i]
    kin0 = replace(kin, v_follower=vf)
    assert kin0.entrainment[i] == 0.0
    film = contact.film(kin0, load)
    assert film.steady[i] == 0.0
    assert film.min[i] > 0.0
    assert np.all(film.min[load > 0.0] > 0.0)


def test_films_rise_with_speed_and_viscosity():
    """Göçmen G4/G5: the film rises with the cam speed and with the viscosity at every angle
    (500 -> 1000 -> 2000 rpm; SAE 20 0.014, 0.021, 0.028 Pa s)."""
    speeds = [run(camshaft=s, extra=FAST)["film_min"] for s in (500.0, 1000.0, 2000.0)]
    oils = [run(viscosity=v, extra=FAST)["film_min"] for v in (0.014, 0.021, 0.028)]
    for series in (speeds, oils):
        for lo, hi in zip(series, series[1:], strict=False):
            assert np.all(hi > lo)


def test_level1_films_rise_with_speed_and_viscosity():
    speeds = [run(model="squeeze", camshaft=s, extra=FAST)["film_min"]
              for s in (500.0, 1000.0, 2000.0)]
    oils = [run(model="squeeze", viscosity=v, extra=FAST)["film_min"] for v in (0.014, 0.028)]
    for series in (speeds, oils):
        for lo, hi in zip(series, series[1:], strict=False):
            assert np.all(hi > lo)


@pytest.mark.derived
def test_level1_on_constant_conditions_is_the_steady_formula():
    """Level 1 with zero squeeze: at constant load, speed and radius the marched film is
    Teodorescu's eq. 5 without squeeze (1e-10)."""
    contact, kin, load = pair(model="squeeze")
    n = kin.theta.size
    const = {f: np.full(n, float(getattr(kin, f)[0])) for f in
             ("radius_x", "v_cam", "v_follower")}
    kin0 = replace(kin, **const)
    W = np.full(n, 650.0)
    film = contact.film(kin0, W)
    lub = contact.lubricant
    F = teodorescu_steady_film(W / contact.width, kin0.radius_x,
                               entrainment(contact.tribology, kin0),
                               lub.viscosity, lub.pressure_viscosity, contact.reduced_modulus)
    np.testing.assert_allclose(film.min, F, rtol=1e-10)


@pytest.mark.derived
def test_level2_load_balance_at_every_loaded_angle(level2, level2_film):
    """Done-when S6 on the deck: the march meets |W - W_P - W_A| / W <= tolerance (1e-6) at every
    loaded angle; recomputed from the film's own loads."""
    assert level2.metrics["film_balance_error_max"].value <= 1e-6
    contact, kin, load, film = level2_film
    tf = film.solution.film
    total = tf.fluid_load + tf.asperity_load
    on = load > 0.0
    np.testing.assert_allclose(total[on], load[on], rtol=1e-6)


def test_friction_is_the_film_solution(level2, level2_film):
    """averaged_reynolds: the friction force is the viscous plus asperity shear of the same
    solution (not the deck's friction law); the plan says which film runs and why."""
    contact, kin, load, film = level2_film
    assert contact.friction_law == "averaged_reynolds"
    tf = film.solution.film
    np.testing.assert_allclose(level2["friction_force"], tf.viscous_friction
                               + tf.asperity_friction, rtol=1e-12)
    reason = {s.effect: s.reason for s in api.plan(load_deck_text(deck_text()).model).steps}
    assert "averaged Reynolds" in reason["film"] and "101 nodes" in reason["film"]


def test_outputs_regimes_and_plots(level2, tmp_path):
    codes = level2["film_regime"]
    assert set(np.unique(codes)) <= {0.0, 1.0, 2.0, 3.0}
    assert {0.0, 1.0} <= set(np.unique(codes))       # hydrodynamic flanks, mixed elsewhere
    assert level2.events_of("regime")
    for name in ("film_steady", "film_transient", "asperity_load_share", "film_pressure_max",
                 "asperity_pressure_max", "squeeze_velocity"):
        assert np.isfinite(level2[name]).all(), name
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from camtrain.report.panels import PANELS
    from camtrain.report.sheets import SHEETS, _ctx
    assert SHEETS["transient_film"][1] == ["transient_film", "film_pressures"]
    fig, ax = plt.subplots()
    try:
        for name in SHEETS["transient_film"][1]:
            ax.clear()
            assert PANELS[name][1](ax, level2, _ctx(level2))
    finally:
        plt.close(fig)


def test_point_contact_refuses_the_line_contact_model(tmp_path):
    """A domed follower is a point contact: averaged_reynolds names the deck field (exit 2)."""
    text = (DECKS / "zeta_intake.toml").read_text() + (
        '\n[tribology]\nfilm_model = "averaged_reynolds"\n')
    with pytest.raises(InputError, match="tribology.film_model"):
        api.run(load_deck_text(text).model)


def test_steady_decks_keep_the_old_warning():
    r = api.run(load_deck_text((DECKS / "harrison_flat.toml").read_text()).model)
    assert 'tribology.film_model = "steady" has no squeeze film' in " ".join(r.warnings)
    assert "film_steady" not in r.columns


def test_march_on_its_own_angle_step():
    """solver.film_angle_step marches on its own grid: a step equal to the run's grid gives the
    same film (1e-12); a step of half of it a film within the first-order march error (10 %)."""
    base = run(extra=FAST)
    same = run(extra=FAST + "film_angle_step = 2.0\n")
    np.testing.assert_allclose(same["film_min"], base["film_min"], rtol=1e-12)
    fine = run(extra=FAST + "film_angle_step = 1.0\n")
    assert np.nanmax(np.abs(fine["film_min"] / base["film_min"] - 1.0)) < 0.1
    assert math.isfinite(fine.metrics["film_cycles"].value)


@pytest.mark.derived
def test_gocmen_base_circle_at_400_rpm():
    """Göçmen §4 D3: at camshaft 400 rpm the eq. 2.1 base-circle film is 0.0494 um (h ~ omega^0.7;
    printed digits)."""
    r = run(camshaft=400.0, extra=FAST)
    np.testing.assert_allclose(r["film_min"][base_circle(r)] * 1e6, 0.0494, atol=5e-5)


@pytest.mark.parametrize("model", ["squeeze", "averaged_reynolds"])
def test_any_contact_load_with_separation(model):
    """The film laws use only the load array: a load from another model (here the rigid load
    with a loss of contact over the nose and a 20 % ripple, as a dynamics run could give) runs;
    out of contact the film is NaN (level 2: labelled separated), in contact positive."""
    contact, kin, load = pair(model=model, extra=FAST)
    theta = kin.theta
    dynamic = load * (1.0 + 0.2 * np.sin(12.0 * theta)) - 1500.0 * np.exp(-(theta / 0.1) ** 2)
    film = contact.film(kin, np.maximum(dynamic, 0.0))
    off = dynamic <= 0.0
    assert off.any() and (~off).any()
    assert np.all(np.isnan(film.min[off]))
    assert np.all(film.min[~off] > 0.0)
    if model == "averaged_reynolds":
        assert set(film.regime[off]) == {"separated"}
        assert np.all(film.friction[off] == 0.0)
