"""Lubricant viscosity from the oil temperature: a Vogel or two-point fit, or given directly."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from camtrain.deck.load import load_deck
from camtrain.deck.schema import Lubricant
from camtrain.errors import InputError
from camtrain.formulas.viscosity import vogel
from camtrain.runner import run_plan
from tests.tribology.conftest import DECKS


def lub(**kw):
    base = dict(pressure_viscosity=22e-9)
    base.update(kw)
    return Lubricant(**base)


def test_direct_viscosity_unchanged():
    assert lub(viscosity=0.05).viscosity == 0.05
    assert lub(viscosity=0.05).problems("lubricant") == []


def test_two_point_passes_through_its_points_and_is_exponential():
    T, eta = (40.0, 100.0), (0.060, 0.0095)
    for t, e in zip(T, eta, strict=True):
        assert lub(temperature=t, viscosity_fit="two_point", fit_temperatures=T,
                   fit_viscosities=eta).viscosity == pytest.approx(e, rel=1e-12)
    mid = lub(temperature=70.0, viscosity_fit="two_point", fit_temperatures=T,
              fit_viscosities=eta).viscosity
    assert mid == pytest.approx(np.sqrt(0.060 * 0.0095), rel=1e-12)   # log-linear midpoint


def test_vogel_through_three_points():
    A, B, Tinf = 7.0e-5, 900.0, 180.0                # a synthetic Vogel oil [Pa s, K, K]
    T = (40.0, 80.0, 120.0)
    eta = tuple(float(vogel(t + 273.15, A, B, Tinf)) for t in T)
    got = lub(temperature=95.0, viscosity_fit="vogel", fit_temperatures=T, fit_viscosities=eta)
    assert got.viscosity == pytest.approx(vogel(95.0 + 273.15, A, B, Tinf), rel=1e-9)
    assert got.problems("lubricant") == []


@pytest.mark.parametrize("kw, text", [
    (dict(), "is missing"),
    (dict(viscosity_fit="vogel", fit_temperatures=(40, 100, 120),
          fit_viscosities=(0.06, 0.01, 0.007)), "is required with viscosity_fit"),
    (dict(temperature=90, viscosity_fit="vogel", fit_temperatures=(40, 100),
          fit_viscosities=(0.06, 0.01)), "must be pairs"),
    (dict(temperature=90, viscosity_fit="two_point", fit_temperatures=(40, 100),
          fit_viscosities=(0.01, 0.06)), "must fall"),
    (dict(viscosity=0.02, temperature=100, viscosity_fit="two_point",
          fit_temperatures=(40, 100), fit_viscosities=(0.06, 0.01)), "conflicts"),
])
def test_problems(kw, text):
    problems = lub(**kw).problems("lubricant")
    assert problems and any(text in str(p) for p in problems)


def test_deck_with_a_fit_runs_like_the_direct_viscosity(tmp_path):
    """Harrison deck: a two-point fit that gives 0.050 Pa s at 60 degC reproduces the run."""
    text = (DECKS / "harrison_flat.toml").read_text(encoding="utf-8")
    fit = ("temperature = 60.0\nviscosity_fit = \"two_point\"\n"
           "fit_temperatures = [40.0, 60.0]\nfit_viscosities = [0.100, 0.050]\n")
    text = text.replace("viscosity = 0.050            # Pa·s\n", fit)
    assert "viscosity_fit" in text
    path = tmp_path / "fit.toml"
    path.write_text(text, encoding="utf-8")
    deck = load_deck(str(path)).model
    assert deck.lubricant.viscosity == pytest.approx(0.050, rel=1e-12)
    base = load_deck(str(DECKS / "harrison_flat.toml")).model
    assert run_plan(deck).metrics["power_loss_mean"].value == pytest.approx(
        run_plan(base).metrics["power_loss_mean"].value, rel=1e-9)
    hot = replace(deck, lubricant=lub(temperature=80.0, viscosity_fit="two_point",
                                      fit_temperatures=(40.0, 60.0),
                                      fit_viscosities=(0.100, 0.050)))
    assert hot.lubricant.viscosity == pytest.approx(0.025, rel=1e-12)


def test_bad_fit_is_an_input_error(tmp_path):
    text = (DECKS / "harrison_flat.toml").read_text(encoding="utf-8")
    text = text.replace("viscosity = 0.050            # Pa·s\n",
                        "viscosity_fit = \"vogel\"\nfit_temperatures = [40.0]\n"
                        "fit_viscosities = [0.1]\n")
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(InputError):
        load_deck(str(path))
