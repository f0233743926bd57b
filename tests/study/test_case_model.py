"""A sweep case changes only its swept fields of the validated datum model: the model it builds
equals the one full validation of the case's raw deck gives, and it fails the same way."""
from __future__ import annotations

import pytest

from camtrain.study.case_model import build_case_model, changes_only_its_field
from camtrain.study.runner import prepare
from camtrain.study.sweep import case_raw

from .conftest import DECKS


def _full(sweep, case):
    from pathlib import Path

    from camtrain.deck.load import validate

    return validate(case_raw(sweep.raw, sweep.params, case), sweep.name, Path(sweep.base_dir))


@pytest.mark.parametrize(("deck", "specs"), [
    ("harrison_flat.toml", [("base_radius", "values", "14,22.5")]),
    ("harrison_flat.toml", [("speed", "values", "900"), ("cam_width", "values", "8,15")]),
    ("harrison_flat.toml", [("lift.four_power.half_period", "values", "55,65")]),
    ("harrison_flat.toml", [("solver.angle_points", "values", "360")]),
    ("harrison_flat.toml", [("lubricant.pressure_viscosity", "relative", "-20%:+20%:3")]),
    ("zeta_intake.toml", [("viscosity", "values", "0.01,0.02"),
                          ("equivalent_mass", "values", "0.1")]),
])
def test_fast_case_model_equals_full_validation(deck, specs):
    sweep = prepare(DECKS / deck, specs)
    assert all(changes_only_its_field(sweep.raw, p) for p in sweep.params)
    for case in sweep.cases:
        fast = build_case_model(sweep.raw, sweep.params, case, sweep.name, sweep.base_dir)
        assert fast == _full(sweep, case)


def test_pivot_rules_take_the_full_path():
    sweep = prepare(DECKS / "pinto_finger.toml", [("base_radius", "values", "16,18")])
    assert not changes_only_its_field(sweep.raw, sweep.params[0])
    for case in sweep.cases:
        model = build_case_model(sweep.raw, sweep.params, case, sweep.name, sweep.base_dir)
        assert model == _full(sweep, case)


def test_cross_field_problem_fails_like_validation():
    """A follower radius on a flat follower is a cross-field problem of [mechanism]: the fast
    case raises the same InputError, naming the same field, as full validation."""
    from camtrain.errors import InputError

    sweep = prepare(DECKS / "harrison_flat.toml", [("follower_radius", "values", "20")])
    case = sweep.cases[0]
    with pytest.raises(InputError) as full:
        _full(sweep, case)
    with pytest.raises(InputError) as fast:
        build_case_model(sweep.raw, sweep.params, case, sweep.name, sweep.base_dir)
    assert str(fast.value) == str(full.value)
    assert "mechanism.follower_radius" in str(fast.value)
