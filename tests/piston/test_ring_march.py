"""A ring marched over the cycle (Yang 1992 §5.3): invariants, convergence, Zeta results
(docs/references/yang1992.md §4.4)."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.piston.gas import ATMOSPHERE, solve_labyrinth
from camtrain.piston.ring import Ring, march_ring
from tests.piston import zeta_piston as Z


def _symmetric_case(n=720, scheme="trapezoid"):
    theta = np.linspace(0.0, 4 * np.pi, n, endpoint=False)
    U = -10.0 * np.sin(theta)                       # pure harmonic stroke
    ring = Ring(height=1.5e-3, radius=0.05, offset=0.0, tension=0.3e6, roughness=0.5e-6)
    return theta, march_ring(ring, theta, U, 0.005, 1e5, 1e5, 300.0, scheme=scheme,
                             tolerance=1e-10, max_cycles=40)


def test_symmetric_barrel_gives_mirror_symmetric_films():
    """Invariant (wave2_models P12): a symmetric barrel (O = 0) under equal pressures and a
    stroke whose speed reverses exactly half a revolution later has the same film on the up- and
    down-strokes (to the cyclic tolerance)."""
    theta, rc = _symmetric_case()
    half = theta.size // 4                          # pi later on a 4 pi grid
    assert np.allclose(rc.h_min, np.roll(rc.h_min, -half), rtol=1e-6)
    assert np.allclose(rc.friction, -np.roll(rc.friction, -half), rtol=1e-6, atol=1e-9)


@pytest.mark.parametrize("scheme, order", [("trapezoid", 2.0), ("backward_euler", 1.0)])
def test_observed_order_of_the_film_march(scheme, order):
    """Convergence: successive halvings of the step (360 ... 5760 steps a cycle) change the film
    by amounts falling at the scheme's order (fitted slope within 0.2; the max-norm over the whole
    cycle, dead centres included)."""
    sizes = [360, 720, 1440, 2880, 5760]
    films = {n: _symmetric_case(n, scheme)[1].h_min for n in sizes}
    changes = [np.max(np.abs(films[n] / films[2 * n][::2] - 1.0)) for n in sizes[:-1]]
    slope = -np.polyfit(np.log(sizes[:-1]), np.log(changes), 1)[0]
    assert slope == pytest.approx(order, abs=0.2)


@pytest.fixture(scope="module")
def zeta_flooded():
    rpm = 3000
    w = rpm * np.pi / 30.0
    gas = solve_labyrinth(Z.TABLE_ANGLES, Z.cylinder_pressure(rpm), 273.15 + 750.0,
                          Z.labyrinth(rpm), w)
    theta = gas.theta[:-1]
    pc, p1 = (gas.pressures[k][:-1] - ATMOSPHERE for k in (0, 1))
    U = Z.liner(theta, rpm)
    out = {}
    for name, ring, depth, above, below in (("top", Z.TOP, 0.0, pc, p1),
                                            ("second", Z.SECOND, Z.SECOND_RING_DEPTH, p1, 0 * p1)):
        out[name] = march_ring(ring, theta, U, Z.viscosity(depth, theta, rpm), above, below, w,
                               boundary_roughness=Z.sigma(ring))
    return theta, U, out


def test_second_ring_thinnest_film_at_bdc(zeta_flooded):
    """Yang Fig. 6.6 (flooded, 3000 rpm): second-ring minimum film 0.07 um at 180 deg; angle
    +-5 deg (figure reading), value +-30 % (the inter-ring volume and rod length are assumed)."""
    theta, _, rings = zeta_flooded
    rc = rings["second"]
    i = int(np.argmin(rc.h_min))
    assert np.degrees(theta[i]) == pytest.approx(180.0, abs=5.0)
    assert rc.h_min[i] == pytest.approx(0.07e-6, rel=0.30)


def test_top_ring_thinnest_film_after_firing_tdc(zeta_flooded):
    """Yang Fig. 6.6: flooded top-ring minimum film 0.08 um at 5 deg ATDC (+-5 deg, +-30 %)."""
    theta, _, rings = zeta_flooded
    rc = rings["top"]
    i = int(np.argmin(rc.h_min))
    assert np.degrees(theta[i]) == pytest.approx(5.0, abs=5.0)
    assert rc.h_min[i] == pytest.approx(0.08e-6, rel=0.30)


def test_top_ring_peak_friction_near_firing_tdc(zeta_flooded):
    """Yang Fig. 6.7: flooded top-ring peak friction about 210 N near TDC firing (figure
    reading, +-20 %), in the boundary regime."""
    theta, _, rings = zeta_flooded
    force = rings["top"].friction * np.pi * Z.BORE
    i = int(np.argmax(np.abs(force)))
    assert abs(force[i]) == pytest.approx(210.0, rel=0.20)
    assert min(np.degrees(theta[i]), 720 - np.degrees(theta[i])) < 20.0
    assert rings["top"].boundary[i]


@pytest.mark.parametrize("ring, table", [
    ("top", (0.63e-7, -0.69e-7, -0.59e-8)), ("second", (0.48e-8, -0.92e-7, -0.87e-7))])
def test_flooded_oil_transport_table_6_2(zeta_flooded, ring, table):
    """Yang Table 6.2 (flooded, 3000 rpm), m^3/cycle, up positive: up, down and net transport;
    signs exact, magnitudes within a factor 2 (the inter-ring volume and rod length are
    assumed)."""
    theta, U, rings = zeta_flooded
    w = 3000 * np.pi / 30.0
    q = -rings[ring].flow * np.pi * Z.BORE * (theta[1] - theta[0]) / w
    up, down = q[q > 0].sum(), q[q < 0].sum()
    for got, want in zip((up, down, up + down), table, strict=True):
        assert np.sign(got) == np.sign(want)
        assert 0.5 < got / want < 2.0


def test_second_ring_consumes_more_than_the_top_ring_over_most_of_the_cycle(zeta_flooded):
    """Yang Fig. 6.8 (flooded): second-ring power above top-ring power over most of the cycle,
    except the first half of the power stroke and the late compression stroke."""
    theta, U, rings = zeta_flooded
    power = {k: r.friction * np.pi * Z.BORE * U for k, r in rings.items()}
    assert np.mean(power["second"] > power["top"]) > 0.5
    early_power = (theta > np.radians(5)) & (theta < np.radians(90))
    assert np.mean(power["top"][early_power] > power["second"][early_power]) > 0.5


def test_liner_speed_is_the_exact_slider_crank():
    """Derived cross-check: Yang's eq. 5.16 equals the piston speed of Williams' exact slider
    crank (App. A5), with the liner moving against the ring (1e-12)."""
    from camtrain.engine.crank import slider_crank_exact
    from camtrain.piston.ring import liner_speed

    theta = np.linspace(0.0, 4 * np.pi, 721)
    xd = slider_crank_exact(theta, Z.CRANK_RADIUS, Z.ROD_LENGTH, 314.0)[1]
    assert np.allclose(liner_speed(theta, Z.CRANK_RADIUS, Z.ROD_LENGTH, 314.0), xd,
                       rtol=0, atol=1e-12 * 314 * Z.CRANK_RADIUS)


def test_oil_control_ring_consumes_more_than_either_compression_ring(zeta_flooded):
    """Yang Fig. 6.14: the oil-control ring (1.890 MPa on 0.5 mm, boundary) loses more power
    than either compression ring (flooded rings, 3000 rpm)."""
    from camtrain.piston.assembly import cycle_mean_power, oil_control_ring_friction

    theta, U, rings = zeta_flooded
    ocr = cycle_mean_power(oil_control_ring_friction(U, 1.890e6, 0.5e-3, Z.BORE), U)
    for rc in rings.values():
        assert ocr > cycle_mean_power(rc.friction * np.pi * Z.BORE, U)
