"""Kinematics effect: the lift law on the run's angle grid, then the follower kinematics."""
from __future__ import annotations

import numpy as np

from camtrain.effects.lift_law import build_lift_law
from camtrain.lift import angle_grid


def lift_columns(deck, result, points: int | None = None):
    """Evaluate the deck's lift law on the angle grid and add lift and its derivatives.

    Returns the LiftLaw and the LiftCurve for later effects.
    """
    law = build_lift_law(deck.lift)
    theta = angle_grid(points or deck.solver.angle_points)
    curve = law.evaluate(theta)
    where = "valve" if deck.lift.measured_at == "valve" else "cam (inspection follower)"
    result.add_column("cam_angle", theta, "rad", "cam angle from the maximum-lift position")
    result.add_column("lift", curve.lift, "m", f"lift at the {where}")
    result.add_column("velocity", curve.d1, "m/rad", "dl/dtheta")
    result.add_column("acceleration", curve.d2, "m/rad^2", "d2l/dtheta2")
    result.add_column("jerk", curve.d3, "m/rad^3", "d3l/dtheta3")
    result.add_metric("max_lift", law.max_lift, "m", "maximum lift", 0.0)
    result.add_metric("opening_angle", law.opening_angle, "rad",
                      "cam angle where the event (ramp included) starts")
    result.add_metric("closing_angle", law.closing_angle, "rad",
                      "cam angle where the event (ramp included) ends")
    i = int(np.argmax(curve.d1))
    result.add_metric("max_velocity", curve.d1[i], "m/rad", "largest dl/dtheta", theta[i])
    i = int(np.argmin(curve.d2))
    result.add_metric("min_acceleration", curve.d2[i], "m/rad^2",
                      "most negative d2l/dtheta2 (nose deceleration)", theta[i])
    i = int(np.argmax(curve.d2))
    result.add_metric("max_acceleration", curve.d2[i], "m/rad^2", "largest d2l/dtheta2",
                      theta[i])
    _report_law_quality(law, result)
    return law, curve


#: jumps larger than these at a joint of a piecewise law are warned about (lift and velocity
#: must be continuous for a cam that can be ground; acceleration steps are reported as metrics).
#: The outer ends of constant-velocity ramps are exempt from the velocity rule: there the
#: follower leaves the base circle at the ramp velocity by design (it takes up the clearance).
_JUMP_WARN = {"lift": 1e-6, "d1": 1e-6}
_RAMP_ENDS = ("opening ramp start", "closing ramp end")


def _worth_warning(j) -> bool:
    limits = dict(_JUMP_WARN)
    if j.label in _RAMP_ENDS:
        limits.pop("d1")
    return any(abs(getattr(j, k)) > tol for k, tol in limits.items())


def _report_law_quality(law, result) -> None:
    """Joint jumps of piecewise laws and the derivative noise of tables, as metrics/warnings."""
    jumps = law.joint_jumps()
    if jumps:
        for name, unit, what in (("lift", "m", "lift"), ("d1", "m/rad", "velocity"),
                                 ("d2", "m/rad^2", "acceleration"), ("d3", "m/rad^3", "jerk")):
            worst = max(jumps, key=lambda j, n=name: abs(getattr(j, n)))
            result.add_metric(f"joint_jump_{what}", abs(getattr(worst, name)), unit,
                              f"largest {what} jump at a joint of the lift law", worst.angle)
        for j in jumps:
            if _worth_warning(j):
                result.warn(f"lift law is discontinuous: {j.describe()}")
    noise = getattr(law, "noise_estimate", None)
    if callable(noise):
        est = noise()
        result.add_metric("table_noise_velocity", est.d1, "m/rad",
                          "estimated RMS noise of the table-derived velocity")
        result.add_metric("table_noise_acceleration", est.d2, "m/rad^2",
                          "estimated RMS noise of the table-derived acceleration")


def run(deck, state) -> None:
    law, curve = lift_columns(deck, state.result)
    state.objects["lift_law"] = law
    state.objects["lift_curve"] = curve
