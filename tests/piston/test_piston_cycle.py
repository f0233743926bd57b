"""The piston assembly as one chain (gas -> ring pack -> OCR, skirt) and the liner thermal model
(Yang 1992 §5.3, App. D.3-D.4; docs/references/yang1992.md §4.4)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.piston.cycle import CompressionRing, PistonCase, PistonOptions, solve_piston
from camtrain.piston.thermal import ViscosityLaw, liner_temperature
from tests.piston import zeta_piston as Z
from tests.piston.test_pack import _pack

RPM = 3000
ZETA_OIL = ViscosityLaw((95.0, 135.0), (0.009865, 0.005123))


def zeta_case(rpm=RPM, **changes):
    t = Z.TEMPERATURES[rpm]
    rings = (CompressionRing(Z.TOP, Z.GAP, 0.0, t[1]),
             CompressionRing(Z.SECOND, Z.GAP, Z.SECOND_RING_DEPTH, t[2]))
    args = dict(bore=Z.BORE, crank_radius=Z.CRANK_RADIUS, rod_length=Z.ROD_LENGTH, rings=rings,
                radial_clearance=Z.RADIAL_CLEARANCE, separations=(Z.SEPARATION,),
                chamber_temperature=t[0], liner_temperatures=t[3:], viscosity=ZETA_OIL,
                liner_roughness=Z.LINER_ROUGHNESS, ocr_tension=1.890e6, ocr_height=0.5e-3)
    args.update(changes)
    return PistonCase(**args)


def zeta_pressure(rpm=RPM):
    p = Z.cylinder_pressure(rpm) - Z.ATMOSPHERE
    return lambda th: np.interp(np.mod(th, 4 * np.pi), Z.TABLE_ANGLES, p, period=4 * np.pi)


@pytest.fixture(scope="module")
def zeta_assembly():
    return solve_piston(zeta_case(), zeta_pressure(), RPM * math.pi / 30.0, cylinders=4)


@pytest.mark.derived
def test_exponential_law_slope_from_the_two_printed_points():
    """Yang App. D.4: 0.009865 Pa s at 95 degC and 0.005123 at 135 degC; ln eta linear in T has
    slope ln(0.005123/0.009865)/40 = -0.01638 /degC (reference notes, 4 digits)."""
    slope = math.log(ZETA_OIL(136.0) / ZETA_OIL(135.0))
    assert slope == pytest.approx(-0.01638, abs=5e-6)
    assert ZETA_OIL([95.0, 135.0]) == pytest.approx([0.009865, 0.005123], rel=1e-12)


@pytest.mark.derived
def test_vogel_law_passes_through_its_three_points():
    law = ViscosityLaw((40.0, 100.0, 150.0), (0.060, 0.010, 0.004), "vogel")
    assert law([40.0, 100.0, 150.0]) == pytest.approx([0.060, 0.010, 0.004], rel=1e-10)
    a, b, c = law.vogel_constants()
    assert b > 0 and c > -40.0


@pytest.mark.derived
def test_liner_temperature_is_the_quadratic_through_the_three_values():
    """Yang §5.3: the quadratic through the liner's top, mid-stroke and bottom temperatures
    (the same fit as numpy's polyfit through the three nodes)."""
    s = 2 * Z.CRANK_RADIUS
    x = np.linspace(0.0, s, 7)
    fit = np.polyfit([0.0, s / 2, s], [185.0, 170.0, 160.0], 2)
    assert liner_temperature(x, s, 185.0, 170.0, 160.0) == pytest.approx(np.polyval(fit, x),
                                                                         rel=1e-12)


@pytest.mark.derived
def test_assembly_chain_equals_the_hand_wired_pack():
    """The chain (labyrinth from the deck data, viscosity from the liner profile) gives the very
    films of the ring pack wired by hand from the same App. D data (tests/piston/test_pack.py):
    the assembly adds no physics of its own. Compared on Yang's two passes, a fixed sequence of
    operations: over the 17 converged passes the round-off of the inputs grows to 3e-8 of the
    friction at 3 angles."""
    _, _, pack = _pack(2)
    chain = solve_piston(zeta_case(), zeta_pressure(), RPM * math.pi / 30.0, cylinders=4,
                        options=PistonOptions(pass_mode="yang1992", passes=2))
    for mine, ref in zip(chain.pack.starved, pack.starved, strict=True):
        assert mine.h_min == pytest.approx(ref.h_min, rel=1e-9)
        assert mine.friction == pytest.approx(ref.friction, rel=1e-9, abs=1e-9)


@pytest.mark.derived
def test_power_sums_and_the_printed_2_pi_option(zeta_assembly):
    """Power of one assembly = rings + OCR (no skirt); the engine's is x cylinders; Yang's printed
    eq. 5.32 divisor 2 pi (``yang1992``) is exactly twice the 4 pi time mean."""
    a = zeta_assembly
    assert a.power == pytest.approx(sum(a.ring_power) + a.ocr_power, rel=1e-12)
    assert a.engine_power == pytest.approx(4 * a.power, rel=1e-12)
    ocr = 0.08 * 1.890e6 * 0.5e-3 * math.pi * Z.BORE * np.mean(np.abs(a.liner_speed))
    assert a.ocr_power == pytest.approx(ocr, rel=1e-12)
    compat = solve_piston(zeta_case(), zeta_pressure(), RPM * math.pi / 30.0, 4,
                          PistonOptions(power_mean="yang1992"))
    assert compat.power == pytest.approx(2 * a.power, rel=1e-12)


@pytest.mark.derived
def test_a_uniform_skirt_adds_its_couette_power():
    """Yang eq. 5.37 with a uniform clearance: the skirt power is pi D L eta U^2 / C averaged
    over the cycle at the liner viscosity where the skirt is."""
    case = zeta_case(skirt_height=0.03, skirt_depth=0.02, skirt_x=(0.0, 0.03),
                     skirt_clearance=(20e-6, 20e-6))
    w = RPM * math.pi / 30.0
    out = solve_piston(case, zeta_pressure(), w, 1, PistonOptions(passes=0, pass_mode="yang1992"))
    eta = case.eta(0.02, out.theta)
    expected = np.mean(math.pi * Z.BORE * 0.03 / 20e-6 * eta * out.liner_speed ** 2)
    assert out.skirt_power == pytest.approx(expected, rel=1e-9)
    assert out.power == pytest.approx(sum(out.ring_power) + out.ocr_power + out.skirt_power)
