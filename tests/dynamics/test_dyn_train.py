"""The lumped train against closed forms: series rule and the single-degree-of-freedom period
(Newmark's period error of order 2), the spring-surge chain (first mode 1/2 sqrt(k/m_s), 518.5 Hz
for the Zeta spring, its N^-2 convergence and the 1/3 end-mass rule), the static state on the
base circle, the explicit scheme's stability guard."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.dynamics import (
    CAM,
    assemble_train,
    chain_end_mass,
    series,
    stability_limit,
    surge_frequency,
    surge_frequency_discrete,
)
from camtrain.dynamics.integrators import bilateral, free_vibration
from camtrain.dynamics.train import static_state

#: Zeta valve spring (Yang 1992 App C): rate and mass
ZETA_RATE, ZETA_SPRING_MASS = 37634.0, 0.035


def _sdof():
    """One node: cam contact 2e8 N/m in series with a 5e7 N/m stem, valve spring 4e4 N/m."""
    model = assemble_train(valve_mass=0.1, contact_stiffness=2e8, links={"stem": 5e7},
                           seat_stiffness=1e8, spring_rate=4e4, spring_preload=200.0,
                           damping_ratio=0.0, spring_damping_ratio=0.0)
    return bilateral(model, contacts=(CAM,))


def _period(u, dt):
    """Mean period from the upward zero crossings (linear interpolation)."""
    s = np.sign(u)
    i = np.nonzero((s[:-1] < 0) & (s[1:] >= 0))[0]
    t = (i + u[i] / (u[i] - u[i + 1])) * dt
    return float((t[-1] - t[0]) / (t.size - 1))


#: steps per period for Newmark's period elongation (omega dt)^2 / 12 to stay below 0.1 %:
#: omega dt <= sqrt(0.012), 2 pi / sqrt(0.012) = 57.4
STEPS_FOR_A_TENTH_PERCENT = 2 * math.pi / math.sqrt(12e-3)


@pytest.mark.derived
def test_series_rule_and_sdof_frequency():
    model = _sdof()
    k_e = series(2e8, 5e7) + 4e4
    assert series(2e8, 5e7) == pytest.approx(4e7, rel=1e-15)
    assert model.stiffness[0, 0] == pytest.approx(k_e, rel=1e-14)
    exact = 2 * math.pi / math.sqrt(k_e / 0.1)
    errors = {}
    for per in (50, 58, 100):
        dt = exact / per
        errors[per] = _period(free_vibration(model, [1e-4], dt, 30 * per)[0], dt) / exact - 1
        # the trapezoid's elongation (omega dt)^2 / 12: 0.13 %, 0.098 %, 0.033 %
        assert errors[per] == pytest.approx((2 * math.pi / per) ** 2 / 12, rel=0.02)
    # within 0.1 % from 58 steps per period (57.4: the resolution the requirement needs)
    assert 0 < errors[58] < 1e-3 < errors[50]


@pytest.mark.derived
@pytest.mark.parametrize("deck", ["zeta_intake_dynamics", "pushrod_dynamics"])
def test_default_step_resolves_the_first_mode_of_the_shipped_decks(deck):
    """The automatic step (the shortest period / 20) puts at least 58 steps in the period of
    the train's first mode (cam closed, valve off its seat), so that mode's frequency is within
    0.1 % by default: 420 steps (Zeta, 514 Hz surge mode), 180 (push rod, 1333 Hz)."""
    from camtrain.assemble.dynamics import setup as dynamic_setup
    from camtrain.deck.load import load_deck
    from tests.conftest import DECKS
    from tests.dynamics.conftest import kinematics_of

    d = load_deck(str(DECKS / f"{deck}.toml")).model
    kin = kinematics_of(d)
    s = dynamic_setup(d, kin)
    lifted = bilateral(s.model, contacts=(CAM,))
    scale = 1 / np.sqrt(lifted.mass)
    w1 = math.sqrt(np.linalg.eigvalsh(lifted.stiffness * scale[:, None] * scale[None, :])[0])
    dt = s.base.period / (kin.theta.size * s.settings.substeps)
    assert 2 * math.pi / w1 / dt > STEPS_FOR_A_TENTH_PERCENT


@pytest.mark.convergence
def test_newmark_period_error_is_second_order():
    model = _sdof()
    exact = 2 * math.pi / math.sqrt(model.stiffness[0, 0] / 0.1)
    per = np.array([16, 32, 64, 128])
    errors = [abs(_period(free_vibration(model, [1e-4], exact / p, 40 * p)[0], exact / p)
                  - exact) / exact for p in per]
    slope = np.polyfit(np.log(1.0 / per), np.log(errors), 1)[0]
    assert slope == pytest.approx(2.0, abs=0.1)


@pytest.mark.derived
def test_surge_frequency_of_the_zeta_spring():
    assert surge_frequency(ZETA_RATE, ZETA_SPRING_MASS) == pytest.approx(518.5, abs=0.05)


def _chain_first_mode(elements):
    """First fixed-fixed mode [Hz] of the assembled chain (retainer held: its node removed)."""
    model = assemble_train(valve_mass=1.0, contact_stiffness=1e8, seat_stiffness=1e8,
                           spring_rate=ZETA_RATE, spring_preload=200.0,
                           spring_mass=ZETA_SPRING_MASS, spring_elements=elements)
    idx = list(model.chain)
    k = model.stiffness[np.ix_(idx, idx)]
    m = model.mass[idx]
    s = 1 / np.sqrt(m)
    w2 = np.linalg.eigvalsh(k * s[:, None] * s[None, :])
    return math.sqrt(w2[0]) / (2 * math.pi)


@pytest.mark.convergence
def test_surge_chain_tends_to_the_continuum_as_n_to_the_minus_two():
    f1 = surge_frequency(ZETA_RATE, ZETA_SPRING_MASS)
    ns = np.array([4, 8, 16, 32])
    assembled = np.array([_chain_first_mode(n) for n in ns])
    np.testing.assert_allclose(assembled, [surge_frequency_discrete(ZETA_RATE, ZETA_SPRING_MASS,
                                                                     n) for n in ns], rtol=1e-12)
    err = np.abs(assembled - f1) / f1
    assert err[1] < 0.01                      # within 1 % at 8 elements (-0.64 %)
    slope = np.polyfit(np.log(ns), np.log(err), 1)[0]
    assert slope == pytest.approx(-2.0, abs=0.1)


@pytest.mark.convergence
def test_chain_end_mass_tends_to_a_third_of_the_spring():
    ns = np.array([4, 8, 16, 32, 64])
    third = ZETA_SPRING_MASS / 3
    err = np.array([chain_end_mass(ZETA_SPRING_MASS, n) for n in ns]) / third - 1
    assert err[1] == pytest.approx(0.0078, abs=0.0001)      # +0.78 % at 8 (reference notes L5)
    slope = np.polyfit(np.log(ns), np.log(err), 1)[0]
    assert slope == pytest.approx(-2.0, abs=0.1)


def test_end_mass_of_the_assembled_chain_under_a_slow_linear_drive():
    """The kinetic energy of the assembled chain moving in its quasi-static (linear) shape is
    that of chain_end_mass at the retainer."""
    n = 8
    model = assemble_train(valve_mass=0.0 + 1e-9, contact_stiffness=1e8, seat_stiffness=1e8,
                           spring_rate=ZETA_RATE, spring_preload=200.0,
                           spring_mass=ZETA_SPRING_MASS, spring_elements=n)
    shape = np.zeros(model.size)
    shape[model.valve] = 1.0
    shape[list(model.chain)] = 1.0 - np.arange(1, n) / n
    m_eq = float(np.sum(model.mass * shape ** 2)) - 1e-9
    assert m_eq == pytest.approx(chain_end_mass(ZETA_SPRING_MASS, n), rel=1e-12)


@pytest.mark.derived
def test_static_state_carries_the_preloads_to_round_off():
    model = assemble_train(valve_mass=0.06, follower_mass=0.05, links={"stem": 3e7},
                           contact_stiffness=2e8, seat_stiffness=2e8, spring_rate=37634.0,
                           spring_preload=210.0, spring_mass=0.035, spring_elements=8,
                           adjuster_load=20.0)
    u, act = static_state(model)
    assert act.tolist() == [True, True]
    cam = model.uni_k[0] * (model.uni_offset[0] - u[model.follower])
    seat = model.uni_k[1] * (model.uni_offset[1] - u[model.valve])
    assert cam == pytest.approx(20.0, rel=1e-12)          # the adjuster's load
    assert seat == pytest.approx(190.0, rel=1e-12)        # spring preload - adjuster load
    assert model.spring_force_at_head(u[:, None])[0] == pytest.approx(210.0, rel=1e-12)


def test_central_difference_step_limit_names_the_stiffest_element():
    model = assemble_train(valve_mass=0.06, follower_mass=0.05, links={"stem": 3e7},
                           contact_stiffness=2e8, seat_stiffness=1e8, spring_rate=37634.0,
                           spring_preload=210.0)
    assert model.stiffest().name.startswith("cam contact")
    assert stability_limit(model) == pytest.approx(2 / model.omega_max())


@pytest.mark.derived
def test_damping_given_as_values_equals_the_same_damping_given_as_ratios():
    """c = 2 zeta sqrt(k m) given directly [N s/m] builds the same matrices as the ratios."""
    from camtrain.dynamics import damping_from_ratio

    common = dict(valve_mass=0.06, follower_mass=0.05, links={"stem": 3e7},
                  contact_stiffness=2e8, seat_stiffness=1e8, spring_rate=37634.0,
                  spring_preload=210.0, spring_mass=0.035, spring_elements=8)
    by_ratio = assemble_train(**common, damping_ratio=0.05, seat_damping_ratio=0.1,
                              spring_damping_ratio=0.02)
    c_el = by_ratio.damping[by_ratio.chain[-1], by_ratio.chain[-1]] / 2   # two equal elements
    m_red = by_ratio.mass[0] * by_ratio.mass[1] / (by_ratio.mass[0] + by_ratio.mass[1])
    values = {"contact": damping_from_ratio(0.05, 2e8, by_ratio.mass[0]),
              "link": damping_from_ratio(0.05, 3e7, m_red),
              "seat": damping_from_ratio(0.1, 1e8, by_ratio.mass[1]), "spring": c_el / 8}
    by_value = assemble_train(**common, damping_ratio=0.3, seat_damping_ratio=0.3,
                              spring_damping_ratio=0.3, damping=values)
    np.testing.assert_allclose(by_value.damping, by_ratio.damping, rtol=1e-12)
    np.testing.assert_allclose(by_value.uni_c, by_ratio.uni_c, rtol=1e-12)
    with pytest.raises(ValueError, match="unknown damping"):
        assemble_train(**common, damping={"pushrod": 1.0})


def test_deck_damping_values_reach_the_model():
    from camtrain.assemble.dynamics import build_model
    from tests.dynamics.conftest import deck_of, zeta_raw

    deck = deck_of(zeta_raw({"dynamics": {"contact_damping": 150.0, "seat_damping": 300.0,
                                          "link_damping": 80.0, "spring_damping": 2.0}}))
    model = build_model(deck)
    assert model.uni_c.tolist() == [150.0, 300.0]
    assert model.damping[0, 1] == pytest.approx(-80.0)
    chain_end = model.chain[-1]
    assert model.damping[chain_end, chain_end] == pytest.approx(2 * 8 * 2.0)
