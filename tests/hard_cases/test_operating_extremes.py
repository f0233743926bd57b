"""Operating extremes: camshaft speed 0 and very high, loss of contact, Barus overflow, a pivoted
follower near self-locking in the friction/load iteration."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.errors import ConvergenceError, InputError
from camtrain.formulas.viscosity import barus, barus_log

from .conftest import DECKS, HARRISON, finite_columns, run_strict, variant

PINTO = (DECKS / "pinto_finger.toml").read_text(encoding="utf-8")


def test_camshaft_speed_zero_is_a_clear_input_error():
    """Speed 0 is refused when the deck is validated, naming the deck field and its unit."""
    with pytest.raises(InputError, match=r"speed\.camshaft: is out of range") as err:
        run_strict(variant(HARRISON, ("camshaft = 2500.0", "camshaft = 0.0")))
    assert err.value.exit_code == 2
    assert "> 0 in rpm" in str(err.value)


def test_creeping_speed_gives_static_loads_and_vanishing_loss():
    """1e-6 rpm: no inertia, so the load is the spring force; friction power -> 0, finite."""
    res = run_strict(variant(HARRISON, ("camshaft = 2500.0", "camshaft = 1e-6")))
    finite_columns(res, ("load", "hertz_pmax", "friction_force", "power_loss"))
    assert 0 <= res.metrics["power_loss_mean"].value < 1e-6
    assert res.metrics["load_min"].value > 0


@pytest.mark.parametrize("rpm", [20_000.0, 1e6])
def test_very_high_speed_loses_contact_with_a_warning(rpm):
    """Far above the bounce speed (3626 rpm) the rigid-train load goes negative: a warning, NaN
    film where the contact is lost (documented), no friction there, finite power."""
    res = run_strict(variant(HARRISON, ("camshaft = 2500.0", f"camshaft = {rpm}")))
    assert any("valve bounce" in w for w in res.warnings)
    lost = res["load"] <= 0
    assert lost.any() and np.all(np.isnan(res["film_min"][lost]))
    assert np.all(res["friction_force"][lost] == 0.0)
    finite_columns(res, ("load", "friction_force", "power_loss", "film_min"))
    assert np.isfinite(res.metrics["power_loss_mean"].value)


def test_barus_overflow_is_inf_or_capped_without_warnings():
    """exp(alpha p) overflows float64 above alpha p ~ 709: 22 /GPa at 50 GPa gives 1100."""
    p = np.array([0.0, 1e9, 3.2e10, 5e10, 1e12])
    with np.errstate(all="raise"):
        eta = barus(p, 0.05, 22e-9)
        capped = barus(p, 0.05, 22e-9, eta_max=1e6)
        log_eta = barus_log(p, 0.05, 22e-9)
    assert np.all(np.isfinite(log_eta)) and np.all(np.diff(log_eta) > 0)
    assert np.isinf(eta[-1]) and np.isinf(eta[-2]) and np.all(np.isfinite(eta[:3]))
    assert np.all(capped <= 1e6) and capped[-1] == 1e6


def test_huge_pressure_viscosity_in_the_chain_stays_finite():
    res = run_strict(variant(HARRISON, ("pressure_viscosity = 22.0", "pressure_viscosity = 1e4")))
    finite_columns(res, ("film_min", "friction_force", "power_loss"))


def _pinto(mu: float, extra: str = "") -> str:
    assert "[solver]" not in PINTO
    return variant(PINTO, ('entrainment = "sum"\n',
                           f'entrainment = "sum"\nboundary_friction = {mu}\n')) + extra


def test_pivoted_follower_near_self_locking_converges():
    """Raising the boundary friction towards the largest allowed (1.0) slows Ball's friction/load
    iteration (38 iterations at mu = 1 against 4 at 0.08) but it still converges to a finite
    cycle whose loss grows with mu. (Not converging within the budget raises: that bound is the
    solver's own, so the test checks that the count and the loss grow with mu.)"""
    runs = {mu: run_strict(_pinto(mu)) for mu in (0.08, 0.3, 1.0)}
    iterations = [runs[mu].metrics["load_iterations"].value for mu in (0.08, 0.3, 1.0)]
    losses = [runs[mu].metrics["power_loss_mean"].value for mu in (0.08, 0.3, 1.0)]
    assert iterations[0] < iterations[1] < iterations[2]
    assert losses[0] < losses[1] < losses[2]
    for res in runs.values():
        finite_columns(res, ("load", "friction_force", "friction_torque", "power_loss"))


def test_friction_iteration_budget_exhausted_is_exit_4():
    with pytest.raises(ConvergenceError) as err:
        run_strict(_pinto(1.0, "\n[solver]\nfriction_max_iterations = 5\n"))
    assert err.value.exit_code == 4
