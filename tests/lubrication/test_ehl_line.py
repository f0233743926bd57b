"""Steady isothermal EHL line contact against the published film formulas and its limits.

Cases on a grid of Moes' (M, L) (mean-speed convention, formulas_and_anchors §4.1 of the
reference notes; docs/ehl.md): E' = 226 GPa, R = 20 mm, eta0 = 0.04 Pa s, G = alpha E' = 4500,
U = (L/G)^4/2 and W = M sqrt(2U). Tolerances: the 5 % of the acceptance criterion.
Sources: Moes (1992) Wear 159:57, the central-film eq. (four-regime interpolation);
Dowson & Higginson (1977) minimum-film eq. (Ball 1988 eq. 4.1); Pan & Hamrock (1989) ASME J.
Tribol. 111:246, minimum-film eq.; Martin (1916) rigid-isoviscous limit.
"""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.formulas.film_line import (
    dowson_higginson_1977,
    martin_1916,
    moes_1992,
    pan_hamrock_1989_min,
)
from camtrain.lubrication.ehl_elastic import ElasticKernel
from camtrain.lubrication.ehl_friction import ehl_friction
from camtrain.lubrication.ehl_line import EHLResolution, LineContact, solve_ehl_line
from camtrain.lubrication.ehl_oil import Oil

E, R, ETA0, G = 2.26e11, 0.02, 0.04, 4500.0
GRID = [(5, 5), (5, 10), (20, 10), (50, 5), (100, 10)]


def ml_contact(M, L, density="incompressible", viscosity="roelands", alpha=None, slide=0.0):
    U = (L / G) ** 4 / 2.0
    W = M * np.sqrt(2.0 * U)
    u = U * E * R / ETA0
    oil = Oil(ETA0, G / E if alpha is None else alpha, viscosity, density)
    return LineContact(W * E * R, R, E, u * (1 - slide / 2), u * (1 + slide / 2), oil)


def formula(fn, c):
    return fn(c.w, c.R, c.u_mean, c.oil.eta0, c.oil.alpha, c.E_r)


_CACHE: dict = {}


def solved(M, L, density="incompressible", nodes=1024):
    key = (M, L, density, nodes)
    if key not in _CACHE:
        _CACHE[key] = solve_ehl_line(ml_contact(M, L, density), EHLResolution(nodes=nodes))
    return _CACHE[key]


def test_dowson_higginson_density_hand_values():
    """rho/rho0 = 1 + 0.6e-9 p / (1 + 1.7e-9 p): 1.2222 at 1 GPa, 1.3529 at infinity."""
    from camtrain.formulas.density import dowson_higginson_density, dowson_higginson_density_slope

    assert dowson_higginson_density(1e9) == pytest.approx(1 + 0.6 / 2.7, rel=1e-12)
    assert dowson_higginson_density(1e15) == pytest.approx(1 + 0.6 / 1.7, rel=1e-5)
    p, dp = 5e8, 1e2
    slope = (dowson_higginson_density(p + dp) - dowson_higginson_density(p - dp)) / (2 * dp)
    assert dowson_higginson_density_slope(p) == pytest.approx(slope, rel=1e-6)


def test_fft_deflection_is_the_linear_convolution():
    """Zero-padded FFT equals the dense Toeplitz product (no wrap-around)."""
    X = np.linspace(-4.5, 1.5, 301)
    kernel = ElasticKernel.of_grid(X.size, X[1] - X[0])
    P = np.sqrt(np.maximum(1 - X**2, 0)) + 0.1 * (X < -3)
    assert np.allclose(kernel.deflection(P), kernel.dense() @ P, rtol=0, atol=1e-12)


def test_hertz_pressure_gives_a_flat_gap():
    """Hertz line contact (Johnson 1985, Contact Mechanics, ch. 5): under p_h sqrt(1 - X^2)
    the deformed gap X^2/2 + V is constant over the contact."""
    X = np.linspace(-3, 3, 2001)
    V = ElasticKernel.of_grid(X.size, X[1] - X[0]).deflection(np.sqrt(np.maximum(1 - X**2, 0)))
    gap = (X**2 / 2 + V)[np.abs(X) < 1]
    assert np.ptp(gap) < 1e-4


@pytest.mark.parametrize("M,L", GRID)
def test_central_film_matches_moes_incompressible(M, L):
    s = solved(M, L)
    assert s.h_central == pytest.approx(formula(moes_1992, s.contact), rel=0.05)


@pytest.mark.parametrize("M,L", GRID)
def test_minimum_film_matches_dowson_higginson(M, L):
    s = solved(M, L, "dowson_higginson")
    assert s.h_min == pytest.approx(formula(dowson_higginson_1977, s.contact), rel=0.05)


@pytest.mark.parametrize("M,L", GRID)
def test_minimum_film_matches_pan_hamrock(M, L):
    s = solved(M, L, "dowson_higginson")
    assert s.h_min == pytest.approx(formula(pan_hamrock_1989_min, s.contact), rel=0.05)


