"""The film model of a bearing as a deck option (model / bearing_model = short | finite | auto):
parsing and bad values, the plan's reason, the finite orbit through the deck, auto per b/d, the
short model's warning and the accuracy knobs."""
from __future__ import annotations

import tomllib

import numpy as np
import pytest
from click.testing import CliRunner

import camtrain.api as ct
from camtrain.bearings import JournalBearing, bearing_orbit
from camtrain.bearings.finite_map import bearing_mobility_map
from camtrain.cli import main
from camtrain.deck.load import validate
from camtrain.study import accuracy as acc
from tests.conftest import DECKS

OCVIRK = DECKS / "bearing_ocvirk_check.toml"
ZETA = DECKS / "zeta_intake_camshaft.toml"
SHORT_LINE = 'model = "short"'


@pytest.fixture(autouse=True, scope="module")
def _private_cache(tmp_path_factory):
    mp = pytest.MonkeyPatch()
    mp.setenv("CAMTRAIN_CACHE", str(tmp_path_factory.mktemp("maps")))
    yield
    mp.undo()


def ocvirk_text(model: str | None, **solver) -> str:
    """The Ocvirk check deck with another film model (None: the line removed, i.e. the default)
    and extra [solver] fields."""
    text = OCVIRK.read_text()
    line = next(ln for ln in text.splitlines() if ln.startswith(SHORT_LINE))
    new = "" if model is None else f'model = "{model}"'
    new += "".join(f"\n{k} = {v!r}".replace("'", '"') for k, v in solver.items())
    return text.replace(line, new)


def reason(text: str, effect: str) -> str:
    return next(s.reason for s in ct.plan(ct.loads(text)).steps if s.effect == effect)


# ------------------------------------------------------------------ the option in the deck

def test_option_parsed_with_auto_as_the_default():
    assert ct.loads(ocvirk_text(None)).model.solver.model == "auto"
    sol = ct.loads(ocvirk_text("finite", cavitation="half_sommerfeld", n_theta=96,
                               n_z=8)).model.solver
    assert (sol.model, sol.cavitation, sol.n_theta, sol.n_z) == ("finite", "half_sommerfeld",
                                                                 96, 8)
    cs = ct.load(ZETA).model.camshaft
    assert (cs.bearing_model, cs.bearing_n_theta, cs.bearing_n_z) == ("short", 72, 6)


@pytest.mark.parametrize("deck,old,new,name", [
    (OCVIRK, 'model = "short"', 'model = "long"', "solver.model"),
    (OCVIRK, 'model = "short"', 'model = "short"\ncavitation = "jfo"', "solver.cavitation"),
    (OCVIRK, 'model = "short"', 'model = "finite"\nn_theta = 8', "solver.n_theta"),
    (OCVIRK, 'model = "short"', 'model = "finite"\nn_z = 1.5', "solver.n_z"),
    (ZETA, 'bearing_model = "short"', 'bearing_model = "finit"', "camshaft.bearing_model"),
])
def test_bad_film_model_exit_2_names_the_field(tmp_path, deck, old, new, name):
    bad = tmp_path / "bad.toml"
    bad.write_text(deck.read_text().replace(old, new, 1))
    for command in ("check", "run"):
        res = CliRunner().invoke(main, [command, str(bad)])
        assert res.exit_code == 2, res.output
        assert name in res.output and "Traceback" not in res.output


def test_template_shows_the_option_with_its_explanation():
    from camtrain.deck.templates import render_template

    bearing = render_template("journal_bearing")
    assert 'model = "short"' in bearing and "Film model: short (Ocvirk" in bearing
    assert "n_theta = 72" in bearing and "cavitation = " in bearing
    flat = render_template("flat")  # the [camshaft] section is commented, default shown
    assert '# bearing_model = "auto"' in flat and "Film model: short (Ocvirk" in flat


# ------------------------------------------------------------------ plan

def test_plan_names_the_model_and_why():
    shipped = reason(OCVIRK.read_text(), "journal_bearing")
    assert "short bearing (Ocvirk) as the deck asks; land b/d = 0.72" in shipped
    # the explicit short model at b/d 0.72 is optimistic: the warning states by how much
    assert "warning" in shipped and "x1.32 at 0.1" in shipped and "x2.42 at 0.01" in shipped
    assert "about x1.5 at the largest load (steady S = 0.056)" in shipped
    auto = reason(ocvirk_text(None), "journal_bearing")
    assert "auto: land b/d = 0.72 > 0.05" in auto and "mesh 72 x 6" in auto
    assert "warning" not in auto
    assert "no film model" in reason(ocvirk_text(None).replace('"mobility"', '"petroff"'),
                                     "journal_bearing")


