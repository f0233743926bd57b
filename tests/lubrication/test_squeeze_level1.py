"""Level 1: Teodorescu et al. (2005) eq. 5 with the squeeze term, marched implicitly."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.formulas import rahnejat_1984
from camtrain.lubrication import relaxation_step, squeeze_film_march, teodorescu_steady_film
from camtrain.lubrication.squeeze import LOAD_EXPONENTS, squeeze_ratio

E_R, ETA, ALPHA, OMEGA = 2.1e11, 0.01, 2e-8, 150.0


def cycle(n=720):
    """A cam-like cycle: entrainment through zero at +-114.6 deg, load peaking at theta = 0."""
    theta = np.linspace(-np.pi, np.pi, n, endpoint=False)
    u = 1.2 * np.cos(theta) + 0.5
    w = 3e4 * (1.0 + 0.5 * np.cos(theta))
    R = 0.012 + 0.006 * np.cos(theta) ** 2
    F = teodorescu_steady_film(w, R, u, ETA, ALPHA, E_R)
    return theta, u, w, R, F


def test_squeeze_factors_of_eq5():
    """D2 (Teodorescu eq. 5): exp(-96.775 w_s) at w_s = -0.01, +0.01, -0.001 = 2.632, 0.380,
    1.102 (three decimals, as derived in the reference notes)."""
    base = rahnejat_1984(3e4, 0.015, 1.0, ETA, ALPHA, E_R)
    for ws, factor in ((-0.01, 2.632), (0.01, 0.380), (-0.001, 1.102)):
        ratio = rahnejat_1984(3e4, 0.015, 1.0, ETA, ALPHA, E_R, squeeze_ratio=ws) / base
        assert ratio == pytest.approx(factor, abs=5e-4)


def test_zero_squeeze_is_the_steady_formula():
    """Level 1 with w_s = 0 is eq. 5 without squeeze (1e-10): the steady film function, the
    march with squeeze off, and the march at constant conditions (w_s -> 0)."""
    theta, u, w, R, F = cycle()
    steady = rahnejat_1984(w, R, u, ETA, ALPHA, E_R, squeeze_ratio=0.0, load_exponent=-0.059)
    np.testing.assert_allclose(F, steady, rtol=1e-10)
    np.testing.assert_allclose(squeeze_film_march(theta, F, u, OMEGA, squeeze=False).film, F,
                               rtol=1e-10)
    const = np.full(theta.shape, F[100])
    h = squeeze_film_march(theta, const, np.full(theta.shape, 1.1), OMEGA).film
    np.testing.assert_allclose(h, const, rtol=1e-10)


def test_march_satisfies_eq5_with_its_squeeze_ratio():
    """Each implicit step solves eq. 5 exactly: h = F exp(-96.775 w_s) with w_s from the backward
    difference of the marched film (1e-10), wherever the entrainment is non-zero."""
    theta, u, w, R, F = cycle()
    s = squeeze_film_march(theta, F, u, OMEGA)
    dt = np.diff(theta, prepend=theta[-1] - 2 * np.pi) / OMEGA
    ws = squeeze_ratio(s.film, np.roll(s.film, 1), dt, u)
    np.testing.assert_allclose(ws, s.squeeze_ratio, rtol=1e-12)
    h5 = rahnejat_1984(w, R, u, ETA, ALPHA, E_R, squeeze_ratio=ws, load_exponent=-0.059)
    moving = np.abs(u) > 1e-3
    np.testing.assert_allclose(h5[moving], s.film[moving], rtol=1e-10)


def test_film_is_trapped_at_zero_entrainment():
    """Teodorescu et al. (2005) Fig. 14, R3 of docs/references/teodorescu2005.md §4 (film minima
    at the inlet reversals, finite by squeeze-film entrapment, 0 without squeeze): the steady
    film vanishes at the reversals, the marched film stays positive there,
    and its minima sit at the reversals: here 0-3 deg after them (the film keeps relaxing while
    |u| is still small), asserted as 0-5 deg in the direction of rotation."""
    theta, u, w, R, F = cycle(1440)
    s = squeeze_film_march(theta, F, u, OMEGA)
    zeros = np.flatnonzero(np.sign(u) != np.sign(np.roll(u, -1)))
    assert zeros.size == 2
    for i in zeros:
        near = np.argmin(np.abs(u[i - 2:i + 3])) + i - 2
        assert F[near] < 0.05 * F.max()
        assert s.film[near] > 0.1 * F.max()
        window = np.arange(i - 80, i + 81) % theta.size      # +-20 deg
        j = window[np.argmin(s.film[window])]
        assert 0.0 <= np.degrees(theta[j] - theta[i]) <= 5.0
    assert np.all(s.film > 0.0)
    assert s.period_error <= 1e-9


def test_printed_load_exponent_option():
    """The printed +0.059 (named option) differs from the default by W*^0.118 exactly."""
    theta, u, w, R, F = cycle(36)
    Fp = teodorescu_steady_film(w, R, u, ETA, ALPHA, E_R, exponent="printed")
    np.testing.assert_allclose(Fp / F, (w / (E_R * R)) ** 0.118, rtol=1e-10)
    assert LOAD_EXPONENTS == {"consistent": -0.059, "printed": 0.059}
    with pytest.raises(ValueError, match="load exponent option"):
        teodorescu_steady_film(w, R, u, ETA, ALPHA, E_R, exponent="plus")


def test_step_edge_cases():
    assert relaxation_step(1e-7, 0.0, 0.0, 1e-4) == 1e-7          # no entrainment: trapped
    assert relaxation_step(1e-7, np.inf, 2.0, 1e-4) == 1e-7       # unloaded: held
    # a huge relaxation (k >> h) reaches F; a tiny one barely moves
    assert relaxation_step(1e-7, 2e-7, 1e9, 1.0) == pytest.approx(2e-7, rel=1e-9)
    assert relaxation_step(1e-7, 2e-7, 1e-9, 1e-6) == pytest.approx(1e-7, rel=1e-9)


def test_first_order_in_the_angle_step():
    """Implicit Euler: the film error at fixed angles falls as dtheta^1 (fitted slope 1 +- 0.2)
    against a 64x finer march."""
    ns = np.array([180, 360, 720, 1440])
    ref_n = 46080
    th_ref, u_r, w_r, R_r, F_r = cycle(ref_n)
    ref = squeeze_film_march(th_ref, F_r, u_r, OMEGA).film
    errs = []
    for n in ns:
        th, u, w, R, F = cycle(n)
        h = squeeze_film_march(th, F, u, OMEGA).film
        errs.append(np.max(np.abs(h - ref[:: ref_n // n]) / ref[:: ref_n // n]))
    slope = -np.polyfit(np.log(ns), np.log(errs), 1)[0]
    assert slope == pytest.approx(1.0, abs=0.2)
