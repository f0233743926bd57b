"""The starved ring pack (Yang 1992 §5.4, Table 6.1, Table 6.2; docs/references/yang1992.md §4.4)."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.piston.gas import ATMOSPHERE, solve_labyrinth
from camtrain.piston.pack import PackRing, pass_change, solve_pack
from camtrain.piston.ring import piston_position
from tests.piston import zeta_piston as Z

RPM = 3000


def _case():
    w = RPM * np.pi / 30.0
    gas = solve_labyrinth(Z.TABLE_ANGLES, Z.cylinder_pressure(RPM), 273.15 + 750.0,
                          Z.labyrinth(RPM), w)
    theta = gas.theta[:-1]
    pc, p1 = (gas.pressures[k][:-1] - ATMOSPHERE for k in (0, 1))
    pack = [PackRing(Z.TOP, 0.0, pc, p1, Z.viscosity(0.0, theta, RPM), Z.sigma(Z.TOP)),
            PackRing(Z.SECOND, Z.SECOND_RING_DEPTH, p1, 0 * p1,
                     Z.viscosity(Z.SECOND_RING_DEPTH, theta, RPM), Z.sigma(Z.SECOND))]
    travel = piston_position(theta, Z.CRANK_RADIUS, Z.ROD_LENGTH)
    return pack, theta, Z.liner(theta, RPM), travel, w


def _pack(passes=None, start=None):
    """The Zeta pack at 3000 rpm: to its fixed point (``passes`` None), or Yang's procedure
    with ``passes`` starved passes (carried on from ``start``)."""
    pack, theta, U, travel, w = _case()
    mode = {} if passes is None else {"pass_mode": "yang1992", "passes": passes}
    return theta, U, solve_pack(pack, theta, U, travel, w, start=start, **mode)


@pytest.fixture(scope="module")
def zeta_pack():
    return _pack()


@pytest.fixture(scope="module")
def yang_pack():
    return _pack(2)


@pytest.mark.parametrize("mode", ["zeta_pack", "yang_pack"])
def test_continuity_holds_at_every_angle(mode, request):
    """Yang eq. 5.34: a starved ring never draws more oil through its inlet than the layer it is
    given brings (the inflow; the outflow differs from it by the oil the squeeze moves). Where
    even an inlet at the minimum gap would draw more, the film splits into streamers that draw
    the whole layer (tests/piston/test_ring_film.py): equality. At the fixed point and after
    Yang's two passes."""
    theta, U, sol = request.getfixturevalue(mode)
    for rc in sol.starved:
        fed = np.isfinite(rc.supply) & (U != 0.0)
        drawn = rc.inflow[fed] * np.sign(U[fed])         # forward, in the direction of entrainment
        assert np.all(drawn <= np.abs(U[fed]) * rc.supply[fed] * (1 + 1e-9) + 1e-18)


def test_starved_layers_are_recorded_where_fed(zeta_pack):
    """The pack records each starved ring's supply where it is fed and NaN where it is flooded:
    the bottom ring is flooded on the downstroke (Yang §5.4), the top ring never."""
    _, U, sol = zeta_pack
    top, bottom = sol.starved
    assert np.all(np.isfinite(top.supply[U != 0.0]))
    assert np.all(np.isnan(bottom.supply[U < 0.0]))
    assert np.all(np.isfinite(bottom.supply[U > 0.0]))


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


def test_the_passes_reach_the_fixed_point_and_a_further_pass_changes_nothing(zeta_pack):
    """Yang Table 6.1 (a further pass changes nothing) at the pack's fixed point: the passes
    stop within the pass tolerance (1e-3 of a ring's largest film and layer), and one more pass
    moves no film by more than 1e-3 (or 0.1 nm, a dry ring at the march's floor), with
    continuity (eq. 5.34) still holding at every angle."""
    theta, U, sol = zeta_pack
    assert sol.converged and 2 <= sol.passes and sol.pass_change < 1e-3
    _, _, more = _pack(1, start=sol)
    for a, b in zip(sol.starved, more.starved, strict=True):
        assert pass_change(a, b) < 1e-3
        assert np.allclose(b.h_min, a.h_min, rtol=1e-3, atol=1e-10)
        fed = np.isfinite(b.supply) & (U != 0.0)
        assert np.all(b.inflow[fed] * np.sign(U[fed])
                      <= np.abs(U[fed]) * b.supply[fed] * (1 + 1e-9) + 1e-18)