@pytest.mark.parametrize("M,L,nodes", [(*g, 1024) for g in GRID] + [(200, 5, 4096),
                                                                    (200, 10, 4096)])
def test_minimum_film_matches_dowson_higginson_under_its_barus_law(M, L, nodes):
    """Dowson & Higginson's formula fits solutions with the exponential (Barus) viscosity, the
    law Ball (1988, §4.1) states beside it; compared under that law (Dowson-Higginson density)
    the whole acceptance grid, M = 200 included, lies within the 5 % (measured -2.1 % ... +2.7 %,
    +3.2 % at (200, 10) on 16,384 nodes). Under Roelands (the test above, the default oil) the
    corner (200, 5) reads -5.6 %, converged: docs/ehl.md."""
    c = ml_contact(M, L, "dowson_higginson", viscosity="barus")
    s = solve_ehl_line(c, EHLResolution(nodes=nodes))
    assert s.h_min == pytest.approx(formula(dowson_higginson_1977, c), rel=0.05)


@pytest.mark.parametrize("M,L", GRID)
def test_compressibility_lowers_the_central_film(M, L):
    """Against Moes, 6-23 % lower with Dowson-Higginson density (the acceptance range of this
    solver, docs/ehl.md; an independent crude solver gave 8 % at case A, formulas_and_anchors
    §4.1)."""
    s = solved(M, L, "dowson_higginson")
    drop = 1.0 - s.h_central / formula(moes_1992, s.contact)
    assert 0.06 <= drop <= 0.23


@pytest.mark.parametrize("L", [5, 10])
def test_heavy_load_m200_on_4096_points(L):
    """M = 200, the top of the acceptance grid, on 4,096 nodes (b/683; on the default 1,024 the
    central film is 8.3 % and 7.0 % below Moes): the incompressible central film within 5 % of
    Moes (measured -4.9 %, -4.3 %; -4.7 %, -4.1 % on 16,384 nodes) and, with the
    Dowson-Higginson density, the minimum film within 5 % of Pan-Hamrock (-0.9 %, +4.3 %).
    Dowson-Higginson's minimum film is not met at L = 5 (-5.6 %, converged; docs/ehl.md)."""
    s = solved(200, L, nodes=4096)
    assert s.h_central == pytest.approx(formula(moes_1992, s.contact), rel=0.05)
    d = solved(200, L, "dowson_higginson", nodes=4096)
    assert d.h_min == pytest.approx(formula(pan_hamrock_1989_min, d.contact), rel=0.05)


def test_light_load_tends_to_martin():
    """Rigid-isoviscous limit (M = 0.05, alpha = 0): h_min = 4.895 eta0 u_m R / w."""
    c = ml_contact(0.05, 5, viscosity="barus", alpha=0.0)
    s = solve_ehl_line(c, EHLResolution(nodes=2048))
    assert s.h_min == pytest.approx(martin_1916(c.w, c.R, c.u_mean, ETA0), rel=0.01)


def test_high_load_tends_to_hertz_with_the_spike_near_the_outlet():
    s = solved(200, 10)
    X = s.x / s.b
    inside = np.abs(X) < 0.9
    assert np.abs(s.p / s.p_h - np.sqrt(np.maximum(1 - X**2, 0)))[inside].max() < 0.01
    assert 0.9 < s.x_spike / s.b < 1.0


@pytest.mark.convergence
def test_observed_order_of_the_central_film():
    """Fitted order of h_central on 257..2049 nodes (fixed domain), upwind2: about 2."""
    c = ml_contact(20, 10)
    h = [solve_ehl_line(c, EHLResolution(nodes=n, inlet=-4.5, outlet=1.5)).h_central
         for n in (257, 513, 1025, 2049)]
    d = np.abs(np.diff(h))
    observed = np.log2(d[:-1] / d[1:])
    assert 1.5 < observed.min() and observed.max() < 2.5, observed


def test_friction_eyring_below_newtonian_and_rolling_without_sliding():
    sliding = solve_ehl_line(ml_contact(20, 10, slide=0.1), EHLResolution(nodes=512))
    newton = ehl_friction(sliding)
    eyring = ehl_friction(sliding, "eyring", eyring_stress=5e6)
    assert 0 < eyring.sliding < newton.sliding
    assert ehl_friction(solved(20, 10)).sliding == 0.0


def test_cli_ehl_prints_and_writes(tmp_path):
    from click.testing import CliRunner

    from camtrain.cli import main

    args = ["ehl", "--load", "200", "--radius", "20", "--speed", "1", "--eta0", "0.04",
            "--alpha", "20", "--nodes", "256", "--out", str(tmp_path)]
    result = CliRunner().invoke(main, args)
    assert result.exit_code == 0, result.output
    assert "central film h_c" in result.output and "µm" in result.output
    assert (tmp_path / "ehl.csv").read_text().startswith("x [mm],p [MPa],h [µm]")
    assert (tmp_path / "ehl.png").stat().st_size > 0


