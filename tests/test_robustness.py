"""Issue 16, first half: decks `check` accepts never crash `run`; results are never silently wrong.

Each test here failed before its fix (behaviour tier).
"""
from __future__ import annotations

import math
import re

import numpy as np
import pytest
from click.testing import CliRunner

from camtrain.cli import main
from camtrain.deck.templates import render_template
from tests.conftest import DECKS

FLAT = render_template("flat")


def _set(text: str, key: str, value: str) -> str:
    """The deck text with the first ``key = ...`` line's value replaced."""
    new, n = re.subn(rf"(?m)^{re.escape(key)} = .*$", f"{key} = {value}", text, count=1)
    assert n == 1, key
    return new


def _drop(text: str, key: str) -> str:
    new, n = re.subn(rf"(?m)^{re.escape(key)} = .*\n", "", text, count=1)
    assert n == 1, key
    return new


def _run(text: str, tmp_path, *args):
    return CliRunner().invoke(main, ["run", "-", "--no-plots", "--out", str(tmp_path / "o"),
                                     *args], input=text)


# ---------------------------------------------------------------- crashes on decks check accepts

def test_valve_train_without_cam_width_runs_with_the_load_free_film(tmp_path):
    deck = _set(_drop(FLAT, "width"), "angle_points", "120")
    assert CliRunner().invoke(main, ["check", "-", "-q"], input=deck).exit_code == 0
    res = _run(deck, tmp_path)
    assert res.exit_code == 0, res.output
    assert "no cam.width" in res.output and "Blok" in res.output


BEARING = (DECKS / "bearing_ocvirk_check.toml").read_text()


@pytest.mark.parametrize("deck, key, value, field", [
    (FLAT, "base_radius", "1e300", "cam.base_radius"),
    (FLAT, "camshaft", "1e300", "speed.camshaft"),
    (render_template("finger"), "follower_radius", "1e300", "mechanism.follower_radius"),
    (BEARING, "clearance", "1e-300", "bearing.clearance"),
    (BEARING, "length", "1e300", "bearing.length"),
    (BEARING, "length", "-1e-300", "bearing.length"),
])
def test_absurd_magnitudes_are_input_errors_naming_the_field(deck, key, value, field, tmp_path):
    res = _run(_set(deck, key, value), tmp_path)
    assert res.exit_code == 2, res.output
    assert field in res.output and "internal error" not in res.output
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("title", ["Intake [rev B]", "Intake [/x] test", "[bold]x[/bold] [/]"])
def test_user_text_is_never_rich_markup(title, tmp_path):
    deck = _set(_set(FLAT, "title", f'"{title}"'), "angle_points", "120")
    checked = CliRunner().invoke(main, ["check", "-"], input=deck)
    assert checked.exit_code == 0, checked.output
    assert title in checked.output
    assert "[camshaft] section" in checked.output and "[guides] section" in checked.output
    res = _run(deck, tmp_path)
    assert res.exit_code == 0, res.output
    assert title in res.output


# ---------------------------------------------------------------- wrong or silent results

def test_non_finite_metric_is_named_in_a_warning():
    from camtrain.result import Result
    from camtrain.runner import warn_non_finite

    res = Result()
    res.add_metric("film_min_at_max_lift", math.nan, "m", "film at the nose")
    res.add_metric("hertz_max", math.inf, "Pa", "largest Hertz pressure")
    res.add_metric("load_max", 1.0, "N", "largest load")
    warn_non_finite(res)
    assert any("film_min_at_max_lift" in w for w in res.warnings)
    assert any("hertz_max" in w for w in res.warnings)
    assert not any("load_max" in w for w in res.warnings)


def test_limit_check_fails_an_infinite_hertz_stress():
    from camtrain.deck.schema_tribology import Limits
    from camtrain.plan import Plan, Step
    from camtrain.report.limits import evaluate
    from camtrain.result import Result

    res = Result(plan=Plan("auto", (Step("kinematics", True, ""), Step("loads", True, ""),
                                    Step("hertz", True, ""))))
    theta = np.linspace(-np.pi, np.pi, 5)
    res.add_axis("cam_angle", theta, "rad", "cam angle")
    res.add_column("load", np.full(5, 100.0), "N", "contact load")
    res.add_column("hertz_pmax", np.array([1e8, np.inf, 2e8, np.nan, 1e8]), "Pa", "p")
    [check] = evaluate(Limits(max_hertz=650e6), res)
    assert not check.ok and check.value == math.inf


def test_friction_warns_where_an_infinite_hertz_stress_leaves_it_uncomputed(monkeypatch):
    from camtrain import api
    from camtrain.contact.model import CamContact

    original = CamContact.hertz

    def one_infinite(self, kin, load):
        field = original(self, kin, load)
        field.pmax[int(np.nanargmax(field.pmax))] = np.inf
        return field

    monkeypatch.setattr(CamContact, "hertz", one_infinite)
    result = api.run(api.loads(_set(FLAT, "angle_points", "120")))
    assert any("friction_force not computed" in w for w in result.warnings)
    assert any("hertz_pmax is infinite" in w for w in result.warnings)


def test_petroff_ratio_of_a_bush_turning_with_the_journal_is_named_in_a_warning(tmp_path):
    deck = _set(BEARING, "bearing", "1500.0")
    res = _run(deck + '\n', tmp_path, "-q")
    assert res.exit_code == 0, res.output
    import json
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["metrics"]["petroff_ratio"]["value"] is None
    assert any("petroff_ratio" in w for w in summary["warnings"])


