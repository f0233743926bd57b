"""The elastic film as a film law of the contact model, run from a deck (docs/ehl.md).

The Göçmen deck with ``tribology.film_model = "ehl"`` at a coarse resolution (128 points,
2 deg steps): the run's columns, metrics, film map and plan; a point contact refused.
"""
from __future__ import annotations

import numpy as np
import pytest

from camtrain import api
from camtrain.errors import InputError
from tests.conftest import DECKS

GOCMEN = (DECKS / "gocmen_table31.toml").read_text()
COARSE = "\n[solver]\nehl_nodes = 128\nehl_angle_step = 2.0\n"


@pytest.fixture(scope="module")
def elastic_run():
    text = GOCMEN.replace('film_model = "averaged_reynolds"', 'film_model = "ehl"') + COARSE
    return api.run(api.load_deck_text(text, "gocmen_ehl.toml"))


def test_the_plan_names_the_elastic_film(elastic_run):
    step = next(s for s in elastic_run.plan.steps if s.effect == "film")
    assert "elastic film" in step.reason and "128 points" in step.reason


def test_films_friction_and_pressures_come_from_the_solution(elastic_run):
    r = elastic_run
    h_min, h_c = r["film_min"], r["film_central"]
    assert np.all(h_min > 0.0) and np.all(h_c >= h_min)
    assert np.all(r["friction_force"] > 0.0)
    ratio = r["film_pressure_over_hertz"]
    assert 0.2 < np.nanmin(ratio) and np.nanmax(ratio) < 1.5   # no rigid 3.7 GPa peaks
    for k in ("film_at_zero_entrainment_1", "film_at_zero_entrainment_2"):
        assert r.metrics[k].value > 10e-9                    # the squeeze keeps a film
    assert r.metrics["film_period_error"].value < 0.05


def test_the_formula_films_beside_the_elastic_film(elastic_run):
    """The closed-form films the elastic film declares (film.FORMULA_COLUMNS) are written and
    equal the formulas of the run's load per width, contact radius, |mean entrainment|, oil and
    reduced modulus at a few angles; the step records them as columns it makes."""
    from camtrain.contact.model import CamContact
    from camtrain.effects.film import FORMULA_COLUMNS
    from camtrain.formulas import film_line

    r = elastic_run
    step = next(s for s in r.plan.steps if s.effect == "film")
    pair = CamContact.from_deck(api.load_deck_text(
        GOCMEN.replace('film_model = "averaged_reynolds"', 'film_model = "ehl"'),
        "gocmen_ehl.toml").model)
    load = r["load"]
    pick = np.flatnonzero(load > 0.0)[::97][:5]
    assert pick.size == 5
    args = (load[pick] / pair.width, r["radius_x"][pick], np.abs(r["entrainment"][pick]),
            pair.lubricant.viscosity, pair.lubricant.pressure_viscosity, pair.reduced_modulus)
    for column, formula, _ in FORMULA_COLUMNS:
        assert column in step.makes and r.columns[column].unit == "m"
        expected = getattr(film_line, formula)(*args)
        assert np.all(expected > 0.0)
        np.testing.assert_allclose(r[column][pick], expected, rtol=1e-12, atol=0.0)
        assert np.all(np.isnan(r[column][load <= 0.0]))


def test_the_film_map_is_a_table_of_its_own(elastic_run):
    r = elastic_run
    assert "film_map_point" in r.axes
    angles = np.unique(r["film_map_angle"])
    assert angles.size == 180
    assert r["film_map_film"].size == 180 * 64
    assert np.all(r["film_map_film"] > 0.0)


def test_a_point_contact_is_refused():
    text = (DECKS / "zeta_intake.toml").read_text() + '\n[tribology]\nfilm_model = "ehl"\n'
    with pytest.raises(InputError, match="tribology.film_model"):
        api.run(api.load_deck_text(text, "zeta_ehl.toml"))


# the film map resamples every angle's own grid onto one position axis: matplotlib warns
# (UserWarning) when the cell centres of a map do not increase along both axes
@pytest.mark.filterwarnings("error::UserWarning")
def test_the_plan_records_the_elastic_film_and_its_sheets_follow(elastic_run, tmp_path):
    """The film step records the model it ran (Step.model = "ehl"); the sheets and panels
    follow from it (EffectSpec.model_panels): the elastic film sheet with its three panels, and
    the transient film sheet."""
    from camtrain.report.sheets import write_plots

    step = next(s for s in elastic_run.plan.steps if s.effect == "film")
    assert step.model == "ehl"
    written = write_plots(elastic_run, None, tmp_path, formats=("png",))
    names = {p.relative_to(tmp_path).as_posix() for p in written}
    assert {"sheet_elastic_film.png", "sheet_transient_film.png"} <= names
    assert {f"panels/{p}.png" for p in ("film_map", "elastic_films", "pressure_over_hertz",
                                        "transient_film", "film_pressures")} <= names


def test_the_film_model_the_plan_records():
    """The film runs the deck's film model under contact loads, the steady film without."""
    from camtrain.effects import film

    text = GOCMEN.replace('film_model = "averaged_reynolds"', 'film_model = "ehl"')
    deck = api.load_deck_text(text, "gocmen_ehl.toml").model
    assert film.model(deck, frozenset({"ContactLoad"})) == "ehl"
    assert film.model(deck, frozenset()) == "steady"


class _Captured(Exception):
    """Raised by the stand-in march once it has the resolution the run built."""


@pytest.mark.parametrize("solver", ["dense", "krylov", "auto"])
def test_the_deck_linear_solver_reaches_the_march(solver, monkeypatch):
    """solver.ehl_linear_solver is the march's CycleResolution.linear_solver (the march
    itself stood in: the solvers' equal films are tests/lubrication/test_ehl_transient.py's)."""
    from camtrain.lubrication import ehl_transient

    seen = {}

    def stand_in(contact, resolution=None, *args, **kwargs):
        seen["resolution"] = resolution
        raise _Captured
    monkeypatch.setattr(ehl_transient, "march_ehl_cycle", stand_in)
    text = (GOCMEN.replace('film_model = "averaged_reynolds"', 'film_model = "ehl"') + COARSE
            + f'ehl_linear_solver = "{solver}"\n')
    with pytest.raises(_Captured):
        api.run(api.load_deck_text(text, "gocmen_ehl.toml"))
    res = seen["resolution"]
    assert res.linear_solver == solver and res.nodes == 128
    assert res.krylov == (solver == "krylov")       # auto: dense at 128 points


def test_a_bad_linear_solver_names_the_field():
    text = (GOCMEN.replace('film_model = "averaged_reynolds"', 'film_model = "ehl"') + COARSE
            + 'ehl_linear_solver = "cholesky"\n')
    with pytest.raises(InputError, match="ehl_linear_solver"):
        api.load_deck_text(text, "gocmen_ehl.toml")
