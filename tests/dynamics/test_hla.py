"""The hydraulic lash adjuster (camtrain.dynamics.hla): closed forms and limits of the element and
of the train marched with it (no deck: the Zeta dynamics deck's train with an adjuster added)."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from camtrain.dynamics.hla import (
    LashAdjuster,
    chamber_stiffness,
    effective_bulk_modulus,
    leak_conductance,
    leakdown_test,
    leakdown_time,
    with_lash_adjuster,
)
from tests.dynamics.conftest import deck_of, kinematics_of, zeta_raw

#: an adjuster of the typical size (reference ranges: plunger 8-13 mm, diametral clearance
#: 5-20 um, leak length 5-10 mm, chamber 100-1000 mm^3): test data, not a product's
ADJUSTER = LashAdjuster(plunger_diameter=11e-3, radial_clearance=4e-6, leak_length=6e-3,
                        viscosity=0.009865, dead_volume=150e-9, stroke=2.5e-3,
                        rest_extension=0.6e-3, plunger_mass=0.008, spring_rate=3e3,
                        spring_preload=10.0, supply_pressure=2.5e5, air_fraction=0.01)


@pytest.fixture(scope="module")
def zeta():
    """The Zeta dynamics train (its constant adjuster load removed) at the deck's 1500 rpm."""
    from camtrain.assemble.dynamics import setup

    deck = deck_of(zeta_raw({"clearance": {"adjuster_load": 0.0}}))
    return setup(deck, kinematics_of(deck), omega=1500 * math.pi / 30)


def _march(s, model, **settings):
    from camtrain.dynamics import march

    return march(model, s.cam, s.base, replace(s.settings, **settings))


# --------------------------------------------------------------------------- closed forms

@pytest.mark.derived
@pytest.mark.parametrize("eccentricity", [0.0, 0.8])
def test_leakdown_time_is_the_laminar_annulus_solution(eccentricity):
    """Under a constant 222 N, no plunger spring rate (its preload kept), the marched plunger
    (mass, compressible chamber with air, leak, shut check valve) takes the closed-form time
    A (A + pi d c/2) s / (G (F - F0)) over the travel, G = pi d c^3 (1 + 1.5 e^2)/(12 mu L),
    once the pressure has built: equal within 1e-5 (what is left of the plunger's ring on its
    chamber after the load is set down, and the step)."""
    adj = replace(ADJUSTER, spring_rate=0.0, eccentricity=eccentricity)
    marched, _, pressure = leakdown_test(adj, load=222.0, travel=1.0e-3, start=0.1e-3)
    closed = leakdown_time(adj, 222.0, 1.0e-3, 0.1e-3)
    assert marched == pytest.approx(closed, rel=1e-5)
    assert pressure == pytest.approx((222.0 - adj.spring_preload) / adj.area, rel=1e-6)


@pytest.mark.derived
def test_eccentric_annulus_leaks_1_plus_1_5_e2_times_more():
    g0 = leak_conductance(11e-3, 4e-6, 6e-3, 0.01)
    assert leak_conductance(11e-3, 4e-6, 6e-3, 0.01, 1.0) == pytest.approx(2.5 * g0, rel=1e-15)
    assert g0 == pytest.approx(math.pi * 11e-3 * 4e-6 ** 3 / (12 * 0.01 * 6e-3), rel=1e-15)


@pytest.mark.derived
def test_leakdown_with_the_spring_rate_follows_the_logarithmic_closed_form():
    """With the spring's rate the pressure falls as the plunger collapses; the closed form
    neglects the chamber's compliance, an error of the order k_spring / k_chamber."""
    adj = replace(ADJUSTER, air_fraction=0.0)
    marched = leakdown_test(adj, load=222.0, travel=1.0e-3, start=0.1e-3)[0]
    closed = leakdown_time(adj, 222.0, 1.0e-3, 0.1e-3)
    assert marched == pytest.approx(closed, rel=5 * adj.spring_rate / adj.stiffness())