# ---------------------------------------------------------------- interrupts and atomic outputs

def _swallowed_ctrl_c(*args, **kwargs):
    """A Ctrl-C arriving where something swallows it (a finalizer, a callback)."""
    import signal

    try:
        signal.raise_signal(signal.SIGINT)
    except BaseException:  # noqa: BLE001 - what matplotlib/PIL clean-up code does to it
        pass
    return []


def test_ctrl_c_swallowed_while_plotting_still_interrupts_run(monkeypatch, tmp_path):
    import camtrain.report.sheets as sheets

    monkeypatch.setattr(sheets, "write_plots", _swallowed_ctrl_c)
    deck = _set(FLAT, "angle_points", "120")
    res = CliRunner().invoke(main, ["run", "-", "--out", str(tmp_path / "o")], input=deck)
    assert res.exit_code == 130, res.output
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("plot", ["interrupt", "swallowed"])
def test_interrupted_lift_leaves_no_lift_csv_without_plots(monkeypatch, tmp_path, plot):
    import camtrain.report.plots as plots

    def interrupt(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(plots, "lift_sheet", interrupt if plot == "interrupt" else _swallowed_ctrl_c)
    res = CliRunner().invoke(main, ["lift", "-", "--out", str(tmp_path / "o")], input=FLAT)
    assert res.exit_code == 130, res.output
    assert not (tmp_path / "o").exists()
    assert not list(tmp_path.iterdir())   # no staging directory left either


def test_lift_writes_its_table_and_plots_together(tmp_path):
    res = CliRunner().invoke(main, ["lift", "-", "--out", str(tmp_path / "o"), "-q"], input=FLAT)
    assert res.exit_code == 0, res.output
    assert {p.name for p in (tmp_path / "o").iterdir()} >= {"lift.csv", "lift.png"}


# ---------------------------------------------------------------- messages in the deck's words

@pytest.mark.parametrize("method, code, fields", [
    ("steady", 2, ("speed.journal, speed.bearing:", "the mean of speed.journal and speed.bearing")),
    ("mobility", 4, ("solver.period_tolerance", "solver.max_cycles")),
])
def test_bearing_solver_errors_name_deck_fields_not_symbols(method, code, fields, tmp_path):
    # a bush turning against the journal: half-speed whirl, the film carries no steady load
    deck = _set(_set(BEARING, "bearing", "-1500.0"), "method", f'"{method}"')
    res = _run(deck, tmp_path, "-q")
    assert res.exit_code == code, res.output
    for text in fields:
        assert text in res.output
    assert not re.search(r"\bomega\b|period_tol\b|\bmax_cycles\b(?! or)", res.output.replace(
        "solver.max_cycles", ""))
    assert not (tmp_path / "o").exists()


def test_a_bearing_march_reaches_a_period_tolerance_below_its_step_error(tmp_path):
    """Tolerances below the march's own error used to march all 1000 cycles (20-37 s), then
    stopped when the change stopped falling. The free-step march replays a settled cycle's
    steps, so the cycle-to-cycle change falls to round-off and 1e-11 is reached in a few
    cycles."""
    from camtrain import api

    deck = _set(BEARING, "load_y", "[-500.0, 500.0, -500.0, 500.0]")
    deck += "max_cycles = 1000\nperiod_tolerance = 1e-11\nstep_tolerance = 1e-11\n"
    res = api.run(api.loads(deck))
    assert not res.warnings
    assert res.metrics["cycles"].value < 20
    assert res.metrics["periodicity_error"].value <= 1e-11


def test_a_bearing_march_that_cannot_reach_its_period_tolerance_stops_early():
    """The march that ends a step on every load angle (``steps="grid"``) places its steps
    afresh each cycle, so its change sits at the step error: below that the march stops when
    the change stops falling (it used to march all max_cycles) and says which tolerance to
    raise. The deck above at 1500 rpm: the change stalls at 1.7e-10 after 19 cycles."""
    import math

    import numpy as np

    from camtrain.bearings import JournalBearing, bearing_orbit
    from camtrain.errors import ConvergenceError

    th = np.arange(4) * (math.pi / 2)
    with pytest.raises(ConvergenceError, match="stopped falling") as err:
        bearing_orbit(JournalBearing(25e-3, 18e-3, 25e-6, 0.01), np.zeros(4),
                      np.array([-500.0, 500.0, -500.0, 500.0]), th, 1500 * math.pi / 30, tol=1e-11,
                      period_tol=1e-11, max_cycles=1000, steps="grid")
    cycles = int(re.search(r"after (\d+) cycles", str(err.value)).group(1))
    assert cycles < 100 and "raise period_tol" in str(err.value)


# ---------------------------------------------------------------- a fresh machine

def test_license_is_an_spdx_expression_that_setuptools_reads_without_deprecation():
    import tomllib

    from tests.conftest import ROOT

    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert meta["project"]["license"] == "MIT"          # a table here is deprecated (PEP 639)
    assert "setuptools>=77" in meta["build-system"]["requires"]


def test_oldest_pins_cover_every_dependency_and_test_extra():
    import tomllib

    from scripts.oldest_pins import pins
    from tests.conftest import ROOT

    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    pinned = dict(p.split("==") for p in pins(ROOT / "pyproject.toml"))
    declared = project["dependencies"] + project["optional-dependencies"]["test"]
    for req in declared:
        name, _, version = req.partition(">=")
        assert pinned[name.split("[")[0]] == version, req
