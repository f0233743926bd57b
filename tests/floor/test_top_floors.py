"""The top floors learn each physics from the plan, not from column names.

report/, study/, api.py and cli*.py decide which sheet, panel, table, knob or study to make
from what the effects that ran declare in the catalogue (EffectSpec.sheets, panels, knobs,
key_metrics, accuracy_metrics, summary), never by testing whether a column or metric name is
in a result. The test reads the source for a membership test on ``.columns`` or ``.metrics``
(``"x" in result.columns``, ``n not in r["metrics"]``); those left are of two kinds that pick
nothing (CURVES_AND_ROWS: the optional curves or rows of something the plan chose;
USER_NAMES: a name the user gave, checked against the run), each file with its reason below.
A new one fails here: declare the need in the catalogue instead.

The second test compares what the declarations give for every shipped deck (from the plan and
metric names in its golden file) with the fixture the column-name code wrote before
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

#: Two kinds of membership test are not dispatch, and only these are left. A sheet, table,
#: knob or study is picked from the plan (EffectSpec.sheets, panels, knobs, key_metrics,
#: accuracy_metrics, summary); the panels of a cycle sheet from EffectSpec.panels.
#:
#: CURVES_AND_ROWS: inside a sheet, panel or table that the plan already chose, which of its
#: optional curves or rows the run has: a column an effect writes only for some deck options
#: (a rocker's valve lift, a flat follower's eccentricity, the transient film's steady
#: reference) or a component that carries a table's metric. Nothing is picked by it.
CURVES_AND_ROWS: dict[str, tuple[int, str]] = {
    "camtrain/report/panels.py": (9, "a declared panel draws the curves the run has (the "
                                 "kinematics of a rocker or a flat follower, the averaged "
                                 "Reynolds film's own film beside the transient film), and "
                                 "gives its axes back when it has none"),
    "camtrain/report/panels_ehl.py": (1, "the declared film map of the elastic film, which "
                                      "writes no map when no angle of its march was loaded"),
    "camtrain/report/bearing_plots.py": (3, "which components of a declared orbit sheet have "
                                         "an orbit, and which extremes of a grooved bearing"),
    "camtrain/report/engine_plots.py": (1, "which bearings of the declared load sheet have a "
                                        "load diagram"),
    "camtrain/report/piston_plots.py": (2, "how many rings and which curves the declared "
                                        "piston sheet holds"),
    "camtrain/report/summaries.py": (4, "which components and parts a declared summary table "
                                     "has rows for"),
    "camtrain/report/engine_report.py": (1, "the header rows of an engine deck: the bearings "
                                         "with a Petroff power"),
    "camtrain/report/text.py": (1, "the optional columns of the declared per-angle table of "
                                "report.txt (a lift-only run has no load)"),
    "camtrain/report/console.py": (1, "the key results the plan's effects declare, of those "
                                   "the run produced"),
    "camtrain/study/sweep_output.py": (3, "a cell of a metric column of the sweep table or "
                                       "a point of its plots, none for a failed case"),
    "camtrain/study/optimize.py": (1, "the rows of the gain table: the powers of the datum "
                                   "that the optimum also has"),
    "camtrain/study/executors.py": (1, "the overlay curves a kept case has (a no-load case "
                                    "has no film)"),
}

#: USER_NAMES: a column or metric the user named (a design limit in the deck, a metric or
#: curve on the command line, a quantity in a fit's data file) is looked up to check that the
#: run has it: validation of the user's input, not a choice of what to compute or draw.
USER_NAMES: dict[str, tuple[int, str]] = {
    "camtrain/report/limits.py": (2, "a design limit names its own column or metric in the "
                                  "deck: the check reads what the user named"),
    "camtrain/study/fit_model.py": (4, "a fit reads the quantities its data file names"),
    "camtrain/study/sensitivity_analysis.py": (2, "the metric the user named, in the cases "
                                               "that produced it"),
    "camtrain/study/trends.py": (2, "the trend of the metric the user named, over the cases "
                                 "that produced it"),
}

#: file -> (number of membership tests left, why none of them picks a sheet, table, knob or
#: study)
ALLOWED: dict[str, tuple[int, str]] = {**CURVES_AND_ROWS, **USER_NAMES}


def test_every_file_left_is_of_one_kind_with_its_reason():
    assert not set(CURVES_AND_ROWS) & set(USER_NAMES)
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
