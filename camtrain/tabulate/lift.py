"""The lift law on a run's angle grid as Result columns and metrics, shared by the kinematics
effect, the ``lift`` command (:func:`camtrain.api.lift`) and the studies that read the lift curve.

Lift laws, their curves and noise estimates depend only on the immutable [lift] model and the
grid, so they are built once per process and their arrays are read-only, shared between runs.
"""
from __future__ import annotations

from functools import lru_cache

from camtrain.identity_cache import by_identity


# Lift laws and their noise estimates depend only on the immutable [lift] model, so they are
# built once per process: sweeps over speed, spring or geometry reuse them (a table law's spline
# fit and noise estimate cost far more than the rest of a run).
@lru_cache(maxsize=32)
def _cached_law(lift_model):
    from camtrain.assemble.lift_law import build_lift_law

    return build_lift_law(lift_model)


@lru_cache(maxsize=32)
def lift_curve(lift_model, points: int):
    """The lift curve on the run's grid: depends only on the [lift] model and the grid, so a
    sweep over anything else evaluates it once (arrays read-only: shared between runs)."""
    from camtrain.lift import angle_grid

    curve = _cached_law(lift_model).evaluate(angle_grid(points))
    for values in (curve.theta, curve.lift, curve.d1, curve.d2, curve.d3):
        values.flags.writeable = False
    return curve


@lru_cache(maxsize=32)
def _cached_noise(lift_model):
    return _cached_law(lift_model).noise_estimate()


@lru_cache(maxsize=32)
def _cached_max_lift(lift_model) -> float:
    """Peak lift of the law (a law without a closed form evaluates 4001 points for it)."""
    return _cached_law(lift_model).max_lift


@lru_cache(maxsize=32)
def _cached_jumps(lift_model):
    return tuple(_cached_law(lift_model).joint_jumps())


def lift_columns(deck, result, points: int | None = None):
    """Evaluate the deck's lift law on the angle grid and add lift and its derivatives.

    Returns the LiftLaw and the LiftCurve for later effects.
    """
    points = points or deck.solver.angle_points
    formed, law, curve = _deck_lift(deck, points)
    if result.axes or result.columns or result.metrics:   # a result under way: one by one
        columns, metrics, warnings = _lift_outputs(deck.lift, points)
        result.add_axis(*columns[0])
        result.add_columns(columns[1:])
        result.add_metrics(metrics)
        for message in warnings:
            result.warn(message)
    else:   # a new result: the lift law's columns and metrics as formed for this law and grid
        result.axes.extend(formed.axes)
        result.columns.update(formed.columns)
        result.metrics.update(formed.metrics)
        for message in formed.warnings:
            result.warn(message)
    return law, curve


@by_identity
def _deck_lift(deck, points: int):
    """:func:`_formed_lift` of a deck model, found by its identity on a repeated run."""
    return _formed_lift(deck.lift, points)


@lru_cache(maxsize=32)
def _formed_lift(lift_model, points: int):
    """A Result holding only the lift law's axis, columns, metrics and warnings on the grid,
    with the law and its curve. Columns and metrics are immutable (their arrays read-only), so
    every run of the law on this grid takes the same ones into its own Result."""
    from camtrain.result import Result

    formed = Result()
    columns, metrics, warnings = _lift_outputs(lift_model, points)
    formed.add_axis(*columns[0])
    formed.add_columns(columns[1:])
    formed.add_metrics(metrics)
    for message in warnings:
        formed.warn(message)
    return formed, _cached_law(lift_model), lift_curve(lift_model, points)


