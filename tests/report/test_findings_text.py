"""Findings (zero entrainment, bounce, boundary, concavity) and the report.txt hard copy."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain import api
from camtrain.report.findings import find, true_ranges, zero_crossings
from camtrain.report.limits import evaluate
from camtrain.report.text import report_text
from tests.conftest import MINIMAL_DECK
from tests.report.conftest import synthetic


def test_zero_crossings_are_interpolated():
    theta = np.linspace(-1.0, 1.0, 5)
    assert zero_crossings(theta, theta ** 2 - 0.25) == [-0.5 - 0.0, 0.5]


def test_true_ranges_at_both_ends():
    theta = np.arange(6.0)
    assert true_ranges(theta, [1, 1, 0, 0, 1, 1]) == [(0.0, 1.0), (4.0, 5.0)]


def test_findings_of_synthetic_cases():
    f = find(synthetic(720))
    assert len(f.zero_entrainment) == 2
    assert f.zero_entrainment[0] == pytest.approx(-f.zero_entrainment[1]) and f.zero_entrainment[1] > 0
    assert not f.loss_of_contact and not f.concave
    bounce = find(synthetic(720, bounce=True))
    (a, b), = bounce.loss_of_contact
    assert a < 0 < b                          # around the nose, where inertia lifts the follower
    assert find(synthetic(720, concave=True)).concave
    messages = bounce.messages()
    assert any(m.startswith("valve bounce") for m in messages)
    # a warning the physics already gave is not repeated
    assert not any("entrainment" in m for m in
                   f.messages(["entrainment velocity passes through zero at ..."]))


def test_report_txt_has_header_echo_results_limits_warnings_table():
    deck = api.loads(MINIMAL_DECK + "\n[limits]\nmax_hertz = 500\n", "mini.toml")
    result = synthetic(360)
    checks = evaluate(deck.model.limits, result, 1500.0)
    text = report_text(result, deck.model, path="mini.toml", sha=deck.sha256, checks=checks,
                       wall_time=0.5)
    assert "CAM OPERATING CHARACTERISTICS" in text
    assert "Cam base radius (mm)" in text and "= 18.00" in text
    assert "Frictional power loss (W)" in text
    assert "cam.base_radius" in text and " mm " in text          # input echo with units
    assert "limits.max_hertz" in text and "MPa" in text
    assert "--- RESULTS" in text and "hertz_max" in text
    assert "--- DESIGN LIMITS" in text and "max_hertz" in text
    assert "synthetic result for tests" in text                 # run warnings
    assert "zero entrainment" in text                           # findings
    table = text[text.index("CYCLE TABLE"):]
    assert "[deg]" in table and "[µm]" in table and "[MPa]" in table
    assert table.count("\n    -180.0") == math.ceil(len(
        [c for c in ("lift", "velocity", "acceleration", "eccentricity", "cam_radius",
                     "equivalent_radius", "v_cam", "v_follower", "entrainment", "load",
                     "hertz_pmax", "film_min", "film_central", "lambda",
                     "friction_coefficient", "friction_torque", "power_loss")]) / 9)


def test_report_txt_of_lift_only_result_without_deck():
    text = report_text(synthetic(90, level="lift"))
    assert "Frictional power loss" not in text          # no deck, no loads: nothing to say
    assert "DESIGN LIMITS" not in text and "lift" in text
