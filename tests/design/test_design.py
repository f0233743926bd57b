"""`camtrain design`: the events of two shipped cams give a spline lift that meets every event
within its tolerance, exceeds no limit, and is continuous to the jerk."""
from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest
import tomli_w

import camtrain.api as ct
from camtrain.assemble.lift_law import build_lift_law
from camtrain.lift.base import DEG, MM
from tests.conftest import DECKS, ROOT
from tests.design._events import read_events

#: (deck, checking heights [mm], whether its law has ramps)
SHIPPED = [("harrison_flat.toml", (1.0, 4.0), True),      # symmetric four-power with ramps
           ("rover_2300_rocker.toml", (0.5, 3.0), False)]  # asymmetric exponential fit


def _deck_with(tmp_path: Path, deck: str, section: dict) -> Path:
    raw = tomllib.loads((DECKS / deck).read_text(encoding="utf-8"))
    raw["design"] = section
    path = tmp_path / deck
    path.write_text(tomli_w.dumps(raw), encoding="utf-8")
    return path


@pytest.fixture(scope="module", params=SHIPPED, ids=[s[0] for s in SHIPPED])
def designed(request, tmp_path_factory):
    deck, heights, ramp = request.param
    section, law = read_events(deck, heights, ramp)
    if deck.startswith("harrison"):
        section["symmetric"] = True
        del section["closing_angles"]
    path = _deck_with(tmp_path_factory.mktemp("design"), deck, section)
    out = path.parent / "out"
    return section, ct.design(path, out, plots=False), out


def test_the_design_runs_on_one_blas_thread(monkeypatch, tmp_path):
    """Its small dense solves in a loop gain nothing from a second BLAS thread, which spins
    between calls and, on a busy two-core machine, waits for a core (the Rover design took
    19-28 s there for 0.5-1 s of work): inside the design every BLAS library loaded, scipy's own
    beside numpy's, has one thread, and after it the counts it had before."""
    import scipy.linalg  # noqa: F401  (its OpenBLAS loaded: the counts before include it)
    from threadpoolctl import threadpool_info

    from camtrain.design import construct
    from camtrain.design.command import events_of

    def blas_threads():
        return [lib["num_threads"] for lib in threadpool_info() if lib["user_api"] == "blas"]

    seen = []

    def look(ev, end_open, end_close):
        seen.append(blas_threads())
        raise construct.DesignInfeasible("only a look inside the design")

    section, _ = read_events("harrison_flat.toml", (1.0, 4.0), True)
    ev = events_of(ct.load(_deck_with(tmp_path, "harrison_flat.toml", section)).model)[0]
    monkeypatch.setattr(construct, "_design_at", look)
    before = blas_threads()
    with pytest.raises(construct.DesignInfeasible):
        construct.design_lift(ev)
    assert len(seen[0]) >= 2 and set(seen[0]) == {1}
    assert blas_threads() == before


def test_every_event_met_within_its_tolerance(designed):
    section, outcome, _ = designed
    events = [i for i in outcome.items if i.kind == "event"]
    assert len(events) >= 2 + 2 * len(section["checking_heights"])
    for item in events:
        assert item.met, item.row()


def test_no_limit_exceeded_on_a_fine_grid(designed):
    section, outcome, _ = designed
    theta = np.arange(-180.0, 180.0, 0.002)
    c = outcome.law.evaluate(theta * DEG)
    assert c.lift.max() / MM <= section["max_lift"] + 1e-9
    assert (c.d2 / MM * DEG ** 2).max() <= section["max_acceleration"]
    assert -(c.d2 / MM * DEG ** 2).min() <= section["max_deceleration"]
    assert np.abs(c.d3 / MM * DEG ** 3).max() <= section["max_jerk"]
    assert all(i.met for i in outcome.items if i.kind == "limit")


def test_checking_angles_read_back_off_the_designed_lift(designed):
    section, outcome, _ = designed
    theta = np.arange(-180.0, 180.0, 0.001)
    lift = outcome.law.evaluate(theta * DEG).lift / MM
    closing = section.get("closing_angles", section["opening_angles"])
    for h, a_open, a_close in zip(section["checking_heights"], section["opening_angles"],
                                  closing, strict=True):
        above = np.nonzero(lift >= h)[0]
        assert -theta[above[0]] == pytest.approx(a_open, abs=0.002)
        assert theta[above[-1]] == pytest.approx(a_close, abs=0.002)