@pytest.mark.xfail(strict=True, reason="Yang's two passes are not the pack's fixed point: a "
                   "third pass changes the top ring at 222 of 720 angles (its largest film and "
                   "layer change 4.7 times their largest value; net +5.49e-10 -> +3.13e-10 "
                   "m^3). In pass 2 the top ring meets, just after TDC, the second ring's pass-1 "
                   "downstroke layer, but the second ring's film there is a squeeze film that "
                   "remembers its starved upstroke, which pass 2 changes: Table 6.1 marks it "
                   "correct after pass 1. Carried on, the passes converge (17 passes to 1e-3; "
                   "test above)")
def test_a_third_of_yangs_passes_changes_nothing(yang_pack):
    """Yang Table 6.1: two starved passes reach the fixed point for any number of rings."""
    _, _, three = _pack(1, start=yang_pack[2])
    for a, b in zip(three.starved, yang_pack[2].starved, strict=True):
        assert np.allclose(a.h_min, b.h_min, rtol=1e-3, atol=1e-10)


def test_a_third_pass_leaves_the_bottom_ring_unchanged(yang_pack):
    """Yang Table 6.1: the bottom ring's films depend only on the flooded downstroke and on the
    top ring's upstroke, which pass 2 has already fixed: pass 3 reproduces them."""
    _, _, three = _pack(1, start=yang_pack[2])
    assert np.allclose(three.starved[-1].h_min, yang_pack[2].starved[-1].h_min, rtol=1e-9,
                       atol=0.0)


def _peaks(sol):
    return tuple(np.max(np.abs(rc.friction)) * np.pi * Z.BORE
                 for rc in (sol.starved[0], sol.flooded[0]))


def test_starved_top_ring_friction_is_relieved(zeta_pack):
    """Yang Fig. 6.11 against Fig. 6.7: the starved top ring's peak friction is below the
    flooded one's ('load relief': the gas on the exposed face, eq. 5.17)."""
    starved, flooded = _peaks(zeta_pack[2])
    assert starved < flooded


@pytest.mark.xfail(strict=True, reason="camtrain's starved top ring peaks at 100.0 N at 10 deg "
                   "ATDC at the pack's fixed point (100.1 N after Yang's two passes; Yang ~140 N): "
                   "the dry ring ruptures at its minimum gap (0.743 of "
                   "1.484 mm) and the 66.6 bar of the chamber on the face past it (eq. 5.17's "
                   "x_4) relieves 4.94 of its 10.18 kN/m; Yang's 140 N is the chamber gas on "
                   "0.49 mm of the face, and he prints no rule for a starved ring's outlet x_4")
def test_starved_top_ring_peak_friction_is_140_newton(zeta_pack):
    """Yang Fig. 6.11: starved top-ring peak friction about 140 N (+-20 %, figure reading)."""
    starved, _ = _peaks(zeta_pack[2])
    assert starved == pytest.approx(140.0, rel=0.2)


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


NET_XFAIL = {
    ("zeta_pack", 0): "at the fixed point the top ring's starved net is +3.03e-10 m^3 (Yang "
    "+0.11e-8: 0.28 of it), the difference of +3.09e-9 up and -2.78e-9 down, each within 40 % "
    "of Yang's: Yang's top ring carries more oil up than his second ring, which continuity "
    "forbids at a fixed point and which he blames on his dead-centre oil (§6.3)",
    ("zeta_pack", 1): "at the fixed point the second ring's starved net is +7.16e-10 m^3, 2.04 "
    "times Yang's +0.35e-9 (up +3.63e-9 and down -2.92e-9, within 10 % of Yang's): the top "
    "ring's oil that Yang's two passes leave above it reaches the second ring",
    ("yang_pack", 0): "after Yang's two passes the top ring's starved net is +5.49e-10 m^3 (Yang "
    "+0.11e-8: 0.499 of it), the difference of +3.77e-9 up and -3.23e-9 down, each within "
    "25 % of Yang's",
}


@pytest.mark.parametrize("mode, ring, net", [
    pytest.param(mode, ring, net, marks=[pytest.mark.xfail(strict=True, reason=NET_XFAIL[
        mode, ring])] if (mode, ring) in NET_XFAIL else [])
    for mode in ("zeta_pack", "yang_pack") for ring, net in ((0, 0.11e-8), (1, 0.35e-9))])
def test_starved_net_transport_within_a_factor_2(mode, ring, net, request):
    """Yang Table 6.2 (starved): net transport top +0.11e-8, second +0.35e-9 m^3/cycle; within
    a factor 2, at the pack's fixed point and after Yang's two passes."""
    theta, _, sol = request.getfixturevalue(mode)
    assert 0.5 < _transport(theta, sol.starved[ring])[2] / net < 2.0
