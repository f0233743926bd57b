"""Desmodromic pair of Ball (1988) App F: opening cam + centrally pivoted follower, closing cam
(negative lift, negated as Ball does) + end-pivoted follower."""
from __future__ import annotations

import numpy as np
import pytest
from numpy.polynomial import Polynomial

from camtrain.errors import InputError
from camtrain.lift.base import LiftCurve, angle_grid
from camtrain.mechanisms import PivotGeometry, desmodromic

from .lifts import APP_F_SEGMENTS, desmo_lift, negated

MM, DEG = 1e-3, np.pi / 180
OMEGA = 2 * np.pi * 2000 / 60
OPENING = PivotGeometry(26.23 * MM, 33.29 * MM, 39.32 * MM, 35.0 * MM, 17.5 * MM,
                        172.69 * DEG, 125.28 * DEG)
CLOSING = PivotGeometry(17.32 * MM, 32.39 * MM, 39.32 * MM, 20.0 * MM, 25.0 * MM,
                        -7.31 * DEG, 9.41 * DEG)


def test_app_f_multipol_is_continuous_with_the_corrected_coefficient():
    """Reference §3.6: with C4(seg 3) = -0.08113 the joints are continuous; the peak lift is
    7.2925 mm (Ball prints 10.50 for the opening pair, an unresolved conflict)."""
    level = 0.3333
    ends = []
    for length, coef in APP_F_SEGMENTS:
        p = Polynomial([level] + coef)
        ends.append([p.deriv(n)(0.0) / length ** n for n in (1, 2)]
                    + [p.deriv(n)(1.0) / length ** n for n in (1, 2)])
        level = p(1.0)
    for left, right in zip(ends[:-1], ends[1:], strict=True):
        assert right[:2] == pytest.approx(left[2:], abs=2e-4)
    assert level == pytest.approx(7.2925, abs=1e-4)
    assert desmo_lift(np.array([0.0])).lift[0] / MM == pytest.approx(7.2925, abs=1e-4)


@pytest.mark.parametrize("rotation", ["clockwise", "anticlockwise"])
def test_desmodromic_pair(rotation):
    theta = angle_grid(1440)
    lift = desmo_lift(theta)
    pair = desmodromic(lift, negated(lift), OPENING, CLOSING, omega=OMEGA, rotation=rotation)
    assert pair.opening.mechanism == "desmodromic opening pair"
    assert np.allclose(pair.closing.valve_lift, lift.lift)           # negated back to positive
    base = np.abs(theta) > 90 * DEG
    for k, rb in ((pair.opening, 17.5 * MM), (pair.closing, 25.0 * MM)):
        assert np.allclose(k.cam_radius[base], rb)
        assert np.allclose(k.v_cam[base], OMEGA * rb)
        assert np.all(k.rocker_ratio > 0) and np.all(np.isfinite(k.rocker_ratio))
    # the same pair given a closing lift that is already positive
    again = desmodromic(lift, lift, OPENING, CLOSING, omega=OMEGA, rotation=rotation)
    assert np.allclose(again.closing.cam_radius, pair.closing.cam_radius)


def test_closing_lift_as_given():
    """negate_closing=False analyses the closing follower with its own (negative) lift: the
    closing cam then dips below its base circle and its nose radius exceeds r_B (Ball §8)."""
    theta = angle_grid(1440)
    lift = desmo_lift(theta)
    pair = desmodromic(lift, negated(lift), OPENING, CLOSING, omega=OMEGA, negate_closing=False)
    k = pair.closing
    assert k.cam_lift.min() < -1 * MM
    assert k.cam_radius[np.argmin(np.abs(theta))] > 25 * MM


def test_closing_lift_must_not_change_sign():
    theta = angle_grid(360)
    lift = desmo_lift(theta)
    mixed = LiftCurve(theta, lift.lift - 1 * MM, lift.d1, lift.d2, lift.d3)
    with pytest.raises(InputError, match="closing"):
        desmodromic(lift, mixed, OPENING, CLOSING, omega=OMEGA)
