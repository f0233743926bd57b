"""The FLAME sum (Yang 1992 Part IV, Table 7.1; docs/references/yang1992.md §4.5) and the
oil-control ring (§5.5)."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.engine.flame import flame_total, fmep, partial_groove_mean
from camtrain.piston.assembly import oil_control_ring_friction, skirt_friction
from tests.piston import zeta_piston as Z

#: Yang Table 7.1 [kW]: speed -> bearings, valve train, piston assembly, accessories, total.
TABLE_7_1 = {2000: (0.275, 0.446, 1.480, 0.551, 2.751), 3000: (0.552, 0.667, 2.080, 0.825, 4.124),
             4000: (0.836, 0.866, 2.876, 1.144, 5.722), 5000: (1.203, 1.031, 3.660, 1.474, 7.368),
             6000: (1.604, 1.153, 4.472, 1.807, 9.036), 6400: (1.785, 1.187, 4.800, 1.943, 9.714),
             7000: (2.074, 1.223, 5.264, 2.140, 10.701)}
DISPLACEMENT = np.pi / 4 * Z.BORE ** 2 * 2 * Z.CRANK_RADIUS * 4      # ASSUMED bore and stroke


@pytest.mark.parametrize("rpm", sorted(TABLE_7_1))
def test_accessories_and_total_table_7_1(rpm):
    """Yang Table 7.1: accessories = 0.25 x the components and the total their sum, to the
    printed 1 W (two rounded entries: 2 W)."""
    b, vt, p, acc, total = TABLE_7_1[rpm]
    row = flame_total(b * 1e3, vt * 1e3, p * 1e3, displacement=DISPLACEMENT,
                      engine_speed=rpm / 60)
    assert row.accessories == pytest.approx(acc * 1e3, abs=2.0)
    assert row.total == pytest.approx(total * 1e3, abs=2.0)


def test_bearing_column_is_the_partial_groove_mean():
    """Yang Tables 2.1-2.4 -> 7.1: 3000 rpm (0.5140 + 0.5900)/2 = 0.552 kW; 6000 rpm
    (1.4681 + 1.7397)/2 = 1.6039 kW (printed 1.604)."""
    assert partial_groove_mean(0.5140, 0.5900) == pytest.approx(0.552, abs=5e-4)
    assert partial_groove_mean(1.4681, 1.7397) == pytest.approx(1.604, abs=5e-4)


def test_fmep_at_3000_rpm():
    """4.124 kW at 3000 rpm over the 1.796 L of the assumed bore and stroke: 91.8 kPa
    (wave2_models §3.1 F8; print precision 0.1 kPa)."""
    assert DISPLACEMENT == pytest.approx(1.796e-3, abs=5e-7)
    assert fmep(4124.0, DISPLACEMENT, 3000 / 60) == pytest.approx(91.8e3, abs=50.0)


def test_shares_and_crossover_statements():
    """Yang Part IV statements on Table 7.1: shares without accessories at 3000 rpm 17/20/63 %
    and at 6000 rpm 22/16/62 % (whole percent); bearings below the valve train at 2000-3000 and
    above from 5000 rpm; the piston assembly more than twice any other component."""
    for rpm, shares in ((3000, (17, 20, 63)), (6000, (22, 16, 62))):
        b, vt, p, *_ = TABLE_7_1[rpm]
        row = flame_total(b, vt, p, displacement=DISPLACEMENT, engine_speed=rpm / 60)
        got = [100 * row.share(k) for k in ("bearings", "valve_train", "piston")]
        assert got == pytest.approx(shares, abs=0.5)
    for rpm, (b, vt, p, *_rest) in TABLE_7_1.items():
        assert (b < vt) if rpm <= 3000 else (b > vt) if rpm >= 5000 else True
        assert p > 2 * max(b, vt)


def test_oil_control_ring_force():
    """Yang §5.5: F = mu T_ocr b_ocr pi D with mu 0.08 (derived, exact), along the liner."""
    U = np.array([-3.0, 0.0, 5.0])
    force = oil_control_ring_friction(U, 1.890e6, 0.5e-3, Z.BORE)
    assert force == pytest.approx(0.08 * 1.890e6 * 0.5e-3 * np.pi * Z.BORE * np.sign(U))


def test_skirt_is_a_couette_film():
    """Yang eq. 5.37 for a uniform clearance: pi D eta U L / C (derived, 1e-12)."""
    f = skirt_friction(10.0, 0.005, Z.BORE, 0.03, [0.0, 0.015, 0.03], [20e-6, 20e-6, 20e-6])
    assert f == pytest.approx(np.pi * Z.BORE * 0.005 * 10.0 * 0.03 / 20e-6, rel=1e-12)