@lru_cache(maxsize=32)
def _lift_outputs(lift_model, points: int):
    """The lift law's columns, metrics and warnings on the grid, as argument tuples for
    ``add_column`` / ``add_metric``: they depend only on the [lift] model and the grid, like
    the curve they come from, so a sweep (or a second run of a deck) forms them once."""
    import numpy as np

    law = _cached_law(lift_model)
    curve = lift_curve(lift_model, points)
    theta = curve.theta
    where = "valve" if lift_model.measured_at == "valve" else "cam (inspection follower)"
    columns = (
        ("cam_angle", theta, "rad", "cam angle from the maximum-lift position"),
        ("lift", curve.lift, "m", f"lift at the {where}"),
        ("velocity", curve.d1, "m/rad", "dl/dtheta"),
        ("acceleration", curve.d2, "m/rad^2", "d2l/dtheta2"),
        ("jerk", curve.d3, "m/rad^3", "d3l/dtheta3"),
    )
    metrics = [
        ("max_lift", _cached_max_lift(lift_model), "m", "maximum lift", 0.0),
        ("opening_angle", law.opening_angle, "rad",
         "cam angle where the event (ramp included) starts"),
        ("closing_angle", law.closing_angle, "rad",
         "cam angle where the event (ramp included) ends"),
    ]
    i = int(np.argmax(curve.d1))
    metrics.append(("max_velocity", curve.d1[i], "m/rad", "largest dl/dtheta", theta[i]))
    i = int(np.argmin(curve.d2))
    metrics.append(("min_acceleration", curve.d2[i], "m/rad^2",
                    "most negative d2l/dtheta2 (nose deceleration)", theta[i]))
    i = int(np.argmax(curve.d2))
    metrics.append(("max_acceleration", curve.d2[i], "m/rad^2", "largest d2l/dtheta2",
                    theta[i]))
    warnings: list[str] = []
    _report_law_quality(lift_model, metrics, warnings, float(np.max(np.abs(curve.d1))))
    return columns, tuple(metrics), tuple(warnings)


#: A joint of a piecewise law is warned about when lift steps by more than 1 µm or velocity by
#: more than this fraction of the peak velocity (the multipol joint tolerance): a cam must be
#: continuous in lift and velocity to be ground. Acceleration steps are reported as metrics.
#: The outer ends of constant-velocity ramps are exempt from the velocity rule: there the
#: follower leaves the base circle at the ramp velocity by design (it takes up the clearance).
_LIFT_STEP = 1e-6
_VELOCITY_STEP_FRACTION = 0.005
_RAMP_ENDS = ("opening ramp start", "closing ramp end")


def _worth_warning(j, peak_velocity: float) -> bool:
    if abs(j.lift) > _LIFT_STEP:
        return True
    return j.label not in _RAMP_ENDS and abs(j.d1) > _VELOCITY_STEP_FRACTION * peak_velocity


def _report_law_quality(lift_model, metrics: list, warnings: list,
                        peak_velocity: float) -> None:
    """Joint jumps of piecewise laws and the derivative noise of tables, as metric argument
    tuples and warnings (both computed once per lift model, see the caches above)."""
    jumps = _cached_jumps(lift_model)
    if jumps:
        for name, unit, what in (("lift", "m", "lift"), ("d1", "m/rad", "velocity"),
                                 ("d2", "m/rad^2", "acceleration"), ("d3", "m/rad^3", "jerk")):
            worst = max(jumps, key=lambda j, n=name: abs(getattr(j, n)))
            metrics.append((f"joint_jump_{what}", abs(getattr(worst, name)), unit,
                            f"largest {what} jump at a joint of the lift law", worst.angle))
        for j in jumps:
            if _worth_warning(j, peak_velocity):
                message = f"lift law is discontinuous: {j.describe()}"
                if message not in warnings:
                    warnings.append(message)
    if callable(getattr(_cached_law(lift_model), "noise_estimate", None)):
        est = _cached_noise(lift_model)
        metrics.append(("table_noise_velocity", est.d1, "m/rad",
                        "estimated RMS noise of the table-derived velocity"))
        metrics.append(("table_noise_acceleration", est.d2, "m/rad^2",
                        "estimated RMS noise of the table-derived acceleration"))
