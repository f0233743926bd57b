"""Design limits against metrics and per-angle columns, and their JUnit XML report."""
from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from camtrain import api
from camtrain.report.junit import DeckReport, junit_xml
from camtrain.report.limits import FAIL, PASS, UNAVAILABLE, evaluate
from tests.conftest import MINIMAL_DECK
from tests.report.conftest import synthetic


def _limits(text: str):
    return api.loads(MINIMAL_DECK + "\n[limits]\n" + text, "d.toml").model.limits


def test_limits_section_is_in_deck_units():
    lim = _limits("max_hertz = 650\nmin_film = 0.1\nmin_bounce_margin = 10\n")
    assert lim.max_hertz == pytest.approx(650e6)
    assert lim.min_film == pytest.approx(0.1e-6)
    assert lim.min_bounce_margin == pytest.approx(0.10)


def test_invalid_limit_is_an_input_error():
    from camtrain.errors import InputError

    with pytest.raises(InputError, match="limits.max_hertz"):
        _limits("max_hertz = -1\n")


def test_max_limit_reports_worst_value_and_angle():
    r = synthetic(720)
    p = r["hertz_pmax"]
    i = int(np.argmax(p))
    (c,) = evaluate(_limits(f"max_hertz = {p[i] * 1e-6 * 0.9}\n"), r, 2500.0)
    assert c.status == FAIL and c.value == pytest.approx(p[i] * 1e-6)
    assert c.angle_deg == pytest.approx(math.degrees(r["cam_angle"][i]), abs=1e-6)
    assert "VIOLATED" in c.text() and "MPa" in c.text()
    (c,) = evaluate(_limits(f"max_hertz = {p[i] * 1e-6 * 1.1}\n"), r, 2500.0)
    assert c.status == PASS and c.ok


def test_min_film_looks_only_where_in_contact():
    r = synthetic(720, bounce=True)       # film is NaN and load <= 0 around the nose
    (c,) = evaluate(_limits("min_film = 0.001\n"), r, 2500.0)
    contact = r["load"] > 0
    assert c.value == pytest.approx(np.nanmin(r["film_min"][contact]) * 1e6)
    assert c.unit == "µm"


def test_bounce_margin_and_power_from_metrics():
    r = synthetic(360)
    bounce = r.metrics["bounce_speed"].value
    checks = evaluate(_limits("min_bounce_margin = 20\nmax_power_loss = 1000\n"), r, 2500.0)
    margin = {c.limit: c for c in checks}["min_bounce_margin"]
    assert margin.value == pytest.approx(100 * (1 - 2500.0 / bounce))
    assert margin.status == PASS and margin.angle_deg is not None
    assert {c.limit: c for c in checks}["max_power_loss"].angle_deg is None
    (c,) = evaluate(_limits("min_bounce_margin = 40\n"), r, 2500.0)
    assert c.status == FAIL


def test_limit_without_data_is_unavailable_and_not_ok():
    (c,) = evaluate(_limits("max_power_loss = 10\n"), synthetic(90, level="lift"), 1500.0)
    assert c.status == UNAVAILABLE and not c.ok and "not computed" in c.text()


def test_no_limits_section_no_checks():
    assert evaluate(None, synthetic(90), 1500.0) == []


def test_junit_xml_suites_cases_and_counts():
    r = synthetic(360)
    checks = evaluate(_limits("max_hertz = 1\nmax_load = 1e9\nmax_power_loss = 1e9\n"), r, 2500)
    xml = junit_xml([
        DeckReport("a", "a.toml", 0.5, checks),
        DeckReport("b", "b.toml", 0.1),
        DeckReport("c", "c.toml", 0.0, error="c.toml: 1 problem in the deck", exit_code=2),
    ])
    root = ET.fromstring(xml)
    assert root.tag == "testsuites"
    assert (root.get("tests"), root.get("failures"), root.get("errors")) == ("5", "1", "1")
    suites = root.findall("testsuite")
    assert [s.get("name") for s in suites] == ["a", "b", "c"]
    a = suites[0]
    assert [t.get("name") for t in a.findall("testcase")] == ["max_hertz", "max_power_loss",
                                                               "max_load"]
    failure = a.find("testcase/failure")
    assert failure is not None and "max_hertz" in failure.get("message")
    assert suites[1].find("testcase").get("name") == "run"
    assert suites[2].find("testcase/error").get("type") == "exit 2"
