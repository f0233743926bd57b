"""Roller followers from decks: the drawn layout, the roller against the curved follower it
carries, the valve pad and pivot effect, the roller's inertia in the elastic train, bad input."""
from __future__ import annotations

import copy
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
import tomli_w
from click.testing import CliRunner

from camtrain import api
from camtrain.cli import main
from camtrain.deck.load import validate
from camtrain.deck.schema_follower import dyson_from_layout

DECK = Path(__file__).resolve().parents[2] / "decks" / "roller_finger.toml"


def _raw() -> dict:
    return tomllib.loads(DECK.read_text(encoding="utf-8"))


def _run(raw: dict):
    return api.run(api.loads(tomli_w.dumps(raw), "deck.toml"))


def _dyson_raw(raw: dict) -> dict:
    """The same deck with A, B, D, kappa, lambda in place of the drawn layout."""
    out = copy.deepcopy(raw)
    layout = validate(raw).mechanism.layout
    d = dyson_from_layout(layout)
    mech = out["mechanism"]
    del mech["layout"]
    mech.update(A=d.A * 1e3, B=d.B * 1e3, D=d.D * 1e3, kappa=math.degrees(d.kappa))
    mech["lambda"] = math.degrees(d.lam)
    return out


@pytest.mark.derived
def test_layout_by_hand():
    """Pivot (-32, -29), roller (0, -25.75), pad (20, -28) mm, valve opening at -90 deg:
    D = |U| = 43.18565 mm, A = |Q - U| = 32.16462 mm, B = |V - U| = 52.00961 mm, and the drawn
    points come back from Dyson's geometry at the base circle, turned by the pivot's angle."""
    from camtrain.assemble.mechanism import pivot_geometry

    deck = validate(_raw())
    d = dyson_from_layout(deck.mechanism.layout)
    assert d.D * 1e3 == pytest.approx(math.hypot(32, 29), abs=1e-9)
    assert d.D * 1e3 == pytest.approx(43.18565, abs=1e-5)
    assert d.A * 1e3 == pytest.approx(32.16462, abs=1e-5)
    assert d.B * 1e3 == pytest.approx(52.00961, abs=1e-5)
    g = pivot_geometry(deck.mechanism, deck.cam.base_radius, "end")
    turn = math.atan2(-29.0, -32.0)
    back = np.array([[math.cos(turn), -math.sin(turn)], [math.sin(turn), math.cos(turn)]])
    pts = {k: back @ v * 1e3 for k, v in g.points().items()}
    assert pts["U"] == pytest.approx([-32.0, -29.0], abs=1e-9)
    assert pts["Q"] == pytest.approx([0.0, -25.75], abs=1e-9)
    assert pts["V"] == pytest.approx([20.0, -28.0], abs=1e-9)
    # the valve opens along (cos kappa, -sin kappa) in Dyson's frame: straight down here
    opening = back @ np.array([math.cos(g.kappa), -math.sin(g.kappa)])
    assert opening == pytest.approx([0.0, -1.0], abs=1e-12)


def test_layout_equals_dyson_fields():
    """The drawn layout and the A, B, D, kappa, lambda it converts to run the same train."""
    raw = _raw()
    drawn, fields = _run(raw), _run(_dyson_raw(raw))
    for name in ("load", "v_cam", "v_follower", "valve_lift", "pressure_angle", "hertz_pmax",
                 "pad_sliding_speed", "pivot_friction_power"):
        assert np.allclose(drawn.columns[name].values, fields.columns[name].values,
                           rtol=1e-9, atol=1e-12), name


@pytest.mark.derived
def test_roller_equals_curved_finger_of_its_radius():
    """Without its rotation (locked roller) and without roller mass, a roller finger follower
    is the curved end-pivoted follower of the roller's radius: every column equal to 1e-12."""
    raw = _raw()
    raw["mechanism"].pop("roller")
    sliding = copy.deepcopy(raw)
    sliding["mechanism"]["follower"] = "sliding"
    a, b = _run(raw), _run(sliding)
    assert set(a.columns) == set(b.columns)
    for name, column in a.columns.items():
        assert np.allclose(column.values, b.columns[name].values, rtol=1e-12, atol=0,
                           equal_nan=True), name


def test_pad_load_is_the_valve_force():
    """The pad load from the arm's moment balance is the valve-side force of the loads effect
    (spring and valve inertia) wherever the cam lifts the valve: the balance closes. (On the
    base circle the lash adjuster's load presses the pad on the seated valve instead.)"""
    result = _run(_raw())
    load = result.columns["load"].values
    on = (load > 0) & (result.columns["valve_force"].values > 0)
    base = result.columns["valve_lift"].values == 0
    assert np.all(result.columns["pad_load"].values[base] > 0)
    assert np.allclose(result.columns["pad_load"].values[on],
                       result.columns["valve_force"].values[on], rtol=1e-9)