@pytest.mark.derived
def test_effective_bulk_modulus_limits():
    """No air: the oil's modulus; only air: the gas's polytropic modulus n p_abs; a few per
    cent of air at low pressure lowers the modulus by an order of magnitude (reference
    notes)."""
    assert float(effective_bulk_modulus(1e6, 1.6e9, 0.0)) == pytest.approx(1.6e9, rel=1e-12)
    k = float(effective_bulk_modulus(1e5, 1.6e9, 1.0, 1.4))
    assert k == pytest.approx(1.4 * (1e5 + 101_325.0), rel=1e-12)
    assert float(effective_bulk_modulus(2.5e5, 1.6e9, 0.02)) < 0.1 * 1.6e9


# --------------------------------------------------------------------------- in the train

def _rigid_equivalent(s, adj):
    """The deck's constant-load adjuster: the plunger's mass on the follower, the rest force as
    the adjuster load, the same link damping as a value."""
    from camtrain.dynamics import assemble_train

    m = s.model
    f, v = m.follower, m.valve
    link_c = -m.damping[f, v]
    kwargs = _train_kwargs(s)
    kwargs["follower_mass"] = m.mass[f] + adj.plunger_mass
    return assemble_train(adjuster_load=adj.rest_force(),
                          damping=dict(kwargs.pop("damping"), link=link_c), **kwargs)


def _train_kwargs(s):
    """The arguments the Zeta train was assembled with (assemble.dynamics.build_model)."""
    deck = deck_of(zeta_raw({"clearance": {"adjuster_load": 0.0}}))
    d = deck.dynamics
    m = s.model
    k_link = -m.stiffness[m.follower, m.valve]
    return dict(valve_mass=m.mass[m.valve] - d.spring_mass / (2 * d.spring_elements),
                follower_mass=m.mass[m.follower], contact_stiffness=m.uni_k[0],
                links={"valve stem": k_link}, seat_stiffness=m.uni_k[1],
                spring_rate=deck.spring.rate,
                spring_preload=deck.spring.rate * deck.spring.preload_compression,
                damping_ratio=d.damping_ratio, spring_mass=d.spring_mass,
                spring_elements=d.spring_elements,
                spring_damping_ratio=d.spring_damping_ratio,
                damping={"contact": m.uni_c[0], "seat": m.uni_c[1]})


@pytest.mark.derived
def test_infinite_modulus_without_leak_is_the_rigid_adjuster(zeta):
    """Incompressible oil, no air, no clearance, a check valve that never cracks: the plunger
    locks onto the body and the train is camtrain's constant-load adjuster (plunger mass on the
    follower): the valve's motion and the contact forces to the integrator's tolerance (its
    contact switches located to 1e-10 of a step, the chamber's pressure to 1e-12 relative:
    measured 6e-8 of the lift after three revolutions)."""
    adj = replace(ADJUSTER, bulk_modulus=math.inf, air_fraction=0.0, radial_clearance=0.0,
                  cracking_pressure=1e9)
    hla = _march(zeta, with_lash_adjuster(zeta.model, adj), cycles_min=3, cycles_max=3)
    rigid = _march(zeta, _rigid_equivalent(zeta, adj), cycles_min=3, cycles_max=3)
    v = zeta.model.valve
    scale = float(np.max(rigid.u[v]))
    assert np.max(np.abs(hla.u[v] - rigid.u[v])) < 2e-7 * scale
    assert np.max(np.abs(hla.contact_force - rigid.contact_force)) < 2e-6 * np.max(
        rigid.contact_force)
    assert np.ptp(hla.hydraulic[3]) < 1e-12   # the plunger never moved in its body


