"""The orbit march with steps free of the load grid (``steps="free"``, the default): its error
falls with the step tolerance at the fitted order of error-per-step control (smooth load), the
load interpolants converge at their orders, the grid samples from the continuous extension match
a march that stops on every grid angle, a settled cycle repeats exactly (replayed steps), and
the number of steps does not follow the load grid."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.bearings import JournalBearing, bearing_orbit
from camtrain.bearings.orbit import load_coefficients, periodic_pchip
from camtrain.errors import InputError

BRG = JournalBearing(25e-3, 18e-3, 25e-6, 0.01)
W = 157.0


def _diagram(n):
    """A smooth cam-bearing-like diagram (a steady part and a lobe pulse) on n angles."""
    th = np.arange(n) * (2 * math.pi / n)
    return 300.0 * np.sin(th), -2000.0 * (1.0 + 0.8 * np.exp(-8.0 * (1.0 - np.cos(th - 1.0)))), th


def _error(a, b):
    return float(np.max(np.hypot(a.eps_x - b.eps_x, a.eps_y - b.eps_y)))


@pytest.mark.convergence
def test_error_falls_with_the_step_tolerance_at_first_order():
    """Spline load (a smooth right-hand side), 1440 angles: the error of the free march against
    one with a step per grid interval at tol 1e-13 falls like tol^p with p fitted near 1 (error
    per step control of a 5th-order step: h ~ tol^(1/5), global error ~ h^5; measured 0.87)."""
    fx, fy, th = _diagram(1440)
    ref = bearing_orbit(BRG, fx, fy, th, W, tol=1e-13, period_tol=1e-12, steps="grid",
                        load_interpolation="spline")
    tols = np.array([1e-6, 1e-7, 1e-8, 1e-9])
    errors = [_error(bearing_orbit(BRG, fx, fy, th, W, tol=tol, period_tol=1e-12,
                                   load_interpolation="spline"), ref) for tol in tols]
    order = np.polyfit(np.log(tols), np.log(errors), 1)[0]
    assert 0.7 < order < 1.3, (errors, order)
    assert errors[-1] < 1e-8


@pytest.mark.convergence
@pytest.mark.parametrize(("interpolation", "low", "high"),
                         [("linear", 1.8, 2.2), ("pchip", 2.0, 3.2), ("spline", 3.6, 4.6)])
def test_load_interpolants_converge_at_their_orders(interpolation, low, high):
    """Orbits of the same smooth diagram sampled on 36, 72, 144, 288 angles against 2304 angles:
    the eps error falls at the interpolant's order (linear 2, spline 4; the shape-preserving
    Hermite between: its slopes are limited; measured 2.01, 2.46, 4.15)."""
    ns = np.array([36, 72, 144, 288])
    fx, fy, th = _diagram(2304)
    opts = dict(tol=1e-11, period_tol=1e-10, load_interpolation=interpolation)
    ref = bearing_orbit(BRG, fx, fy, th, W, **opts)
    errors = []
    for n in ns:
        a, b, t = _diagram(n)
        o = bearing_orbit(BRG, a, b, t, W, **opts)
        k = np.arange(n) * (2304 // n)
        errors.append(np.max(np.hypot(o.eps_x - ref.eps_x[k], o.eps_y - ref.eps_y[k])))
    order = -np.polyfit(np.log(ns), np.log(errors), 1)[0]
    assert low < order < high, (errors, order)


def test_continuous_extension_samples_the_grid_within_the_step_error():
    """Spline load, 360 angles, tol 1e-9: the free march spans several load intervals per step
    (fewer steps than intervals), so most grid samples come from the continuous extension; they
    agree with a march ending a step on every grid angle at tol 1e-13 to the step error
    (measured 4.3e-9; a wrong extension would err by about the eps change over a step, 1e-3)."""
    fx, fy, th = _diagram(360)
    ref = bearing_orbit(BRG, fx, fy, th, W, tol=1e-13, period_tol=1e-12, steps="grid",
                        load_interpolation="spline")
    free = bearing_orbit(BRG, fx, fy, th, W, tol=1e-9, period_tol=1e-12,
                         load_interpolation="spline")
    assert _steps(360, "free", tol=1e-9, interpolation="spline") < 360
    assert _error(free, ref) < 2e-8


def test_linear_load_error_stays_below_the_period_tolerance():
    """Linear load (the default): a step across the kinks at grid angles errs at order h^3,
    which the 5(4) estimate sees only in part, so the error is not proportional to tol
    (measured at 360 angles: 2.0e-6 at tol 1e-8, 2.2e-7 at 1e-9); at the camshaft decks' step
    tolerance (1e-3 of the period tolerance) it stays below the default period tolerance 1e-5."""
    fx, fy, th = _diagram(360)
    ref = bearing_orbit(BRG, fx, fy, th, W, tol=1e-13, period_tol=1e-12, steps="grid")
    errors = [_error(bearing_orbit(BRG, fx, fy, th, W, tol=tol, period_tol=1e-12), ref)
              for tol in (1e-8, 1e-9)]
    assert errors[0] < 1e-5 and errors[1] < errors[0] / 3, errors


def test_a_settled_cycle_repeats_exactly():
    """Replaying the previous cycle's steps makes the cycle-to-cycle change fall to round-off
    (1e-13 reached at a step tolerance of 1e-6; steps placed afresh each cycle would leave it
    near the march's error, about 1e-6)."""
    fx, fy, th = _diagram(1440)
    o = bearing_orbit(BRG, fx, fy, th, W, tol=1e-6, period_tol=1e-13, max_cycles=30)
    assert o.converged and o.periodicity_error <= 1e-13


def _steps(n, steps, tol=1e-7, interpolation="linear"):
    """Accepted steps in the last cycle of the compiled march (exact mobility)."""
    from camtrain.bearings import _orbit_march as M
    from camtrain.bearings._orbit_kernel import EXACT, Mobility

    fx, fy, th = _diagram(n)
    t = th / W
    T = 2 * math.pi / W
    coef = load_coefficients(t, T, fx, fy, np.full(n, 0.5 * W), interpolation)
    dts = np.append(np.diff(t), T - t[-1])
    table = (np.zeros(2), np.zeros((2, 1)), np.zeros((2, 1)))
    out = M.march_orbit(coef, t, dts, T, 0.3, -0.3, steps == "grid",
                        Mobility(EXACT, 1.0 / BRG.stiffness, *table), tol, 1e-5, 20, 200_000,
                        1 - 1e-12)
    return out[7]


def test_steps_do_not_follow_the_load_grid():
    """The same diagram on 360 and 1440 angles: the free march takes about as many steps on
    both (fewer than 360), the march ending on every grid angle at least one per interval."""
    free = [_steps(n, "free") for n in (360, 1440)]
    grid = [_steps(n, "grid") for n in (360, 1440)]
    assert max(free) < 360 and abs(free[1] / free[0] - 1) < 0.3, free
    assert grid[0] >= 360 and grid[1] >= 1440


def test_shape_preserving_interpolant_keeps_jumps_and_zero_stretches():
    """A diagram that is zero, jumps to 500 N and falls back (a lobe taking up its clearance):
    the Hermite stays within each interval's end values (no ringing into the zero stretch),
    and turns with the frame (the vector form of the slopes)."""
    n = 72
    t = np.arange(n) / n
    f = np.where((t > 0.3) & (t < 0.6), 500.0 * np.sin(np.pi * (t - 0.3) / 0.3) + 300.0, 0.0)
    data = np.column_stack((0.3 * f, -f, np.ones(n)))
    coef = periodic_pchip(t, 1.0, data)
    s = np.linspace(0.0, 1.0 / n, 9)
    values = coef[:, 0, :, None] + s * (coef[:, 1, :, None] + s * (coef[:, 2, :, None]
                                                                    + s * coef[:, 3, :, None]))
    ends = np.stack((data, np.roll(data, -1, axis=0)))
    assert np.all(values <= ends.max(axis=0)[..., None] + 1e-9)
    assert np.all(values >= ends.min(axis=0)[..., None] - 1e-9)
    zero = (f == 0.0) & (np.roll(f, -1) == 0.0)
    assert np.all(values[zero, :2] == 0.0)
    c, s_ = math.cos(0.7), math.sin(0.7)
    turned = data.copy()
    turned[:, 0], turned[:, 1] = c * data[:, 0] - s_ * data[:, 1], s_ * data[:, 0] + c * data[:, 1]
    rc = periodic_pchip(t, 1.0, turned)
    np.testing.assert_allclose(rc[:, :, 0], c * coef[:, :, 0] - s_ * coef[:, :, 1], atol=1e-9)


@pytest.mark.derived
def test_periodic_spline_is_the_standard_periodic_spline():
    """Against scipy's periodic CubicSpline on an uneven grid (the march builds its own,
    compiled, to keep scipy.interpolate out of a bearing deck's start)."""
    from scipy.interpolate import CubicSpline

    rng = np.random.default_rng(3)
    t = np.sort(rng.uniform(0.0, 2.0, 40))
    f = np.column_stack((np.sin(np.pi * t), np.cos(3 * np.pi * t) + 0.2, t * 0.0 + 1.0))
    coef = load_coefficients(t, 2.0, f[:, 0], f[:, 1], f[:, 2], "spline")
    ref = CubicSpline(np.append(t, t[0] + 2.0), np.vstack((f, f[:1])), bc_type="periodic")
    # scipy's c[k] multiplies s^(3 - k)
    np.testing.assert_allclose(coef[:, ::-1, :], np.moveaxis(ref.c, 0, 1), rtol=1e-10,
                               atol=1e-10)


@pytest.mark.parametrize(("field", "value"), [("load_interpolation", "cubic"),
                                              ("steps", "adaptive")])
def test_unknown_options_are_field_errors(field, value):
    fx, fy, th = _diagram(36)
    with pytest.raises(InputError, match=field):
        bearing_orbit(BRG, fx, fy, th, W, **{field: value})