def test_roller_mass_adds_m_a2_about_the_pivot():
    """The roller's mass at its centre adds m_r A^2 to the finger's inertia about the pivot:
    the rigid train's load grows by omega^2 m_r A^2 q'' / arm_normal."""
    from camtrain.assemble.mechanism import body_inertia

    deck = validate(_raw())
    A = dyson_from_layout(deck.mechanism.layout).A
    assert body_inertia(deck)["follower_inertia"] == pytest.approx(2.5e-5 + 0.012 * A * A,
                                                                   rel=1e-12)


def test_roller_inertia_in_the_elastic_train():
    """A roller finger follower deck runs [dynamics]; the valve-referred mass of the train
    holds the finger's and the roller's inertia about the pivot over B^2."""
    from camtrain.assemble.dynamics import build_model

    raw = _raw()
    raw["dynamics"] = {"follower_mass": 0.02, "contact_stiffness": 2.0e5,
                       "rocker_stiffness": 1.5e4, "seat_stiffness": 2.0e5}
    deck = validate(raw)
    heavy = build_model(deck)
    light_raw = copy.deepcopy(raw)
    light_raw["mechanism"]["roller"]["mass"] = 0.0
    light = build_model(validate(light_raw))
    d = dyson_from_layout(deck.mechanism.layout)
    assert heavy.total_mass() - light.total_mass() == pytest.approx(
        0.012 * d.A ** 2 / d.B ** 2, rel=1e-9)
    result = _run(raw)
    assert "dynamics" in result.plan.chosen
    assert np.isfinite(result.metrics["load_max"].value)


def test_crowned_roller_is_an_elliptical_contact():
    """A crowned roller, not turning: the deck without its [roller] section (a turning crowned
    roller: tests/roller/test_crowned_roller.py)."""
    raw = _raw()
    raw.pop("roller")
    raw["mechanism"]["roller"]["crown_radius"] = 500.0
    from camtrain.assemble.lift_law import build_lift_law
    from camtrain.assemble.mechanism import kinematics
    from camtrain.lift import angle_grid

    deck = validate(raw)
    k, _ = kinematics(deck, build_lift_law(deck.lift).evaluate(angle_grid(720)))
    assert np.all(k.radius_y == 0.5) and not k.line_contact
    assert k.mechanism == "roller end-pivoted follower"
    plain = _raw()
    plain.pop("roller")
    straight = _run(plain)
    crowned = _run(raw)       # an elliptical contact carries the load at a higher pressure
    assert crowned.metrics["hertz_max"].value > straight.metrics["hertz_max"].value


def _exit_2(tmp_path, raw, *fields):
    deck = tmp_path / "bad.toml"
    deck.write_text(tomli_w.dumps(raw))
    res = CliRunner().invoke(main, ["check", str(deck)])
    assert res.exit_code == 2, res.output
    assert "Traceback" not in res.output
    for field in fields:
        assert field in res.output, res.output
    return res.output


def test_bad_roller_inputs_exit_2_naming_the_field(tmp_path):
    raw = _raw()
    off = copy.deepcopy(raw)
    off["mechanism"]["layout"]["roller_centre"] = [0.0, -26.0]
    out = _exit_2(tmp_path, off, "mechanism.layout.roller_centre")
    assert "25.7500 mm" in out and "26.0000 mm" in out
    both = copy.deepcopy(raw)
    both["mechanism"]["A"] = 32.0
    _exit_2(tmp_path, both, "mechanism.A", "[mechanism.layout]")
    no_width = copy.deepcopy(raw)
    del no_width["mechanism"]["arm"]["pad_width"]
    _exit_2(tmp_path, no_width, "mechanism.arm.pad_width")
    stray = copy.deepcopy(raw)
    stray["mechanism"]["follower"] = "sliding"
    _exit_2(tmp_path, stray, "mechanism.roller")
    flat = {k: v for k, v in copy.deepcopy(raw).items()}
    flat["mechanism"] = {"type": "flat", "follower": "roller"}
    _exit_2(tmp_path, flat, "mechanism.follower")
    tappet = copy.deepcopy(raw)
    tappet["mechanism"] = {"type": "domed", "follower": "roller", "follower_radius": 10.0,
                           "roller": {"mass": 0.01}, "arm": raw["mechanism"]["arm"]}
    _exit_2(tmp_path, tappet, "mechanism.roller.mass", "mechanism.arm")
    tapered = copy.deepcopy(tappet)
    tapered["mechanism"] = {"type": "domed", "follower": "roller", "follower_radius": 10.0}
    tapered["cam"]["taper_angle"] = 0.1
    _exit_2(tmp_path, tapered, "cam.taper_angle")
    at_pivot = copy.deepcopy(raw)
    at_pivot["mechanism"]["layout"]["pad_centre"] = [-32.0, -29.0]
    _exit_2(tmp_path, at_pivot, "mechanism.layout.pad_centre")


