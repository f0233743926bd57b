"""Illinois regula falsi helpers of the compiled kernels (camtrain.numerics.roots): hand
computations on a known root, the Illinois halving and its convergence."""
from __future__ import annotations

import math

import pytest

from camtrain.numerics.roots import false_position, false_position_mean, illinois_update


def test_false_position_is_the_secant_zero_in_both_roundings():
    # the secant through (1, -1) and (3, 3) crosses zero at 1.5
    assert false_position(1.0, -1.0, 3.0, 3.0) == 1.5
    assert false_position_mean(1.0, -1.0, 3.0, 3.0) == 1.5
    # a straight line is solved in one point whatever the bracket
    assert false_position(0.0, -2.0, 10.0, 18.0) == pytest.approx(1.0, rel=1e-15)


def test_update_replaces_the_end_of_the_trial_sign():
    assert illinois_update(0.0, -1.0, 2.0, 1.0, 0.5, -0.25, 0) == (0.5, -0.25, 2.0, 1.0, -1)
    assert illinois_update(0.0, -1.0, 2.0, 1.0, 1.5, 0.25, 0) == (0.0, -1.0, 1.5, 0.25, 1)


def test_update_halves_an_end_kept_twice_in_a_row():
    # lo moved last time (side -1) and moves again: hi, kept twice, has its value halved
    assert illinois_update(0.5, -0.25, 2.0, 1.0, 0.7, -0.1, -1) == (0.7, -0.1, 2.0, 0.5, -1)
    # hi moved last time and moves again: lo's value is halved
    assert illinois_update(0.0, -1.0, 1.5, 0.25, 1.2, 0.1, 1) == (0.0, -0.5, 1.2, 0.1, 1)
    # the ends alternate: nothing is halved
    assert illinois_update(0.5, -0.25, 2.0, 1.0, 1.5, 0.25, -1) == (0.5, -0.25, 1.5, 0.25, 1)


def _solve(f, lo, hi, point, iterations):
    f_lo, f_hi, side = f(lo), f(hi), 0
    x = lo
    for _ in range(iterations):
        x = point(lo, f_lo, hi, f_hi)
        fx = f(x)
        if fx == 0.0:
            break
        lo, f_lo, hi, f_hi, side = illinois_update(lo, f_lo, hi, f_hi, x, fx, side)
    return x


@pytest.mark.parametrize("point", [false_position, false_position_mean])
def test_converges_to_a_known_root_where_plain_false_position_stalls(point):
    # x^3 - 2 on (0, 2): plain regula falsi keeps the end 2 for ever and creeps in from below
    # (error still ~7e-5 after 12 points); the Illinois halving reaches 2^(1/3) to rounding
    root = 2.0 ** (1.0 / 3.0)
    f = lambda x: x ** 3 - 2.0                                              # noqa: E731
    assert _solve(f, 0.0, 2.0, point, 12) == pytest.approx(root, rel=1e-14)
    lo, f_lo, hi, f_hi = 0.0, -2.0, 2.0, 6.0
    for _ in range(12):
        x = point(lo, f_lo, hi, f_hi)
        lo, f_lo = x, f(x)                       # without halving only lo ever moves here
    assert abs(lo - root) > 1e-5
    assert math.isclose(_solve(math.cos, 0.0, 3.0, point, 30), math.pi / 2, rel_tol=1e-14)
