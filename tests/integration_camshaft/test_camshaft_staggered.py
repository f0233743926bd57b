"""The staggered march of the shaft and the trains (camshaft.flexibility.coupling_solver =
"staggered"; camtrain.coupled._partition): within every time step the shaft under each
contact's predicted load, then every train with the shaft's lobe motion prescribed. Its only
difference from the monolithic march is the splitting of the step, so the two must agree as the
step falls, at the predictor's order (issue: monolithic and staggered within 1 % at a quarter of
the default step; the splitting error falls with the step). docs/camshaft_dynamics.md."""
from __future__ import annotations

import tomllib

import numpy as np
import pytest

from camtrain import api
from camtrain.deck.load import validate
from tests.integration_camshaft.test_camshaft_coupled import DECKS, coupled_raw

QUARTER = 96.0     # steps per degree: a quarter of the default step at 1500 rpm (24 per degree)


def loads(raw: dict) -> np.ndarray:
    r = api.run(validate(raw, "coupled", DECKS))
    assert r.metrics["coupling_change"].value <= 1e-4
    assert not any("no periodic state" in w for w in r.warnings)
    lobes = len(raw["camshaft"]["lobes"])
    return np.array([r.component(f"lobe_{j}")["load"] for j in range(1, lobes + 1)])


def shipped(solver: str, **flexibility) -> dict:
    raw = tomllib.loads((DECKS / "zeta_intake_camshaft_coupled.toml").read_text("utf-8"))
    raw["dynamics"]["steps_per_degree"] = QUARTER
    raw["camshaft"]["flexibility"].update(flexibility, coupling_solver=solver)
    return raw


@pytest.mark.derived
@pytest.mark.slow   # make test-all (about a minute on two cores)
def test_staggered_meets_monolithic_on_the_shipped_deck_at_a_quarter_step():
    """The shipped eight-train deck (the assumed shaft, its belt's hub load, friction at every
    step), the staggered march with its defaults (linear predictor, up to 10 passes a step):
    at 96 steps per degree its loads lie within 1 % of the peak of the monolithic march's at
    every angle of every lobe (the issue's tolerance; measured 0.08-0.19 %, where a contact
    opens or closes inside a step; 0.66-2.8 % at the default 24 steps per degree)."""
    mono = loads(shipped("monolithic"))
    stag = loads(shipped("staggered"))
    gap = np.max(np.abs(stag - mono), axis=1) / np.max(mono)
    assert np.all(gap < 1e-2), gap


def two_lobes(solver: str, steps_per_degree: float, **flexibility) -> np.ndarray:
    """Lobes 1 and 3 (cylinders 1 and 4) of the Zeta camshaft on the x10 shaft."""
    raw = coupled_raw(10.0, solver=solver)
    raw["camshaft"]["lobes"] = raw["camshaft"]["lobes"][::2]
    raw["dynamics"]["steps_per_degree"] = steps_per_degree
    raw["camshaft"]["flexibility"].update(flexibility)
    return loads(raw)


@pytest.fixture(scope="module")
def splitting():
    """Largest difference to the monolithic march over each lobe's curve, over its peak, at 24,
    48 and 96 steps per degree, for both predictors, one pass per step (loosely coupled)."""
    gaps = {"linear": [], "constant": []}
    for spd in (24.0, 48.0, QUARTER):
        mono = two_lobes("monolithic", spd)
        for predictor, found in gaps.items():
            stag = two_lobes("staggered", spd, coupling_predictor=predictor,
                             coupling_iterations=1)
            found.append(np.max(np.abs(stag - mono), axis=1) / np.max(mono))
    return {k: np.array(v) for k, v in gaps.items()}


@pytest.mark.convergence
@pytest.mark.parametrize("predictor, low, high", [("linear", 1.6, 2.6), ("constant", 0.6, 1.4)])
def test_splitting_error_falls_at_the_predictors_order(splitting, predictor, low, high):
    """Halving the step twice: the linear predictor's splitting error falls at second order
    (measured 2.17 -> 0.54 -> 0.14 % of the peak at lobe 1, fitted 2.0), the constant
    predictor's at first (6.7 -> 3.5 -> 1.7 %, fitted 1.0): the predicted load errs by the
    step times its rate (constant) or the step squared times its curvature (linear)."""
    gaps = splitting[predictor]
    assert np.all(np.diff(gaps, axis=0) < 0), gaps
    order = np.polyfit(np.log([24.0, 48.0, QUARTER]), np.log(gaps), 1)[0] * -1.0
    assert np.all((low < order) & (order < high)), order


@pytest.mark.derived
def test_passes_within_a_step_tend_to_the_monolithic_step(splitting):
    """Repeating every step with the load it produced until the two agree (the default, up to
    10 passes: the strongly coupled staggered step) leaves only the steps where a contact
    opens or closes, over which the shaft carries the step's end load: at 96 steps per degree
    within 0.05 % of the peak (measured 0.028 / 0.033 %), below a single pass's 0.14 / 0.05
    %."""
    mono = two_lobes("monolithic", QUARTER)
    strong = two_lobes("staggered", QUARTER)
    gap = np.max(np.abs(strong - mono), axis=1) / np.max(mono)
    assert np.all(gap < 5e-4), gap
    assert np.all(gap <= splitting["linear"][-1]), (gap, splitting["linear"][-1])
