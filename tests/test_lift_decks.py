"""Lift laws reached through decks and the `camtrain lift` command (the deck -> law adapter)."""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest
from click.testing import CliRunner

from camtrain import api
from camtrain.assemble.lift_law import build_lift_law
from camtrain.cli import main
from camtrain.deck.load import validate
from camtrain.errors import InputError
from tests.conftest import DECKS, MINIMAL_DECK


def test_harrison_deck_lift_reproduces_ball():
    """Ball (1988) §5.2 / Fig 5.1: peak valve lift 9.40 mm = ramp 0.50 + l_max 8.90; event
    (ramps included) from -85 to +85 deg. Exact for the analytic law: tolerance is round-off."""
    result = api.lift(DECKS / "harrison_flat.toml")
    assert result.metrics["max_lift"].value == pytest.approx(9.40e-3, rel=1e-12)
    assert math.degrees(result.metrics["closing_angle"].value) == pytest.approx(85.0)
    assert math.degrees(result.metrics["opening_angle"].value) == pytest.approx(-85.0)


def test_rover_deck_lift_at_nose():
    """Ball (1988) §2.1(d): Lim et al. fit, lift at the nose e^a = 10.1463 mm (printed 10.15);
    the shift blend leaves the nose exact, so the tolerance is the 5th printed digit."""
    result = api.lift(DECKS / "rover_2300_rocker.toml")
    assert result.metrics["max_lift"].value == pytest.approx(10.1463e-3, abs=5e-8)


def test_pinto_table_deck_peak_cam_lift_and_noise():
    """Ball (1988) App E: peak cam lift 6.3323 mm at 0 deg; printed to 4 decimals, so the
    smoothing spline may move the peak by about the data quantum (1e-4 mm)."""
    result = api.lift(DECKS / "pinto_finger.toml")
    assert result.metrics["max_lift"].value == pytest.approx(6.3323e-3, abs=1e-7)
    assert result.metrics["table_noise_acceleration"].value > 0


def _deck_with_lift(lift: dict) -> dict:
    raw = tomllib.loads(MINIMAL_DECK)
    raw["lift"] = lift
    return raw


def test_every_form_builds_from_a_deck():
    forms = {
        "polynomial": {"form": "polynomial", "polynomial": {
            "half_period": 60, "max_lift": 9, "exponents": [2, 8, 14, 20, 26]}},
        "exp_poly": {"form": "exp_poly", "exp_poly": {"coefficients": [2.3, 0, -1.5]}},
        "multipol": {"form": "multipol", "ramps": {"opening_height": 0.3333},
                     "multipol": {"segments": [
                         {"length": 3.0, "coefficients": [0.037, 0.0, 0.04894, -0.01224, 0.0]},
                         {"length": 8.0, "coefficients": [0.35969, 0.52204, 0, 0, 0]},
                         {"length": 5.0, "coefficients": [0.87736, 0.20392, 0, -0.08113,
                                                          0.02828]},
                         {"length": 5.0, "coefficients": [1.10212, 0, -0.04167, 0.02153,
                                                          -0.00490]},
                         {"length": 34.0, "coefficients": [7.06324, -2.07447, -1.44115,
                                                           0.34428, 0.00640]}]}},
        "table": {"form": "table", "table": {"dataset": "zeta_intake"}},
    }
    for name, lift in forms.items():
        law = build_lift_law(validate(_deck_with_lift(lift)).lift)
        curve = law.evaluate(np.linspace(-np.pi, np.pi, 721))
        assert np.all(np.isfinite(curve.d2)), name
        assert curve.lift.max() > 1e-3, name


def test_multipol_with_printed_c4_sign_is_refused_naming_the_segment():
    """Ball (1988) App F prints C4 = +.08113 for segment 3; only -.08113 is continuous. The
    printed value must be refused with the field path of the segment."""
    lift = {"form": "multipol", "ramps": {"opening_height": 0.3333}, "multipol": {"segments": [
        {"length": 3.0, "coefficients": [0.037, 0.0, 0.04894, -0.01224, 0.0]},
        {"length": 8.0, "coefficients": [0.35969, 0.52204, 0, 0, 0]},
        {"length": 5.0, "coefficients": [0.87736, 0.20392, 0, 0.08113, 0.02828]},
        {"length": 5.0, "coefficients": [1.10212, 0, -0.04167, 0.02153, -0.00490]},
        {"length": 34.0, "coefficients": [7.06324, -2.07447, -1.44115, 0.34428, 0.00640]}]}}
    with pytest.raises(InputError) as info:
        build_lift_law(validate(_deck_with_lift(lift)).lift)
    assert "lift.multipol.segments[" in str(info.value)


def test_lift_command_writes_table_and_plots(tmp_path):
    res = CliRunner().invoke(main, ["lift", str(DECKS / "harrison_flat.toml"), "--out",
                                    str(tmp_path), "--points", "360", "--quiet"])
    assert res.exit_code == 0, res.output
    header = (tmp_path / "lift.csv").read_text().splitlines()[0]
    assert header == ("cam_angle[deg],lift[mm],velocity[mm/deg],acceleration[mm/deg²],"
                      "jerk[mm/deg³]")
    assert len((tmp_path / "lift.csv").read_text().splitlines()) == 361
    assert (tmp_path / "lift.png").stat().st_size > 10_000
    assert (tmp_path / "lift.pdf").exists()


def test_lift_command_units_si(tmp_path):
    """--units si writes the lift table in SI for machine pipelines, the angle in rad too."""
    res = CliRunner().invoke(main, ["lift", str(DECKS / "harrison_flat.toml"), "--out",
                                    str(tmp_path), "--points", "360", "--quiet", "--no-plots",
                                    "--units", "si"])
    assert res.exit_code == 0, res.output
    lines = (tmp_path / "lift.csv").read_text().splitlines()
    assert lines[0] == ("cam_angle[rad],lift[m],velocity[m/rad],acceleration[m/rad^2],"
                        "jerk[m/rad^3]")
    assert abs(max(abs(float(r.split(",")[0])) for r in lines[1:]) - 3.14159) < 0.02


def test_lift_command_bad_table_exit_2(tmp_path):
    deck = tmp_path / "d.toml"
    raw = _deck_with_lift({"form": "table", "table": {"file": "missing.csv"}})
    import tomli_w

    deck.write_text(tomli_w.dumps(raw))
    res = CliRunner().invoke(main, ["lift", str(deck), "--out", str(tmp_path / "o")])
    assert res.exit_code == 2 and "lift.table.file" in res.output
