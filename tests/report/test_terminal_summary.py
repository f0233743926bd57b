"""What a run prints comes from what the effects declare (key metrics, summary tables), the
report is headed by its deck kind, and the progress bar names the effect that runs and is gone
before the deck's report is printed."""
from __future__ import annotations

import importlib
import io
from contextlib import contextmanager

from click.testing import CliRunner

from camtrain import api
from camtrain.catalogue import KINDS
from camtrain.report.console import PlainOut, key_metric_names, print_run, summary_tables
from camtrain.report.text import report_text
from camtrain.study.dynamics_speed import render
from tests.conftest import DECKS


def test_every_declared_summary_is_a_function():
    for kind in KINDS.values():
        for spec in kind.effects:
            if spec.summary:
                module, function = spec.summary.split(":")
                assert callable(getattr(importlib.import_module(module), function)), spec.name


def test_every_kind_has_its_own_heading():
    titles = {k.name: k.title for k in KINDS.values()}
    assert titles["valve_train"] == "CAM OPERATING CHARACTERISTICS"
    assert len(set(titles.values())) == len(titles)


def _printed(result, deck) -> str:
    stream = io.StringIO()
    print_run(PlainOut(stream, width=100), result, [], None, None, deck)
    return stream.getvalue()


def test_bearing_deck_prints_its_orbit_and_heading():
    loaded = api.load(DECKS / "bearing_ocvirk_check.toml")
    result = api.run(loaded)
    out = _printed(result, loaded.model)
    assert key_metric_names(result)[0] == "min_film"
    assert "min_film" in out and "µm" in out
    text = report_text(result, loaded.model)
    assert "JOURNAL BEARING" in text.splitlines()[1]
    assert "CAM OPERATING" not in text


def test_camshaft_deck_prints_every_bearing_orbit():
    loaded = api.load(DECKS / "pinto_camshaft.toml")
    result = api.run(loaded)
    tables = summary_tables(result, loaded.model)
    assert [t.title.split(" (")[0] for t in tables] == ["camshaft bearings"]
    rows = {row[0][0]: row for row in tables[0].rows}
    assert set(rows) == {"bearing 1", "bearing 2", "bearing 3"}
    film = result.metrics["bearing_2_min_film"]
    assert rows["bearing 2"][1][0] == f"{film.value * 1e6:.3f}"
    assert rows["bearing 2"][2][0] == f"{film.angle * 57.29577951308232:.1f}"
    out = _printed(result, loaded.model)
    assert "camshaft bearings" in out and "power_loss_mean" in out


class _Bar:
    """A stand-in for the rich progress bar: it records what it is told."""

    def __init__(self, log):
        self.log, self.console = log, self

    def add_task(self, description, total=None):
        self.log.append(("task", description))
        return 1

    def update(self, task, description, completed, total):
        self.log.append(("label", description))

    def remove_task(self, task):
        self.log.append(("removed",))

    def print(self, text, **kw):
        self.log.append(("said", text))


def test_progress_names_the_effects_and_is_gone_before_the_report(monkeypatch, tmp_path):
    import camtrain.report.console as console

    log = []

    @contextmanager
    def bar(enabled=True):
        log.append(("open",))
        yield _Bar(log)
        log.append(("closed",))

    real = console.print_run
    monkeypatch.setattr(console, "progress_bar", bar)
    monkeypatch.setattr(console, "print_run",
                        lambda *a, **k: (log.append(("report",)), real(*a, **k)))
    from camtrain.cli import main

    out = CliRunner().invoke(main, ["run", str(DECKS / "harrison_flat.toml"), "--no-plots",
                                    "--out", str(tmp_path / "h")])
    assert out.exit_code == 0, out.output
    labels = [entry[1] for entry in log if entry[0] == "label"]
    assert any("running kinematics" in label for label in labels)
    assert any("running power" in label for label in labels)
    events = [entry[0] for entry in log if entry[0] in ("open", "closed", "report")]
    assert events == ["open", "closed", "report"]


def test_dynamics_speed_says_its_speeds_are_the_camshafts():
    text = render({"deck": "d.toml", "found": True, "speed_of": "camshaft",
                   "separation_speed": 2130.0, "separating_speed": 2134.0,
                   "separation_angle": 40.0, "rtol": 2e-3, "evaluations": [(2000.0, False)],
                   "bounce_speed": 2500.0, "bounce_angle": -30.0})
    assert "camshaft rpm" in text
    assert all("rpm camshaft" in line for line in text.splitlines()[2:4])


def test_a_long_effect_says_what_it_does_now():
    """The crank-bearing effect names each bearing as it marches its orbit; the progress
    callback gets it as "<effect>: <what>" with the effect's place in the plan."""
    seen = []
    api.run(DECKS / "zeta_crank_bearings.toml",
            progress=lambda label, done, total: seen.append((label, done, total)))
    bearings = [(label, done) for label, done, _ in seen if label.startswith("crank_bearings")]
    assert ("crank_bearings: big-end 1 of 4", 1) in bearings
    assert ("crank_bearings: main 5 of 5", 1) in bearings
    assert seen[-1][0] == "done" and seen[-1][1] == seen[-1][2]


def test_bare_engine_deck_prints_each_correlation_by_group():
    loaded = api.load(DECKS / "zeta_bare_engine.toml")
    result = api.run(loaded)
    text = _printed(result, loaded.model)
    assert "friction correlations" in text
    for name, label in (("pnh1989", "PNH 1989"), ("sandoval_heywood2003", "S-H 2003")):
        row = next(line for line in text.splitlines() if label in line)
        fmep = result.component(name).metrics["fmep"].value * 1e-3
        assert f"{fmep:.1f}" in row
        assert f"{result.component(name).metrics['power'].value:.0f}" in row
