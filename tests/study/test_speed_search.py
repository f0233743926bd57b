"""One speed search and one report for the separation speed and the adjuster's pump-up
(camtrain/study/speed_search.py): `camtrain dynamics-speed` and `--pump-up` print the text the
two separate reports printed before they shared it, and a search without a bracket says what
did or did not happen in the finding's own words."""
from __future__ import annotations

import json
from types import SimpleNamespace

import pytest
from click.testing import CliRunner

from tests.conftest import DECKS


def _separation_before(report: dict) -> str:
    """The separation report as camtrain/study/dynamics_speed.py rendered it before the shared
    renderer (kept here, line for line, as the reference)."""
    lines = [f"deck: {report['deck']}",
             "speeds are camshaft rpm (a four-stroke engine turns at twice that); angles are "
             "cam deg from maximum lift"]
    if report["bounce_speed"] is not None:
        lines.append(f"rigid train, closed-form bounce speed: {report['bounce_speed']:.1f} rpm "
                     f"camshaft (contact lost first at {report['bounce_angle']:.1f} deg cam)")
    if not report["found"]:
        lines.append(f"elastic train: {report['message']}")
        return "\n".join(lines)
    lines.append(f"elastic train keeps contact up to {report['separation_speed']:.1f} rpm "
                 f"camshaft; separates at {report['separating_speed']:.1f} rpm camshaft (first "
                 f"loss at {report['separation_angle']:.2f} deg cam); bracket "
                 f"{100 * report['rtol']:g} %")
    lines.append("camshaft speeds tried (rpm, separated): " + ", ".join(
        f"{w:.0f} {'yes' if s else 'no'}" for w, s in report["evaluations"]))
    return "\n".join(lines)


def _pump_up_before(r: dict) -> str:
    """The pump-up report as camtrain/study/lash_adjuster.py rendered it before."""
    lines = [f"deck: {r['deck']}", "speeds are camshaft rpm (a four-stroke engine turns at "
             "twice that)"]
    if not r["found"]:
        lines.append(f"lash adjuster: {r['message']}")
        return "\n".join(lines)
    lines.append(f"lash adjuster holds the valve shut on the base circle up to "
                 f"{r['pump_up_free_speed']:.1f} rpm camshaft; pumps up at "
                 f"{r['pump_up_speed']:.1f} rpm (valve held {r['held_open_mm']:.3g} mm open); "
                 f"bracket {100 * r['rtol']:g} %")
    lines.append("camshaft speeds tried (rpm, pumped up): " + ", ".join(
        f"{w:.0f} {'yes' if p else 'no'}" for w, p in r["evaluations"]))
    return "\n".join(lines)


#: The keys, in order, of each report's JSON before the shared search.
KEYS_BEFORE = {
    "separation": ["deck", "found", "speed_of", "separation_speed", "separating_speed",
                   "separation_angle", "evaluations", "rtol", "bounce_speed", "bounce_angle"],
    "pump-up": ["deck", "found", "speed_of", "pump_up_free_speed", "pump_up_speed",
                "held_open_mm", "evaluations", "rtol"]}


def _command(*args: str) -> str:
    from camtrain.cli import main

    out = CliRunner().invoke(main, ["dynamics-speed", *args])
    assert out.exit_code == 0, out.output
    return out.stdout


@pytest.mark.parametrize(("finding", "deck", "before"), [
    ("separation", "zeta_intake_dynamics.toml", _separation_before),
    ("pump-up", "zeta_intake_hla.toml", _pump_up_before)])
def test_the_command_prints_what_each_report_printed_before(finding, deck, before):
    """A coarse bracket from near the threshold (a few marches): the JSON has the keys it had,
    in their order, and the text is the former renderer's of that JSON."""
    args = [str(DECKS / deck), "--tolerance", "0.05", "--start", "1950",
            *(["--pump-up"] if finding == "pump-up" else [])]
    report = json.loads(_command(*args, "--json"))
    assert list(report) == KEYS_BEFORE[finding]
    assert report["found"] and len(report["evaluations"]) >= 3
    assert any(crossed for _, crossed in report["evaluations"])
    assert _command(*args) == before(report) + "\n"


def _no_bracket(finding, crossed: bool) -> dict:
    from camtrain.study.speed_search import search_speed

    deck = SimpleNamespace(speed=SimpleNamespace(omega=150.0))
    return search_speed("d.toml", deck, finding, lambda omega: (crossed, None), rtol=2e-3,
                        start_rpm=None)


def test_a_search_without_a_bracket_words_the_separation_as_before():
    from camtrain.study.dynamics_speed import SEPARATION, render

    for crossed, said in ((True, "the train separates at every speed tried"),
                          (False, "the train never separates at the speeds tried")):
        report = {**_no_bracket(SEPARATION, crossed), "bounce_speed": 2500.0,
                  "bounce_angle": -30.0}
        assert report["message"] == f"no separation threshold found: {said}"
        assert render(report) == _separation_before(report)


def test_a_search_without_a_bracket_says_the_adjuster_pumps_up():
    """Before, the pump-up message was the separation's with words replaced, and read "the
    train pumps up": it is the adjuster that pumps up."""
    from camtrain.study.lash_adjuster import PUMP_UP, render_pump_up

    for crossed, said in ((True, "the adjuster pumps up at every speed tried"),
                          (False, "the adjuster never pumps up at the speeds tried")):
        report = _no_bracket(PUMP_UP, crossed)
        assert report["message"] == f"no pump-up threshold found: {said}"
        assert render_pump_up(report) == _pump_up_before(report)
        assert render_pump_up(report).splitlines()[-1] == f"lash adjuster: {report['message']}"


def test_a_bracket_without_a_place_leaves_the_place_out():
    """A search whose upper end returned nothing (angle None) prints the bracket without the
    parenthesis (the renderers before failed on formatting None)."""
    from camtrain.study.lash_adjuster import PUMP_UP, render_pump_up
    from camtrain.study.speed_search import search_speed

    deck = SimpleNamespace(speed=SimpleNamespace(omega=150.0))
    report = search_speed("d.toml", deck, PUMP_UP, lambda omega: (omega > 200.0, None),
                          rtol=0.05, start_rpm=None)
    assert report["found"] and report["held_open_mm"] is None
    line = render_pump_up(report).splitlines()[2]
    assert "pumps up at" in line and "held" not in line and line.endswith("bracket 5 %")
