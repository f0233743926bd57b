"""The starved ring pack (Yang 1992 §5.4, Table 6.1, Table 6.2; docs/references/yang1992.md §4.4)."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.piston.gas import ATMOSPHERE, solve_labyrinth
from camtrain.piston.pack import PackRing, solve_pack
from camtrain.piston.ring import piston_position
from tests.piston import zeta_piston as Z

RPM = 3000


def _pack(passes):
    w = RPM * np.pi / 30.0
    gas = solve_labyrinth(Z.TABLE_ANGLES, Z.cylinder_pressure(RPM), 273.15 + 750.0,
                          Z.labyrinth(RPM), w)
    theta = gas.theta[:-1]
    pc, p1 = (gas.pressures[k][:-1] - ATMOSPHERE for k in (0, 1))
    pack = [PackRing(Z.TOP, 0.0, pc, p1, Z.viscosity(0.0, theta, RPM), Z.sigma(Z.TOP)),
            PackRing(Z.SECOND, Z.SECOND_RING_DEPTH, p1, 0 * p1,
                     Z.viscosity(Z.SECOND_RING_DEPTH, theta, RPM), Z.sigma(Z.SECOND))]
    travel = piston_position(theta, Z.CRANK_RADIUS, Z.ROD_LENGTH)
    U = Z.liner(theta, RPM)
    return theta, U, solve_pack(pack, theta, U, travel, w, passes=passes)


@pytest.fixture(scope="module")
def zeta_pack():
    return _pack(2)


@pytest.mark.xfail(strict=True, reason="continuity fails at 16 (top) and 7 (second) of 720 angles "
                   "near the dead centres and where squeeze flow alone exceeds the supplied layer: "
                   "moving the inlet to the minimum gap is not enough there")
def test_continuity_holds_at_every_angle(zeta_pack):
    """Yang eq. 5.34: a starved ring never passes more oil than the layer it is given."""
    theta, U, sol = zeta_pack
    for rc, layer in zip(sol.starved, sol.layers, strict=True):
        fed = np.isfinite(layer) & (U != 0.0)
        passed = rc.flow[fed] * np.sign(U[fed])          # forward, in the direction of entrainment
        assert np.all(passed <= np.abs(U[fed]) * layer[fed] * (1 + 1e-9) + 1e-18)


@pytest.mark.parametrize("ring, net", [(0, 0.11e-8), (1, 0.35e-9)])
def test_starved_net_transport_is_upward_and_far_below_flooded(zeta_pack, ring, net):
    """Yang Table 6.2 and §6.3: starved rings carry oil net upward (top +0.11e-8, second
    +0.35e-9 m^3/cycle) and much less than flooded; the sign is asserted, and the starved net
    below a tenth of the flooded net (the magnitudes depend on assumed volume data)."""
    theta, U, sol = zeta_pack
    w = RPM * np.pi / 30.0
    dt = (theta[1] - theta[0]) / w

    def net_up(rc):
        return float(np.sum(-rc.flow) * np.pi * Z.BORE * dt)

    assert net_up(sol.starved[ring]) > 0.0
    assert abs(net_up(sol.starved[ring])) < 0.1 * abs(net_up(sol.flooded[ring]))


@pytest.mark.xfail(strict=True, reason="the starved top ring's film is not yet a fixed point of "
                   "the passes: a third pass still changes it (dead-centre oil bookkeeping)")
def test_a_third_pass_changes_nothing(zeta_pack):
    """Yang Table 6.1: two starved passes reach the fixed point for any number of rings."""
    _, _, three = _pack(3)
    _, _, two = zeta_pack
    for a, b in zip(three.starved, two.starved, strict=True):
        assert np.allclose(a.h_min, b.h_min, rtol=1e-3)


@pytest.mark.xfail(strict=True, reason="camtrain's starved top ring peaks at ~200 N, no lower "
                   "than flooded: the load relief of the exposed inlet face is not reproduced")
def test_starved_top_ring_friction_is_relieved(zeta_pack):
    """Yang Fig. 6.11: starved top-ring peak friction about 140 N (+-20 %, figure reading),
    below the flooded ring's (Fig. 6.7, about 210 N)."""
    _, _, sol = zeta_pack
    peak = np.max(np.abs(sol.starved[0].friction)) * np.pi * Z.BORE
    flooded = np.max(np.abs(sol.flooded[0].friction)) * np.pi * Z.BORE
    assert peak < flooded
    assert peak == pytest.approx(140.0, rel=0.2)


def _transport(theta, rc):
    """Up, down and net oil transport [m^3/cycle] through a ring, up positive."""
    q = -rc.flow * np.pi * Z.BORE * (theta[1] - theta[0]) / (RPM * np.pi / 30.0)
    return q[q > 0].sum(), q[q < 0].sum(), q.sum()


STARVED_TABLE_6_2 = [(0, (0.50e-8, -0.39e-8)), (1, (0.33e-8, -0.30e-8))]


@pytest.mark.parametrize("ring, table", STARVED_TABLE_6_2)
def test_starved_up_and_down_transport_within_a_factor_2(zeta_pack, ring, table):
    """Yang Table 6.2 (starved, 3000 rpm): up and down transport, top +0.50e-8 / -0.39e-8,
    second +0.33e-8 / -0.30e-8 m^3/cycle; signs exact, magnitudes within a factor 2 (the
    inter-ring volume and rod length are assumed)."""
    theta, _, sol = zeta_pack
    up, down, _ = _transport(theta, sol.starved[ring])
    for got, want in zip((up, down), table, strict=True):
        assert 0.5 < got / want < 2.0


@pytest.mark.xfail(strict=True, reason="the starved nets are small differences of up and down "
                   "flows: camtrain's top-ring net is +2.9e-11 (Yang +0.11e-8, 38x less) and the "
                   "second ring's +7.7e-10 (Yang +0.35e-9, 2.2x more); the dead-centre oil "
                   "bookkeeping that also keeps the third pass moving decides them")
@pytest.mark.parametrize("ring, net", [(0, 0.11e-8), (1, 0.35e-9)])
def test_starved_net_transport_within_a_factor_2(zeta_pack, ring, net):
    """Yang Table 6.2 (starved): net transport top +0.11e-8, second +0.35e-9 m^3/cycle; within
    a factor 2."""
    theta, _, sol = zeta_pack
    assert 0.5 < _transport(theta, sol.starved[ring])[2] / net < 2.0