@pytest.mark.derived
def test_pad_load_and_pivot_reaction_by_hand():
    """The deck's layout on the base circle, 100 N on the roller, no friction: the normal
    through the roller centre is vertical (x = 0), 32 mm from the pivot; the valve axis through
    the pad contact is vertical (x = 20 mm), 52 mm from it. So F_pad = 100 x 32/52 = 61.5385 N
    and, both forces vertical, the pivot reaction is 100 - 61.5385 = 38.4615 N; the ball socket
    (4 mm, 0.1) carries 0.1 x 4 mm x 38.4615 N = 0.0153846 N m."""
    from camtrain.assemble.lift_law import build_lift_law
    from camtrain.assemble.mechanism import kinematics, pivot_geometry
    from camtrain.lift import angle_grid
    from camtrain.mechanisms.arm_contacts import arm_contacts

    deck = validate(_raw())
    k, _ = kinematics(deck, build_lift_law(deck.lift).evaluate(angle_grid(720)))
    g = pivot_geometry(deck.mechanism, deck.cam.base_radius, "end")
    out = arm_contacts(k, g, np.full(k.theta.shape, 100.0), pad_radius=12e-3, pad_width=5.5e-3,
                       pivot_radius=4e-3, pivot_friction=0.1, pad_friction=0.1,
                       reduced_modulus=2.3e11)
    base = 0                                       # theta = -180 deg, on the base circle
    assert out.pad_load[base] == pytest.approx(100 * 32 / 52, rel=1e-9)
    assert out.pivot_reaction[base] == pytest.approx(100 - 100 * 32 / 52, rel=1e-9)
    assert out.pivot_friction_torque[base] == pytest.approx(0.1 * 4e-3 * 38.461538, rel=1e-7)
    assert out.pad_sliding_speed[base] == 0.0 and out.pad_travel[base] == 0.0


def test_push_rod_roller_lifter_is_a_line_contact():
    from camtrain import api as _api
    from camtrain.deck.templates import render_template

    loaded = _api.loads(render_template("pushrod_roller"), "pushrod_roller.toml")
    from camtrain.assemble.lift_law import build_lift_law
    from camtrain.assemble.mechanism import kinematics
    from camtrain.lift import angle_grid

    deck = loaded.model
    k, _ = kinematics(deck, build_lift_law(deck.lift).evaluate(angle_grid(720)))
    assert k.mechanism == "roller simple push rod" and k.line_contact
    assert np.all(k.follower_radius == 12e-3)


@pytest.mark.derived
def test_roller_rocker_by_hand():
    """The roller rocker template on its base circle: pivot (25, 32), roller (0, 25.75), pad
    centre (62, 27) mm, valve opening down. The normal through the roller is the line x = 0,
    25 mm from the pivot; the valve axis through the pad contact is x = 62 mm, 37 mm from it:
    load ratio W/F = 37/25 = 1.48. A centre pivot carries both forces, cam up and valve up on
    the arm: reaction W + F = 100 (1 + 25/37) = 167.5676 N for 100 N on the roller."""
    from camtrain import api as _api
    from camtrain.assemble.lift_law import build_lift_law
    from camtrain.assemble.mechanism import kinematics, pivot_geometry
    from camtrain.deck.templates import render_template
    from camtrain.lift import angle_grid
    from camtrain.mechanisms.arm_contacts import arm_contacts

    deck = _api.loads(render_template("roller_rocker"), "roller_rocker.toml").model
    k, _ = kinematics(deck, build_lift_law(deck.lift).evaluate(angle_grid(720)))
    assert k.mechanism == "roller central-pivoted follower"
    assert k.rocker_ratio[0] == pytest.approx(37 / 25, rel=1e-9)
    g = pivot_geometry(deck.mechanism, deck.cam.base_radius, "central")
    out = arm_contacts(k, g, np.full(k.theta.shape, 100.0), pad_radius=12e-3,
                       pad_shape="spherical", reduced_modulus=2.3e11)
    assert out.pad_load[0] == pytest.approx(100 * 25 / 37, rel=1e-9)
    assert out.pivot_reaction[0] == pytest.approx(100 * (1 + 25 / 37), rel=1e-9)
    assert out.pad_max_pressure[0] > 0 and np.all(out.pivot_friction_torque == 0)
