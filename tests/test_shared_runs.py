"""The session's shared deck runs (tests/shared_runs.py) hand every test what its own run gives:
the same numbers in a copy of its own, and the run's warnings again."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

from camtrain import api
from tests.conftest import DECKS
from tests.shared_runs import run_deck

FLAT = DECKS / "harrison_flat.toml"


def test_each_asker_gets_its_own_copy_of_the_one_run():
    loaded, first = run_deck(FLAT)
    _, second = run_deck(FLAT)
    own = api.run(api.load(FLAT))
    assert first is not second
    assert loaded.sha256 == api.load(FLAT).sha256
    for name, column in own.columns.items():
        assert np.array_equal(first[name], column.values, equal_nan=True), name
    assert {k: m.value for k, m in first.metrics.items()} == pytest.approx(
        {k: m.value for k, m in own.metrics.items()}, rel=0, abs=0, nan_ok=True)
    first.metrics.clear()
    first.columns["lift"].values[:] = 0.0
    _, third = run_deck(FLAT)
    assert set(third.metrics) == set(own.metrics)
    assert np.array_equal(third["lift"], own["lift"])


def test_equal_models_share_one_run():
    """The shipped deck (2500 rpm) and the same deck with that speed set are one model, one run;
    another speed is another run."""
    _, shipped = run_deck(FLAT)
    _, same = run_deck(FLAT, ("speed.camshaft=2500",))
    _, other = run_deck(FLAT, ("speed.camshaft=2400",))
    assert api.load(FLAT, ("speed.camshaft=2500",)).model == api.load(FLAT).model
    assert same.timings == shipped.timings      # the same run, its timings too
    assert other.metrics["power_loss_mean"].value != shipped.metrics["power_loss_mean"].value


def test_the_runs_warnings_reach_every_asker(monkeypatch):
    deck, sets = FLAT, ("speed.camshaft=1234.5",)    # a model no other test runs
    run = api.run

    def warning_run(loaded, progress=None):
        warnings.warn("a run that warns", UserWarning, stacklevel=1)
        return run(loaded, progress)

    monkeypatch.setattr(api, "run", warning_run)
    with pytest.warns(UserWarning, match="a run that warns"):
        run_deck(deck, sets)
    with pytest.warns(UserWarning, match="a run that warns"):
        run_deck(deck, sets)      # from the cache
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(UserWarning, match="a run that warns"):
            run_deck(deck, sets)
