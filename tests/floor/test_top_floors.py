"""The top floors learn each physics from the plan, not from column names.

report/, study/, api.py and cli*.py decide which sheet, panel, table, knob or study to make
from what the effects that ran declare in the catalogue (EffectSpec.sheets, panels, knobs,
key_metrics, accuracy_metrics, summary), and which optional curves and rows it holds from the
optional columns and components they declare (EffectSpec.optional_columns, recorded per deck
in Step.makes; EffectSpec.components), never by testing whether a column or metric name is in
a result. A name the user gave (a fit's data file, a study's --metric) is checked by one
function, Result.column / Result.metric. The test reads the source for a membership test on
``.columns`` or ``.metrics`` (``"x" in result.columns``, ``n not in r["metrics"]``); the few
left test what the run found, not what the deck asked (FOUND_BY_THE_RUN), each file with its
reason below. A new one fails here: declare the need in the catalogue instead.

The other tests hold each step's record of its optional columns to what its effect wrote for
every shipped deck, and compare what the declarations give for every shipped deck (from the
plan and metric names in its golden file) with the fixture the column-name code wrote before
(tests/report/declarations.py regenerates it)."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "camtrain"
GOLDEN = ROOT / "tests" / "golden" / "data"
FIXTURE = ROOT / "tests" / "report" / "data" / "declarations.json"

#: ``in``/``not in`` followed by an expression ending in .columns or .metrics (or ["metrics"])
MEMBERSHIP = re.compile(r"""\bin\s+[\w.()]*(\.(columns|metrics)|\[["'](columns|metrics)["']\])"""
                        r"""(?!\s*\.|\w|\[|\()""")

FOR_IN = re.compile(r"\bfor\s+[\w\s,()*]+?\s+in\b")

#: The membership tests left: what the run found, which no deck option and no declaration can
#: say before it runs. Nothing is picked by them: a sheet, table, knob or study is picked from
#: the plan (EffectSpec.sheets, panels, model_panels, knobs, key_metrics, accuracy_metrics,
#: summary), the optional curves and rows of one from the declared optional columns and
#: components. file -> (number left, why)
FOUND_BY_THE_RUN: dict[str, tuple[int, str]] = {
    "camtrain/report/findings.py": (1, "whether the film has a central thickness (the film "
                                    "panel's second curve, a column of report.txt's table): "
                                    "without cam.width the contact's geometry, known once the "
                                    "kinematics ran, decides between the Blok film (none) "
                                    "and a point contact's EHL film"),
    "camtrain/report/panels_ehl.py": (1, "the declared film map of the elastic film, which "
                                      "writes no map when no angle of its march was loaded"),
    "camtrain/report/summaries.py": (1, "the camshaft bearings with an orbit in the declared "
                                     "bearing table: none for one whose orbit did not "
                                     "converge (warned) or of method petroff"),
    "camtrain/report/bearing_plots.py": (1, "which of the declared bearings of an orbit "
                                         "sheet have an orbit: a camshaft bearing whose orbit "
                                         "did not converge is warned, not drawn, and a "
                                         "partially grooved main has its two extremes"),
    "camtrain/report/console.py": (1, "the key results the plan's effects declare, of those "
                                   "the run stated: a separation angle or a seat-impact speed "
                                   "only when the train separated or the valve landed"),
}

#: file -> (number of membership tests left, why none of them picks a sheet, table, knob or
#: study)
ALLOWED: dict[str, tuple[int, str]] = FOUND_BY_THE_RUN


def test_every_file_left_has_its_reason():
    assert all(count > 0 and len(why) > 20 for count, why in ALLOWED.values())
    # the modules that pick sheets, tables, knobs and studies have none left
    for picker in ("camtrain/report/sheets.py", "camtrain/report/outputs.py",
                   "camtrain/report/profile.py", "camtrain/study/accuracy.py",
                   "camtrain/study/accuracy_knobs.py", "camtrain/api.py"):
        assert picker not in ALLOWED


def top_floor_files() -> list[Path]:
    files = [*sorted((PACKAGE / "report").rglob("*.py")), *sorted((PACKAGE / "study").rglob("*.py")),
             PACKAGE / "api.py", *sorted(PACKAGE.glob("cli*.py"))]
    return [f for f in files if f.exists()]


def membership_tests(path: Path) -> list[str]:
    out = []
    for number, line in enumerate(path.read_text().splitlines(), 1):
        code = FOR_IN.sub("for _ of", line.split("#", 1)[0])   # iteration is no test
        if MEMBERSHIP.search(code):
            out.append(f"{number}: {line.strip()}")
    return out


def test_no_membership_test_on_column_or_metric_names():
    found = {}
    for path in top_floor_files():
        hits = membership_tests(path)
        rel = path.relative_to(ROOT).as_posix()
        allowed = ALLOWED.get(rel, (0, ""))[0]
        if len(hits) != allowed:
            found[rel] = hits
    assert found == {}, ("membership tests on column or metric names (declare the need in "
                         "the catalogue, or give the reason in ALLOWED): "
                         + json.dumps(found, indent=1))


def _shipped_with_golden() -> list[str]:
    return sorted(p.stem for p in GOLDEN.glob("*.json") if "+" not in p.stem)


@pytest.mark.parametrize("name", _shipped_with_golden())
def test_each_step_makes_the_optional_columns_its_effect_writes(name):
    """The plan's record of the optional columns (Step.makes, from the effect module's
    ``makes(deck, planned)``) is what the effect wrote for every shipped deck: the sheets that
    ask the plan draw the curves of before."""
    from camtrain import api
    from camtrain.catalogue import _named
    from camtrain.scene import resolve

    golden = json.loads((GOLDEN / f"{name}.json").read_text())
    plan = resolve(api.load(ROOT / "decks" / f"{name}.toml").model)
    for step in (s for s in plan.steps if s.chosen):
        for declared in step.spec.optional_columns:
            written = {c for c in golden["columns"] if _named(c, declared)}
            assert {c for c in step.makes if _named(c, declared)} == written, step.effect


def test_the_plan_is_asked_only_for_declared_optional_columns():
    from camtrain.catalogue import makes
    from camtrain.plan import Plan, Step

    plan = Plan("auto", (Step("kinematics", True, ""),
                         Step("loads", True, "", makes=("valve_force",))))
    assert makes(plan, "valve_force") and not makes(None, "valve_force")
    assert not makes(plan, "spring_force_retainer")
    with pytest.raises(ValueError, match="not an optional column"):
        makes(plan, "film_min")
    engine = Plan("auto", (Step("piston", True, "", makes=("inter_ring_pressure_1",)),),
                  kind="engine")
    assert makes(engine, "inter_ring_pressure_1") and not makes(engine, "inter_ring_pressure_2")


def test_a_name_the_user_gave_is_checked_by_one_function():
    """Result.column / Result.metric: the deck-input error (exit 2) names the option, the
    name and what the run has."""
    import numpy as np

    from camtrain.errors import EXIT_INVALID_INPUT, InputError
    from camtrain.result import Result

    r = Result()
    r.add_axis("cam_angle", np.linspace(-1.0, 1.0, 5), "rad", "cam angle")
    r.add_column("film_min", np.ones(5), "m", "film")
    r.add_axis("time", np.linspace(0.0, 1.0, 3), "s", "time")
    r.add_metric("load_max", 1.0, "N", "largest load")
    assert r.column("film_min", field="--data", axis="cam_angle").unit == "m"
    assert r.metric("load_max", field="--metric").value == 1.0
    with pytest.raises(InputError) as bad:
        r.column("film_min", field="--data", axis="time")
    assert bad.value.exit_code == EXIT_INVALID_INPUT
    assert bad.value.problems[0].render() == ("--data: film_min is not a column on the time "
                                              "axis of this run (got 'film_min'); expected "
                                              "one of time")
    with pytest.raises(InputError, match="--metric: nothing is not a metric of this run "
                                         r"\(got 'nothing'\); expected one of load_max"):
        r.metric("nothing", field="--metric")


def test_the_pattern_finds_what_it_is_for():
    assert MEMBERSHIP.search('if "crank_angle" not in result.columns:')
    assert MEMBERSHIP.search('found = [m for m in names if m in r["metrics"]]')
    assert MEMBERSHIP.search('names = [c for c in names if "min_film" in part.metrics]')
    assert not MEMBERSHIP.search("for name, m in result.metrics.items():")
    assert not MEMBERSHIP.search(FOR_IN.sub("for _ of", "for name in r.columns:"))
    assert not MEMBERSHIP.search("columns += [k for k in row if k not in columns]")


#: deck -> {field: value} where the declarations give better than the column-name code did,
#: with the reason
BETTER = {
    # a bare engine deck runs the correlations alone: the crank-train and crank-bearing knobs
    # were offered for every engine deck, although none of them changes its numbers
    "zeta_bare_engine": {"knobs": []},
}


def _fixture() -> dict:
    return json.loads(FIXTURE.read_text())


@pytest.mark.parametrize("name", sorted(_fixture()))
def test_declarations_give_the_knobs_metrics_and_results_of_before(name):
    from tests.report.declarations import from_golden

    want = {**_fixture()[name], **BETTER.get(name, {})}
    got = from_golden(name)
    assert {k: got[k] for k in got} == {k: want[k] for k in got}


@pytest.mark.parametrize("name", sorted(_fixture()))
def test_every_sheet_written_before_is_declared_by_an_effect_of_the_plan(name):
    """Each sheet the column-name code wrote is declared by an effect that ran (the sheets
    written now are compared with the fixture in tests/report/test_every_deck.py)."""
    import tomllib

    from camtrain.catalogue import declared_effects
    from tests.report.declarations import StoredPlan

    want = _fixture()[name]
    kind = tomllib.loads((ROOT / "decks" / f"{name}.toml").read_text()).get("kind",
                                                                             "valve_train")
    declared = {s for spec in declared_effects(StoredPlan(kind, want["plan"]))
                for s in spec.sheets}
    written = {s.removeprefix("sheet_") for s in want["sheets"] if s.startswith("sheet_")}
    if any(s.startswith("orbit_") for s in want["sheets"]):
        written.add("orbits")
    assert written <= declared