def test_auto_chooses_per_bearing_by_its_land():
    """Zeta camshaft with the default (auto) film: the grooved lands (b/d 0.29-0.35) run finite; a
    bearing whose lands are made short (2 x 1.2 mm on 26 mm, b/d 0.046) keeps the short film."""
    raw = tomllib.loads(ZETA.read_text())
    del raw["camshaft"]["bearing_model"]
    raw["camshaft"]["bearings"][2].update(length=3.4, groove_width=1.0)
    plan = ct.plan(validate(raw, "zeta", DECKS))
    why = next(s.reason for s in plan.steps if s.effect == "bearings")
    assert "bearing 1: auto: land b/d = 0.347 > 0.05" in why
    assert "bearings 2, 4, 5: auto: land b/d = 0.289 > 0.05" in why
    assert "bearing 3: auto: land b/d = 0.0462 <= 0.05, where the short bearing" in why


def test_auto_keeps_the_short_film_for_a_short_land():
    """D 50 x b 2 mm (b/d 0.04): auto runs the short model, the same orbit as model = short."""
    text = ocvirk_text(None).replace("diameter = 25.0", "diameter = 50.0").replace(
        "length = 18.0", "length = 2.0").replace("-500.0", "-100.0")
    auto, short = ct.run(ct.loads(text)), ct.run(ct.loads(text.replace(
        'method = "mobility"', 'method = "mobility"\nmodel = "short"')))
    assert np.array_equal(auto["eccentricity"], short["eccentricity"])
    assert "short film model" in auto.metrics["min_film"].description


# ------------------------------------------------------------------ the finite orbit via the deck

def test_ocvirk_check_deck_with_the_finite_model():
    """model = "finite" on the Ocvirk check deck (b/d 0.72): a periodic orbit whose film is below
    the short bearing's 7.09 um, at the steady finite solve's 4.78 um within 0.5 % (the map's
    72 x 6 table against the 120 x 12 steady solve), and the same as the library's map orbit."""
    fin = ct.run(ct.loads(ocvirk_text("finite")))
    short = ct.run(OCVIRK)
    assert fin.metrics["periodicity_error"].value <= 1e-5
    assert fin.metrics["min_film"].value < short.metrics["min_film"].value
    assert fin.metrics["min_film"].value == pytest.approx(4.78e-6, rel=0.005)
    assert "finite film model" in fin.metrics["min_film"].description
    assert "finite-length Reynolds film as the deck asks" in fin.plan.steps[0].reason
    from camtrain.report.bearing_plots import bearing_header_rows

    rows = dict(bearing_header_rows(ct.loads(ocvirk_text("finite")).model, fin))
    assert rows["Film model"] == "finite (reynolds, 72 x 6)"
    assert dict(bearing_header_rows(ct.load(OCVIRK).model, short))["Film model"] == \
        "short (Ocvirk)"
    # the plan's estimate (validity table interpolated at the deck's S 0.056) against the runs
    from camtrain.bearings.validity import short_model_ratio_at

    ratio = short.metrics["min_film"].value / fin.metrics["min_film"].value
    assert short_model_ratio_at(0.72, 0.056) == pytest.approx(ratio, rel=0.03)
    for name in ("eccentricity", "attitude", "min_film", "min_film_position", "power"):
        assert fin[name].shape == short[name].shape
    deck = ct.load(OCVIRK).model
    g, s, ld = deck.bearing, deck.speed, deck.load
    brg = JournalBearing(g.diameter, g.length, g.clearance, g.viscosity, g.groove_width)
    lib = bearing_orbit(brg, np.asarray(ld.load_x), np.asarray(ld.load_y),
                        np.asarray(ld.angles), s.journal, period=ld.period,
                        mobility=bearing_mobility_map(brg))
    assert np.array_equal(fin["eccentricity"], lib.eccentricity)


def test_steady_method_with_the_finite_model_agrees_with_its_orbit():
    """A constant load: the quasi-static finite locus equals the settled finite orbit (eps within
    0.2 %: both interpolate tables of the same mesh)."""
    orbit = ct.run(ct.loads(ocvirk_text("finite")))
    steady = ct.run(ct.loads(ocvirk_text("finite").replace('method = "mobility"',
                                                           'method = "steady"')))
    assert steady["eccentricity"] == pytest.approx(orbit["eccentricity"], rel=2e-3)
    assert steady.metrics["min_film"].value < 7.0e-6