def test_cli_ehl_rejects_a_negative_load(tmp_path):
    from click.testing import CliRunner

    from camtrain.cli import main

    result = CliRunner().invoke(main, ["ehl", "--load", "-1", "--radius", "20", "--speed", "1",
                                       "--eta0", "0.04", "--alpha", "20", "--out",
                                       str(tmp_path / "o")])
    assert result.exit_code == 2 and "--load" in result.output
    assert not (tmp_path / "o").exists()


def test_matrix_free_steps_give_the_dense_solution():
    """GMRES steps above dense_nodes converge to the dense Newton's solution."""
    c = ml_contact(20, 10, "dowson_higginson")
    dense = solve_ehl_line(c, EHLResolution(nodes=1500, dense_nodes=4000))
    free = solve_ehl_line(c, EHLResolution(nodes=1500, dense_nodes=400))
    assert free.h_central == pytest.approx(dense.h_central, rel=1e-7)
    assert free.h_min == pytest.approx(dense.h_min, rel=1e-7)
    assert np.abs(free.p - dense.p).max() < 1e-6 * dense.p_h


def test_multilevel_grids_end_on_a_small_dense_grid():
    """The preconditioner's grids coarsen by four down to at most COARSEST nodes, whatever
    the fine grid: no dense factorisation grows with n."""
    from camtrain.lubrication.ehl_krylov import COARSEST, coarse_grids
    from camtrain.lubrication.ehl_line import _discrete

    fine, _ = _discrete(ml_contact(20, 10), EHLResolution(nodes=65536))
    sizes = [g.X.size for g in coarse_grids(fine)]
    assert sizes == [16384, 4096, 1024, 256] and sizes[-1] <= COARSEST
    assert all(g.X[0] == fine.X[0] and g.X[-1] == fine.X[-1] for g in coarse_grids(fine))


def test_four_grid_preconditioner_gives_the_dense_solution(monkeypatch):
    """With the coarsest dense grid forced down to 64 nodes, 1500 points go through three
    coarse grids (375, 94 and 24 nodes, the last one dense): the dense Newton's solution."""
    from camtrain.lubrication import ehl_krylov

    c = ml_contact(20, 10, "dowson_higginson")
    dense = solve_ehl_line(c, EHLResolution(nodes=1500, dense_nodes=4000))
    monkeypatch.setattr(ehl_krylov, "COARSEST", 64)
    assert [g.X.size for g in ehl_krylov.coarse_grids(_fine(c, 1500))] == [375, 94, 24]
    free = solve_ehl_line(c, EHLResolution(nodes=1500, dense_nodes=400))
    assert free.h_central == pytest.approx(dense.h_central, rel=1e-7)
    assert free.h_min == pytest.approx(dense.h_min, rel=1e-7)
    assert np.abs(free.p - dense.p).max() < 1e-6 * dense.p_h


def _fine(contact, nodes):
    from camtrain.lubrication.ehl_line import _discrete
    return _discrete(contact, EHLResolution(nodes=nodes))[0]


def _case_a_spike(density: str, nodes: int) -> float:
    """Outlet spike height [p_h] of case A (M = 10.5, L = 9.3, Roelands) on ``nodes`` points
    over -12.47 .. 1.5 b (spacing b / (nodes / 14))."""
    c = LineContact(2e5, 0.02, 2.26e11, 1.0, 1.0, Oil(0.04, 2e-8, "roelands", density))
    s = solve_ehl_line(c, EHLResolution(nodes=nodes))
    return s.p_spike / s.p_h


@pytest.mark.slow   # make test-all: about 10 s of CPU (32,768 points twice)
def test_outlet_spike_converges_compressible_and_not_incompressible():
    """Case A on uniform grids of b/586, b/1173, b/2346. With the Dowson-Higginson density
    the spike's height converges: the differences fall by more than 2 (observed order 1.9
    measured) and the b/1173 height lies within 1 % of the Richardson value (0.3 %; b/586:
    1.1 %). Incompressible,
    its height keeps growing by more than 10 % per halving (2.23, 2.77, 3.13 p_h measured;
    3.76 at b/4691): the spike narrows with the grid (docs/ehl.md, "The spike")."""
    sizes = (8192, 16384, 32768)
    dh = [_case_a_spike("dowson_higginson", n) for n in sizes]
    d1, d2 = dh[1] - dh[0], dh[2] - dh[1]
    assert 0 < d2 < d1 / 2
    order = np.log2(d1 / d2)
    richardson = dh[2] + d2 / (2**order - 1)
    assert abs(dh[1] / richardson - 1) < 0.01
    inc = [_case_a_spike("incompressible", n) for n in sizes]
    assert all(b > 1.1 * a for a, b in zip(inc, inc[1:], strict=False))
