"""Lift laws: periodic valve (or cam) lift and its first three derivatives on a cam-angle grid.

Every law is a ``LiftLaw``: build it from SI parameters (m, rad), then ``evaluate(theta)`` returns
a ``LiftCurve`` (lift, d1, d2, d3 per radian) for any cam angles, periodic over one revolution, in
the angle convention of ``camtrain.lift.base``. ``REGISTRY`` maps the deck's form names to the
classes.
"""
from camtrain.lift.base import (
    DEG,
    MM,
    JointJump,
    LiftCurve,
    LiftLaw,
    angle_grid,
    evaluate_on_grid,
)
from camtrain.lift.exp_poly import ExpPolyLift
from camtrain.lift.four_power import FourPowerLift
from camtrain.lift.multipol import MultipolLift, Segment
from camtrain.lift.polynomial import PolynomialLift, polydyne_coefficients
from camtrain.lift.ramps import Ramps
from camtrain.lift.spline import SplineLift
from camtrain.lift.table import TableLift, TableNoise
from camtrain.lift.williams import (
    ElementaryHalf,
    LowJerkHalf,
    WilliamsElementaryLift,
    WilliamsLowJerkLift,
)

REGISTRY: dict[str, type[LiftLaw]] = {
    "four_power": FourPowerLift,
    "multipol": MultipolLift,
    "table": TableLift,
    "exp_poly": ExpPolyLift,
    "polynomial": PolynomialLift,
    "williams_elementary": WilliamsElementaryLift,
    "williams_low_jerk": WilliamsLowJerkLift,
    "spline": SplineLift,
}

__all__ = [
    "DEG", "MM", "REGISTRY", "ElementaryHalf", "ExpPolyLift", "FourPowerLift", "JointJump",
    "LiftCurve", "LiftLaw", "LowJerkHalf", "MultipolLift", "PolynomialLift", "Ramps", "Segment",
    "SplineLift", "TableLift", "TableNoise", "WilliamsElementaryLift", "WilliamsLowJerkLift", "angle_grid",
    "evaluate_on_grid", "polydyne_coefficients",
]