@pytest.mark.derived
def test_closed_chamber_is_a_spring_of_K_A2_over_V_in_series(zeta):
    """Check valve shut, no leak, no air, no plunger spring rate: the train with the adjuster
    and the train with a linear spring K A^2/V between follower and plunger move alike, to the
    chamber's own nonlinearity over the event (relative volume change and p/K, both ~3e-5)."""
    adj = replace(ADJUSTER, bulk_modulus=1.6e11, dead_volume=2e-5, air_fraction=0.0,
                  radial_clearance=0.0, cracking_pressure=1e9, spring_rate=0.0)
    model = with_lash_adjuster(zeta.model, adj)
    k_h = chamber_stiffness(adj.bulk_modulus, adj.area, adj.rest_volume)
    assert model.series.stiffness() == pytest.approx(k_h, rel=1e-12)
    linear = _as_linear_spring(model, k_h)
    hla = _march(zeta, model, cycles_min=3, cycles_max=3)
    spring = _march(zeta, linear, cycles_min=3, cycles_max=3)
    v, f, q = model.valve, model.follower, model.series.node
    scale = float(np.max(spring.u[v]))
    assert np.max(np.abs(hla.u[v] - spring.u[v])) < 2e-4 * scale
    deflection_hla = hla.u[f] - hla.u[q]
    deflection_spring = spring.u[f] - spring.u[q]
    assert np.max(np.abs(deflection_hla - deflection_spring)) < 2e-3 * np.ptp(deflection_spring)


def _as_linear_spring(model, k_h):
    """The adjuster replaced by a linear spring k_h (its rest force kept as a preload pair,
    the spring unstrained in the train's state at rest, as the chamber is)."""
    from camtrain.dynamics.hla import _spring_at_rest

    k = model.stiffness.copy()
    f, q = model.follower, model.series.node
    r = model.series.ratio ** 2 * k_h
    k[f, f] += r
    k[q, q] += r
    k[f, q] -= r
    k[q, f] -= r
    preload = model.preload.copy()
    preload[f] -= model.series.rest_force()
    preload[q] += model.series.rest_force()
    return _spring_at_rest(replace(model, stiffness=k, preload=preload, series=None), r, q)


def test_rigid_adjuster_undoes_the_placement(zeta):
    """rigid_adjuster (the lift-loss reference) is the constant-load train built by
    assemble_train with the plunger's mass on the follower."""
    from camtrain.dynamics.hla import rigid_adjuster

    adj = ADJUSTER
    built = _rigid_equivalent(zeta, adj)
    back = rigid_adjuster(with_lash_adjuster(zeta.model, adj))
    for name in ("mass", "stiffness", "damping", "preload", "uni_offset", "uni_k", "uni_c"):
        assert np.allclose(getattr(back, name), getattr(built, name), rtol=1e-12, atol=1e-9)


@pytest.mark.derived
def test_plunger_on_the_closed_chamber_rings_at_sqrt_k_over_m():
    """A load set suddenly on the plunger of a closed chamber (no leak, no air, no spring):
    x = D (1 - cos wt), w = sqrt(K A^2 / (V m)); it passes D at T/4 and 1.5 D at T/3, so the
    time between them is T/12 (the chamber's own step, 2000 steps per period)."""
    from camtrain.dynamics.hla import chamber_start, hydraulic_record
    from camtrain.dynamics.hla.leakdown import _leakdown_march

    adj = replace(ADJUSTER, air_fraction=0.0, radial_clearance=0.0, spring_rate=0.0,
                  spring_preload=0.0, supply_pressure=0.0, cracking_pressure=1e9,
                  rest_extension=ADJUSTER.stroke)
    load = 5.0
    k = chamber_stiffness(adj.bulk_modulus, adj.area, adj.dead_volume + adj.area * adj.stroke)
    period = 2 * math.pi * math.sqrt(adj.plunger_mass / k)
    deflection = load / k
    out = np.zeros(3)
    record = hydraulic_record(adj, 0, 0, 1.0, 0.0)
    _leakdown_march(record, chamber_start(record, 0.0),
                    np.array([adj.plunger_mass, 0.0, 0.0, load]),
                    np.array([period / 2000, 10 * period, period / 2000, 0.0]),
                    np.array([deflection, 1.5 * deflection]), out)
    assert out[0] == pytest.approx(period / 4, rel=2e-4)
    assert out[1] - out[0] == pytest.approx(period / 12, rel=2e-4)
