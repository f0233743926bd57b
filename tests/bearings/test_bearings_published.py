"""Journal bearings against published numbers (each test names its source and tolerance)."""
from __future__ import annotations

import math

import pytest

from camtrain.bearings import JournalBearing, bearing_petroff_power
from camtrain.bearings.mobility import mobility_exact
from camtrain.formulas.bearings import ocvirk_attitude_angle

RPM = 2.0 * math.pi / 60.0


def _zeta_big_end(eta_cp):
    # Yang (1992) Appendix B.4: d 46.9 mm, b 19.10 mm, c 0.0210 mm, ungrooved.
    return JournalBearing(46.9e-3, 19.10e-3, 21.0e-6, eta_cp * 1e-3)


def _zeta_main(eta_cp, grooved):
    # Appendix B.4: d 58.0 mm, b 18.30 mm (two 7.175 mm lands when grooved), c 0.0175 mm.
    g = 18.30e-3 - 2 * 7.175e-3 if grooved else 0.0
    return JournalBearing(58.0e-3, 18.30e-3, 17.5e-6, eta_cp * 1e-3, groove_width=g)


# (engine rpm, big-end cP, main cP, big-end kW, main ungrooved kW, main grooved kW), Yang (1992)
# Tables 2.1-2.4 Petroff columns; viscosities from Appendix B.6.
ZETA_PETROFF = [(3000, 2.90, 2.57, 0.0211, 0.0407, 0.0319),
                (6000, 2.07, 1.75, 0.0602, 0.1107, 0.0868)]


# Half a unit of the 4th decimal (kW) plus 1e-4 relative: the 3000 rpm ungrooved main computes
# to 40.646 W, 0.004 W below the rounding boundary of the printed 0.0407 kW (Yang's program
# probably carried fewer digits in pi or the rpm conversion); every other cell rounds exactly.
def _cell_tol(v):
    return 0.5e-4 + 1e-4 * v


@pytest.mark.parametrize("rpm, eta_be, eta_mb, be, mu, mg", ZETA_PETROFF)
def test_yang_tables_2_1_to_2_4_petroff_cells(rpm, eta_be, eta_mb, be, mu, mg):
    """Printed to 4 decimals in kW; the relative speed is the engine speed (Yang's Petroff
    column)."""
    w = rpm * RPM
    for brg, printed in ((_zeta_big_end(eta_be), be), (_zeta_main(eta_mb, False), mu),
                         (_zeta_main(eta_mb, True), mg)):
        assert bearing_petroff_power(brg, w) / 1e3 == pytest.approx(printed,
                                                                     abs=_cell_tol(printed))


@pytest.mark.parametrize("rpm, eta_be, eta_mb, total_u, total_g",
                         [(3000, 2.90, 2.57, 0.2879, 0.2439), (6000, 2.07, 1.75, 0.7943, 0.6748)])
def test_yang_tables_2_1_to_2_4_petroff_totals(rpm, eta_be, eta_mb, total_u, total_g):
    """Totals = 4 big-ends + 5 mains. Yang added the rounded cells (0.2879 = 4 x 0.0211 +
    5 x 0.0407), so the tolerance is nine half-units of the 4th decimal."""
    w = rpm * RPM
    be = bearing_petroff_power(_zeta_big_end(eta_be), w) / 1e3
    mu = bearing_petroff_power(_zeta_main(eta_mb, False), w) / 1e3
    mg = bearing_petroff_power(_zeta_main(eta_mb, True), w) / 1e3
    assert 4 * be + 5 * mu == pytest.approx(total_u, abs=9 * 0.5e-4)
    assert 4 * be + 5 * mg == pytest.approx(total_g, abs=9 * 0.5e-4)


def test_yang_table_4_1_camshaft_petroff():
    """Zeta intake camshaft bearings at 1500 rev/min camshaft (Yang Appendix C.5: d 25.97 mm,
    c 0.0225 mm, lands 9.0 and 7.5 mm, eta 0.009865 Pa s): 2.7 W (No.1) and 2.2 W (Nos 2-5),
    printed to 1 decimal; exact after rounding."""
    w = 1500 * RPM
    no1 = JournalBearing(25.97e-3, 20.0e-3, 22.5e-6, 0.009865, groove_width=2.0e-3)
    no2 = JournalBearing(25.97e-3, 17.0e-3, 22.5e-6, 0.009865, groove_width=2.0e-3)
    assert round(bearing_petroff_power(no1, w), 1) == 2.7
    assert round(bearing_petroff_power(no2, w), 1) == 2.2
    # the source's own check values to 4 significant figures
    assert bearing_petroff_power(no1, w) == pytest.approx(2.679, abs=5e-4)
    assert bearing_petroff_power(no2, w) == pytest.approx(2.232, abs=5e-4)


def test_petroff_anchor_example():
    """formulas_and_anchors §4.3: D 25, L 18 mm, c 25 um, 0.01 Pa s, 1500 rev/min -> 2.180 W
    (printed to 4 figures)."""
    b = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
    assert bearing_petroff_power(b, 1500 * RPM) == pytest.approx(2.180, abs=5e-4)


def test_booker_mobility_at_centre():
    """Yang §2.1.5 check: at eps = 0 the exact pi-film squeeze mobility is 1/(pi (b/d)^2) in
    Booker's normalisation, i.e. |w| = 2 W c^2/(pi eta r b^3). Exact up to round-off."""
    delta, m = mobility_exact(0.0, 0.3)
    assert delta == pytest.approx(0.3, abs=1e-12)
    assert m == pytest.approx(2.0 / math.pi, rel=1e-12)


def test_ocvirk_attitude_anchor_by_mobility():
    """formulas_and_anchors §4.3: the anchor bearing at eps = 0.7165 has attitude 37.40 deg.
    The exact mobility of a pure-rotation film must point the load there (1e-9 rad)."""
    from camtrain.bearings.mobility import squeeze_force
    fx, fy = squeeze_force(0.7165, -0.5 * math.pi, 1.0)
    assert -math.atan2(fy, fx) == pytest.approx(float(ocvirk_attitude_angle(0.7165)), abs=1e-9)
    assert math.degrees(-math.atan2(fy, fx)) == pytest.approx(37.40, abs=5e-3)