@pytest.mark.derived
def test_lift_continuous_to_the_jerk_at_every_knot(designed):
    """A quintic B-spline is C4 across simple knots (de Boor 2001, ch. IX) and meets the base
    circle with zero lift, velocity, acceleration and jerk: the one-sided limits 1e-7 deg either
    side of every joint differ by no more than the derivative of next order times the gap."""
    _, outcome, _ = designed
    law = outcome.law
    curve = law.evaluate(np.linspace(-np.pi, np.pi, 20001))
    scale = [np.abs(getattr(curve, k)).max() for k in ("lift", "d1", "d2", "d3")]
    eps = 1e-7 * DEG
    for angle, _label in law.joints():
        left, right = law.evaluate(np.array([angle - eps])), law.evaluate(np.array([angle + eps]))
        for k, name in enumerate(("lift", "d1", "d2", "d3")):
            jump = abs(getattr(right, name)[0] - getattr(left, name)[0])
            assert jump <= 1e-6 * scale[k], (angle / DEG, name, jump)
    # the fourth derivative is continuous too inside the event (C4): d3 has no kink at a knot
    inner = [a for a, label in law.joints() if label.startswith("knot")]
    h = 1e-4 * DEG
    for angle in inner:
        d3 = law.evaluate(np.array([angle - 2 * h, angle - h, angle, angle + h, angle + 2 * h])).d3
        left, right = (d3[2] - d3[0]) / (2 * h), (d3[4] - d3[2]) / (2 * h)
        assert abs(right - left) <= 1e-3 * scale[3] / DEG


def test_designed_deck_runs_as_an_ordinary_deck(designed):
    _, outcome, out = designed
    written = out / "designed.toml"
    deck = ct.load(written)
    assert deck.model.lift.form == "spline"
    law = build_lift_law(deck.model.lift)
    theta = np.linspace(-np.pi, np.pi, 721)
    assert np.allclose(law.evaluate(theta).lift, outcome.law.evaluate(theta).lift,
                       rtol=0, atol=1e-12)
    result = ct.run(deck)
    assert result.metrics["max_lift"].value == pytest.approx(outcome.events.max_lift * MM,
                                                             abs=1e-9)
    assert (out / "design.md").read_text(encoding="utf-8").count("| met") == len(outcome.items)


def test_crank_basis_halves_the_angles(tmp_path):
    cam = {"max_lift": 8.0, "checking_heights": [1.0], "opening_angles": [50.0],
           "ramp_height": 0.3, "ramp_velocity": 0.015, "symmetric": True}
    crank = dict(cam, angle_basis="crank", opening_angles=[100.0], ramp_velocity=0.0075)
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    a = ct.design(_deck_with(tmp_path / "a", "harrison_flat.toml", cam))
    b = ct.design(_deck_with(tmp_path / "b", "harrison_flat.toml", crank))
    assert np.allclose(a.law.knots, b.law.knots) and np.allclose(a.law.coefficients,
                                                                 b.law.coefficients)


def _cli(*args, cwd=ROOT):
    return subprocess.run([sys.executable, "-m", "camtrain.cli", *map(str, args)],
                          capture_output=True, text=True, cwd=cwd)


def test_impossible_events_exit_3_and_write_nothing(tmp_path):
    # 9 mm of lift within 10 deg of the nose under a gentle deceleration limit
    section = {"max_lift": 9.0, "checking_heights": [1.0], "opening_angles": [10.0],
               "max_deceleration": 0.001, "symmetric": True}
    path = _deck_with(tmp_path, "harrison_flat.toml", section)
    run = _cli("design", path, "--out", tmp_path / "out")
    assert run.returncode == 3, run.stderr
    assert "error:" in run.stderr and "Traceback" not in run.stderr
    assert not (tmp_path / "out").exists()


def test_deck_without_design_section_exits_2(tmp_path):
    run = _cli("design", DECKS / "harrison_flat.toml", "--out", tmp_path / "out")
    assert run.returncode == 2
    assert "design" in run.stderr and "Traceback" not in run.stderr


def test_bad_design_field_names_it(tmp_path):
    section = {"max_lift": 9.0, "checking_heights": [1.0, 2.0], "opening_angles": [50.0]}
    run = _cli("design", _deck_with(tmp_path, "harrison_flat.toml", section))
    assert run.returncode == 2
    assert "design.opening_angles" in run.stderr and "Traceback" not in run.stderr


def test_cli_design_writes_the_deck_and_report(tmp_path):
    section = {"max_lift": 8.0, "checking_heights": [1.0], "opening_angles": [50.0],
               "ramp_height": 0.3, "ramp_velocity": 0.015, "symmetric": True}
    path = _deck_with(tmp_path, "harrison_flat.toml", section)
    run = _cli("design", path, "--out", tmp_path / "out", "--quiet")
    assert run.returncode == 0, run.stderr
    for name in ("designed.toml", "design.md", "design.csv", "design.png"):
        assert (tmp_path / "out" / name).is_file(), name
    assert ct.load(tmp_path / "out" / "designed.toml").model.lift.form == "spline"
