"""The half-Sommerfeld exit condition of the steady EHL line contact, against closed forms.

Rigid-isoviscous limit (M = 0.01, L = 5, alpha = 0): the full-Sommerfeld pressure of a rigid
cylinder near a plane, h = h0 (1 + xi^2), xi = x / sqrt(2 R h0), from d/dx(h^3 dp/dx) =
12 eta0 u_m dh/dx with p = 0 at both ends of the symmetric domain [-a, a]:

    p = 12 eta0 u_m sqrt(2 R h0) / h0^2 [I2(xi) - I2(-A) - k (I3(xi) - I3(-A))],
    I2(t) = t / (2 (1 + t^2)) + atan(t)/2,  (the integral of (1 + t^2)^-2)
    I3(t) = t / (4 (1 + t^2)^2) + 3 t / (8 (1 + t^2)) + 3 atan(t)/8,  (of (1 + t^2)^-3)
    k = (I2(A) - I2(-A)) / (I3(A) - I3(-A)),  A = a / sqrt(2 R h0)

antisymmetric in x; for a -> infinity k = 4/3 and p = -4 eta0 u_m sqrt(2 R h0) xi / (h0^2
(1 + xi^2)^2), whose positive half carries w = 4 eta0 u_m R / h0 (Hamrock, Schmid & Jacobson
2004, the half-Sommerfeld infinitely long cylinder), against Martin's 4.895 eta0 u_m R / h_min
with the Reynolds exit condition: at the same load the half-Sommerfeld film is the thinner,
by the factor 4 / 4.895.
"""
from __future__ import annotations

import numpy as np
import pytest
from click.testing import CliRunner

from camtrain.lubrication.ehl_line import EHLResolution, solve_ehl_line

from .test_ehl_line import ETA0, ml_contact

pytestmark = pytest.mark.derived

_SOLVED: dict = {}


def rigid(nodes: int, cavitation: str):
    key = (nodes, cavitation)
    if key not in _SOLVED:
        c = ml_contact(0.01, 5, viscosity="barus", alpha=0.0)
        _SOLVED[key] = solve_ehl_line(c, EHLResolution(nodes=nodes, cavitation=cavitation))
    return _SOLVED[key]


def _i2(t):
    return t / (2 * (1 + t * t)) + np.arctan(t) / 2


def _i3(t):
    return t / (4 * (1 + t * t) ** 2) + 3 * t / (8 * (1 + t * t)) + 3 * np.arctan(t) / 8


def full_sommerfeld(x, h0, R, eta0, u_m, a):
    """The closed form of the module docstring on [-a, a] [Pa]."""
    scale = np.sqrt(2 * R * h0)
    xi, A = x / scale, a / scale
    k = (_i2(A) - _i2(-A)) / (_i3(A) - _i3(-A))
    return 12 * eta0 * u_m * scale / h0**2 * (_i2(xi) - _i2(-A) - k * (_i3(xi) - _i3(-A)))


def _error(s) -> float:
    c = s.contact
    exact = full_sommerfeld(s.x, s.h_min, c.R, ETA0, c.u_mean, s.x[-1])
    return float(np.abs(s.p_sommerfeld - exact).max() / exact.max())


def test_rigid_pressure_is_the_full_sommerfeld_solution_to_second_order():
    """Measured: 0.38 % of the peak at 512 points, 0.095 % at 1,024 (order 2.0)."""
    coarse, fine = rigid(512, "half_sommerfeld"), rigid(1024, "half_sommerfeld")
    assert fine.x[0] == pytest.approx(-fine.x[-1])            # the outlet mirrors the inlet
    e_coarse, e_fine = _error(coarse), _error(fine)
    assert e_fine < 2e-3
    assert np.log2(e_coarse / e_fine) > 1.6
    P = fine.p_sommerfeld
    assert np.abs(P + P[::-1]).max() < 2e-3 * P.max()           # antisymmetric
    assert fine.p.min() == 0.0 and P.min() < -0.9 * P.max()      # negative half dropped


def test_load_from_the_positive_half_thins_the_film_against_reynolds():
    """At the same load: h_min(half-Sommerfeld) / h_min(Reynolds) = 4 / 4.895 (rigid)."""
    hs, rey = rigid(1024, "half_sommerfeld"), rigid(1024, "reynolds")
    c = hs.contact
    assert np.trapezoid(hs.p, hs.x) == pytest.approx(c.w, rel=2e-3)
    assert hs.h_min < rey.h_min
    assert hs.h_min / rey.h_min == pytest.approx(4.0 / 4.895, rel=0.01)


def test_cli_ehl_half_sommerfeld_and_a_bad_value():
    from camtrain.cli import main

    base = ["ehl", "--load", "200", "--radius", "20", "--speed", "1", "--eta0", "0.04",
            "--alpha", "20", "--nodes", "256"]
    ok = CliRunner().invoke(main, base + ["--cavitation", "half_sommerfeld"])
    assert ok.exit_code == 0, ok.output
    assert "central film h_c" in ok.output
    bad = CliRunner().invoke(main, base + ["--cavitation", "sommerfeld"])
    assert bad.exit_code == 2 and "--cavitation" in bad.output and "sommerfeld" in bad.output
    with pytest.raises(ValueError, match="cavitation 'sommerfeld'"):
        EHLResolution(cavitation="sommerfeld")


def test_cycle_march_half_sommerfeld_keeps_negative_pressures_out_of_the_load():
    """The entrainment reversal of the march's tests with ``half_sommerfeld``: the film stays
    positive, the recorded pressures are the kept ones (>= 0), and the balance of the kept
    film does not close (measured 6.7e-3, as the Reynolds condition's; Elrod-Adams 1.7e-6)."""
    from .test_ehl_transient import reversal

    u, out = reversal("half_sommerfeld")
    assert np.all(out.h_min > 0.0) and np.all(out.p_max > 0.0)
    assert np.nanmin(out.map_p) >= 0.0
    assert np.nanmax(out.mass_error) > 1e-3


def test_deck_rejects_a_bad_cavitation_with_exit_2(tmp_path):
    from camtrain.cli import main
    from tests.conftest import DECKS

    text = (DECKS / "gocmen_table31.toml").read_text()
    text = text.replace('film_model = "averaged_reynolds"',
                        'film_model = "ehl"\nehl_cavitation = "sommerfeld"')
    bad = tmp_path / "bad.toml"
    bad.write_text(text)
    res = CliRunner().invoke(main, ["check", str(bad)])
    assert res.exit_code == 2, res.output
    assert "tribology.ehl_cavitation" in res.output and "sommerfeld" in res.output
    assert "half_sommerfeld" in res.output and "Traceback" not in res.output
