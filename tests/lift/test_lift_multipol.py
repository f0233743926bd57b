"""Ball's multipol on the App F desmodromic data (Ball 1988 App F.1.1).

App F prints C4 of segment 3 as +.08113. With -.08113 lift, velocity, acceleration and jerk are
continuous at every joint; with the printed sign the velocity steps 0.350 -> 0.220 mm/deg at the
segment 3/4 joint. camtrain uses the corrected sign by default.
"""
from __future__ import annotations

import numpy as np
import pytest
from _lift_cases import problem

from camtrain.errors import InputError
from camtrain.lift import DEG, MM, MultipolLift, Ramps, Segment
from camtrain.lift.multipol import BALL_APP_F


def _jumps(law):
    return {j.label: j.in_mm_deg() for j in law.joint_jumps()}


def test_corrected_app_f_is_continuous_at_every_segment_joint():
    """Corrected data: every segment joint (and the nose) continuous in lift, velocity,
    acceleration and jerk to the rounding of the 5-decimal coefficients: the largest residual
    steps are 8e-6 mm/deg, 7.1e-6 mm/deg^2 and 4.5e-6 mm/deg^3 (derived), so bounds of 1e-5
    are the data's own precision."""
    jumps = _jumps(MultipolLift.ball_desmo())
    segment_joints = [k for k in jumps if "segment" in k and "ramp" not in k] + ["nose"]
    assert len(segment_joints) == 9
    for k in segment_joints:
        j = jumps[k]
        assert abs(j["lift_mm"]) < 1e-12
        assert abs(j["d1_mm_per_deg"]) < 1e-5, k
        assert abs(j["d2_mm_per_deg2"]) < 1e-5, k
        assert abs(j["d3_mm_per_deg3"]) < 1e-5, k


def test_corrected_app_f_values_at_seg3_seg4_joint_and_nose():
    """Derived from the corrected App F table: at the seg 3/4 joint v = 0.22042 mm/deg, a = 0,
    j = -0.0020 mm/deg^3; peak 0.3333 + 6.9592 = 7.2925 mm; nose velocity 0. Tolerances are
    half a unit of the last printed digit."""
    law = MultipolLift.ball_desmo()
    theta = -(55.0 - 3.0 - 8.0 - 5.0) * DEG             # seg 3/4 joint: 16 deg after ramp end
    c = law.evaluate(np.array([theta + 1e-9, 0.0]))
    assert c.d1[0] / MM * DEG == pytest.approx(0.22042, abs=5e-6)
    assert abs(c.d2[0] / MM * DEG**2) < 5e-6
    assert c.d3[0] / MM * DEG**3 == pytest.approx(-0.0020, abs=5e-5)
    assert law.max_lift / MM == pytest.approx(7.2925, abs=5e-5)
    assert c.lift[1] / MM == pytest.approx(7.29254, abs=1e-9)
    assert abs(c.d1[1] / MM * DEG) < 1e-5


def test_ramp_length_is_derived_from_the_first_segment_velocity():
    """Segment 1 starts at 0.012333 mm/deg with zero acceleration, so a constant-velocity ramp
    of 0.3333 mm lasts 27.0 deg (derived); the ramp then joins without a velocity
    step, and the half event spans ramp + 55 deg of segments."""
    law = MultipolLift.ball_desmo()
    assert law.ramps.opening_length / DEG == pytest.approx(27.0, abs=0.05)
    assert law.opening_angle / DEG == pytest.approx(-(55.0 + 27.0243), abs=1e-3)
    j = _jumps(law)["opening ramp / segment 1"]
    assert abs(j["d1_mm_per_deg"]) < 1e-12 and abs(j["d2_mm_per_deg2"]) < 1e-12
    assert _jumps(law)["opening ramp start"]["d1_mm_per_deg"] == pytest.approx(0.012333, 1e-4)


def test_printed_sign_reports_the_velocity_step():
    """Printed +.08113: the seg 3/4 joint steps in velocity 0.350 -> 0.220 mm/deg, and the
    peak becomes 7.4548 mm (derived from the printed table)."""
    law = MultipolLift.ball_desmo(corrected=False)
    j = _jumps(law)["opening segment 3 / segment 4"]
    assert j["d1_mm_per_deg"] == pytest.approx(0.22042 - 0.35022, abs=1e-4)
    assert abs(j["d2_mm_per_deg2"]) > 0.01
    assert law.max_lift / MM == pytest.approx(7.4548, abs=5e-5)


def test_printed_sign_is_rejected_when_continuity_is_checked():
    with pytest.raises(InputError) as err:
        MultipolLift.ball_desmo(corrected=False, check_continuity=True)
    p = problem(err.value)
    assert p.path == "lift.multipol.segments[2]"
    assert "velocity jumps" in p.message and "mm/deg" in p.message


def _app_f_segments():
    return [Segment(ln * DEG, [c * MM for c in cs]) for ln, cs in BALL_APP_F]


def test_separate_closing_chain_and_unequal_ramps():
    """A closing chain of its own (here the same segments with a higher, longer ramp) gives an
    asymmetric event that still meets at the nose without a step."""
    segs = _app_f_segments()
    law = MultipolLift(segs, closing_segments=segs,
                       ramps=Ramps(0.3333 * MM, None, 0.5 * MM, 40.0 * DEG),
                       check_continuity=False)
    assert law.closing_angle / DEG == pytest.approx(95.0)
    nose = _jumps(law)["nose"]
    assert abs(nose["lift_mm"]) == pytest.approx(0.5 - 0.3333, abs=1e-9)
    symmetric = MultipolLift(segs, closing_segments=segs, ramps=Ramps(0.3333 * MM, None))
    assert _jumps(symmetric)["nose"]["lift_mm"] == pytest.approx(0.0, abs=1e-12)


def test_start_lift_overrides_the_chain():
    """An explicit start lift that breaks the chain is caught as a lift step (1 um limit)."""
    segs = _app_f_segments()
    segs[1] = Segment(segs[1].length, segs[1].coefficients, start_lift=0.5 * MM)
    with pytest.raises(InputError) as err:
        MultipolLift(segs, ramps=Ramps(0.3333 * MM, None))
    assert problem(err.value).path == "lift.multipol.segments[0]"
    assert "lift jumps" in err.value.render()


@pytest.mark.parametrize("build, path", [
    (lambda s: MultipolLift(s * 2, ramps=Ramps(0.3333 * MM, None)), "lift.multipol.segments"),
    (lambda s: MultipolLift([Segment(s[0].length, [1e-4] * 6)] + s[1:]),
     "lift.multipol.segments[0].coefficients"),
    (lambda s: MultipolLift(s, max_order=4), "lift.multipol.segments[2].coefficients"),
    (lambda s: MultipolLift([Segment(-3 * DEG, s[0].coefficients)] + s[1:]),
     "lift.multipol.segments[0].length"),
    (lambda s: MultipolLift([Segment(3 * DEG, [np.inf, 0.0])] + s[1:]),
     "lift.multipol.segments[0].coefficients[0]"),
    (lambda s: MultipolLift(s, ramps=Ramps(0.3333 * MM, 200 * DEG)), "lift.multipol.segments"),
])
def test_bad_input_names_the_field(build, path):
    with pytest.raises(InputError) as err:
        build(_app_f_segments())
    assert problem(err.value).path == path
