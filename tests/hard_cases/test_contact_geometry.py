"""Contact geometry at its limits: zero entrainment at the nose, concave flanks against a curved
follower, conformal contact (R -> inf) and a sharp nose (r_c -> 0)."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain import mechanisms as M
from camtrain.assemble.lift_law import build_lift_law
from camtrain.contact.model import contact_film, contact_hertz
from camtrain.deck.load import load_deck
from camtrain.errors import GeometryError
from camtrain.lift import angle_grid

from .conftest import DECKS, HARRISON, finite_columns, run_strict, variant

CHAIN = ("load", "hertz_pmax", "entrainment", "film_min", "friction_force", "friction_torque",
         "power_loss")


def _nose_index(res) -> int:
    i = int(np.argmin(np.abs(res["cam_angle"])))
    assert res["cam_angle"][i] == 0.0  # an even grid holds the nose exactly
    return i


def _exact_zero_entrainment_radius() -> float:
    """Ball §5.2.1: V_c + V_f = 0 at the nose of a flat follower when r_B = -(2 l'' + l) [mm]."""
    res = run_strict(HARRISON)
    i = _nose_index(res)
    return float(-1e3 * (2.0 * res["acceleration"][i] + res["lift"][i]))


def test_ball_radius_for_zero_entrainment_is_33_247_mm():
    assert _exact_zero_entrainment_radius() == pytest.approx(33.247, abs=5e-4)


@pytest.mark.parametrize("points", [360, 720, 1440])
def test_harrison_zero_entrainment_at_the_nose(points):
    """r_B at Ball's value (printed 33.247 mm, exact from the deck's own l and l''): the film at
    the nose vanishes, friction falls to the boundary cap, everything stays finite."""
    rb = _exact_zero_entrainment_radius()
    for radius, film_bound in ((33.247, 1e-9), (rb, 1e-12)):
        res = run_strict(variant(HARRISON, ("base_radius = 18.0", f"base_radius = {radius!r}"),
                                 ("angle_points = 1440", f"angle_points = {points}")))
        i = _nose_index(res)
        finite_columns(res, CHAIN)
        assert abs(res["entrainment"][i]) <= 1e-5 * res["v_cam"][i]
        assert 0.0 <= res["film_min"][i] < film_bound  # normally ~0.5 um at the nose
        assert res["friction_coefficient"][i] == pytest.approx(0.08)
        assert res["friction_force"][i] == pytest.approx(0.08 * res["load"][i])
        assert any("passes through zero" in w for w in res.warnings)


def test_zero_entrainment_power_loss_converges_with_angle_points():
    """The nose is a grid point at every even resolution; power loss settles under refinement."""
    rb = _exact_zero_entrainment_radius()
    text = variant(HARRISON, ("base_radius = 18.0", f"base_radius = {rb!r}"))
    p = [run_strict(variant(text, ("angle_points = 1440", f"angle_points = {n}")))
         .metrics["power_loss_mean"].value for n in (720, 1440, 2880, 5760)]
    d = np.abs(np.diff(p))
    assert np.all(np.isfinite(p)) and d[-1] < d[0] and d[-1] < 2e-3 * p[-1]


@pytest.fixture(scope="module")
def harrison_curve():
    deck = load_deck(str(DECKS / "harrison_flat.toml")).model
    return deck, build_lift_law(deck.lift).evaluate(angle_grid(720))


def test_concave_flanks_against_a_domed_follower(harrison_curve):
    """r_B = 10 mm gives concave flanks (r_c < 0, through +-inf at the inflections); a 20 mm domed
    follower still fits (|r_c| > r_f), so R stays finite and positive."""
    deck, curve = harrison_curve
    with np.errstate(all="raise"):
        k = M.domed(curve, base_radius=0.010, follower_radius=0.020, omega=deck.speed.omega)
    rc, R = k.cam_radius, k.equivalent_radius
    assert rc.min() < -0.020  # concave, less curved than the follower
    finite = np.isfinite(rc)
    assert np.all(R[finite] > 0) and np.all(np.isfinite(R))


def test_concave_flank_tighter_than_the_follower_is_a_clear_error(harrison_curve):
    deck, curve = harrison_curve
    with pytest.raises(GeometryError, match="follower_radius") as err:
        M.domed(curve, base_radius=0.010, follower_radius=0.200, omega=deck.speed.omega)
    assert err.value.exit_code == 3


def test_conformal_contact_r_c_to_minus_r_f(harrison_curve):
    """1/R = 1/r_c + 1/r_f: R grows without bound as r_c -> -r_f and is +inf at equality; the
    Hertz and film steps turn R = inf into NaN (documented) and large R into finite values."""
    deck, curve = harrison_curve
    rf = 0.020
    rc = -rf * (1.0 + np.array([1e-1, 1e-3, 1e-6, 1e-9, 0.0]))
    with np.errstate(all="raise"):
        R = M.base.equivalent_radius(rc, rf)
    assert np.all(np.diff(R[:-1]) > 0) and np.isinf(R[-1])
    assert R[-2] == pytest.approx(rf / 1e-9, rel=1e-6)
    k = M.domed(curve, base_radius=0.010, follower_radius=rf, omega=deck.speed.omega)
    big = k.equivalent_radius.copy()
    i = int(np.argmax(k.valve_lift))
    big[i] = R[-2]
    from dataclasses import replace

    kin = replace(k, equivalent_radius=big, radius_x=big)
    load = np.where(k.valve_lift > 0, 300.0, 0.0)
    with np.errstate(all="raise"):
        hz = contact_hertz(deck, kin, load)
        film = contact_film(deck, kin, load)
    pmax = np.asarray(hz.pmax)
    assert np.isfinite(pmax[i]) and 0 < pmax[i] < np.median(pmax[load > 0])  # flatter contact
    assert np.isfinite(film.min[i]) and film.min[i] > 0


def test_sharp_nose_r_c_to_zero():
    """A flat follower needs r_B > max -(l + l'') = 13.5903 mm for a convex cam (13.5896 mm on
    a 720-angle grid, which misses the worst angle; 13.5902 mm on the default 1440). Approaching
    it the nose radius -> 0: Hertz stress rises without bound but stays finite; just below it is
    a clear geometry error (exit 3) that names the radius needed."""
    pmax = []
    for rb in ("13.7", "13.6", "13.591"):
        res = run_strict(variant(HARRISON, ("base_radius = 18.0", f"base_radius = {rb}")))
        finite_columns(res, CHAIN)
        assert res.metrics["cam_radius_min"].value > 0
        pmax.append(res.metrics["hertz_max"].value)
    assert pmax[0] < pmax[1] < pmax[2]
    with pytest.raises(GeometryError, match="base-circle radius must exceed") as err:
        run_strict(variant(HARRISON, ("base_radius = 18.0", "base_radius = 13.58")))
    assert err.value.exit_code == 3