def test_steady_finite_beyond_its_curve_is_a_convergence_finding():
    """A load the finite film cannot carry above eps 0.99 stops like the orbit that leaves the
    map: a ConvergenceError (a camshaft bearing warns and reports no orbit), not bad input."""
    from camtrain.bearings.models import finite_steady_orbit
    from camtrain.errors import ConvergenceError

    brg = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
    with pytest.raises(ConvergenceError, match="eps > 0.99"):
        finite_steady_orbit(brg, np.zeros(2), np.full(2, -1e7), np.array([0.0, 3.0]), 157.0)


def test_zeta_camshaft_with_the_finite_model():
    """Zeta intake camshaft, bearing_model = "finite": every bearing's film below the short
    one (Yang's model), orbits periodic (the run warns on none), eps higher."""
    text = ZETA.read_text()
    fin = ct.run(ct.loads(text.replace('bearing_model = "short"', 'bearing_model = "finite"')))
    short = ct.run(ZETA)
    assert not [w for w in fin.warnings if "orbit" in w]
    for k in range(1, 6):
        f, s = fin.component(f"bearing_{k}"), short.component(f"bearing_{k}")
        assert f.metrics["min_film"].value < s.metrics["min_film"].value
        assert f.metrics["max_eccentricity"].value > s.metrics["max_eccentricity"].value
    assert fin.metrics["bearings_power_total"].value > 0


# ------------------------------------------------------------------ the short model's warning

@pytest.mark.derived
@pytest.mark.parametrize("b_over_d", [0.25, 0.7])
def test_warning_table_is_the_computed_film_ratio(b_over_d):
    """FILM_RATIO_TABLE (what the warning quotes; docs/bearings.md) is short_film_ratio at the
    default mesh, to its 2 printed decimals."""
    from camtrain.bearings.validity import FILM_RATIO_SOMMERFELD, FILM_RATIO_TABLE, short_film_ratio

    computed = short_film_ratio(b_over_d, np.array(FILM_RATIO_SOMMERFELD))
    assert computed == pytest.approx(np.array(FILM_RATIO_TABLE[b_over_d], float), abs=0.0051)


def test_no_warning_where_the_short_film_is_accurate():
    from camtrain.bearings.models import choose_model
    from camtrain.bearings.validity import short_model_warning

    assert short_model_warning(0.05) is None
    assert "x1.51 at 0.01" in short_model_warning(0.25)
    tiny = JournalBearing(50e-3, 2.0e-3, 25e-6, 0.01)
    assert "warning" not in choose_model(tiny, "short")[1]


# ------------------------------------------------------------------ accuracy knobs

def test_accuracy_knobs_for_bearing_decks():
    bearing = tomllib.loads(OCVIRK.read_text())
    cam = tomllib.loads(ZETA.read_text())
    assert acc.relevant_knobs(bearing) == ["bearing_mesh", "bearing_model"]
    assert {"angle_points", "bearing_mesh", "bearing_model"} <= set(acc.relevant_knobs(cam))
    assert "bearing_mesh" not in acc.relevant_knobs(tomllib.loads(
        (DECKS / "harrison_flat.toml").read_text()))
    bearing["solver"]["method"] = "petroff"
    assert "bearing_model" not in acc.relevant_knobs(bearing)
    rung = acc.KNOBS["bearing_mesh"].setter(cam, 144)["camshaft"]
    assert (rung["bearing_model"], rung["bearing_n_theta"], rung["bearing_n_z"]) == \
        ("finite", 144, 12)


def test_accuracy_study_of_short_against_finite():
    """The model knob on the Ocvirk check deck (reference: the finite film at the finest rung
    given): the short film's error is the x1.48 of the validity table, the finite rung's small."""
    raw = tomllib.loads(OCVIRK.read_text())
    k = acc.study_knob(raw, "bearing_model", 1e-3, base_dir=DECKS,
                       ladder=("short", "finite:36", "finite"))
    assert [r["status"] for r in k["rungs"]] == ["ok"] * 3
    film = k["metrics"]["min_film"]
    assert film["reference_kind"] == "finest"
    assert film["values"][0] / film["reference"] == pytest.approx(1.49, abs=0.02)
    assert film["errors"][1] < 0.03
    table = acc.render_table({"title": "t", "tolerance": 1e-3, "knobs": {"bearing_model": k}})
    assert "short" in table and "finite:36" in table
