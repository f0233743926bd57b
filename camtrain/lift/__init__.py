"""Lift laws: periodic valve (or cam) lift and its first three derivatives on a cam-angle grid.

Every law is a ``LiftLaw``: build it from SI parameters (m, rad), then ``evaluate(theta)`` returns
a ``LiftCurve`` (lift, d1, d2, d3 per radian) for any cam angles, periodic over one revolution, in
the angle convention of ``camtrain.lift.base``. ``REGISTRY`` maps the deck's form names to the
classes. Each law's module is imported when its class is first asked for.
"""
from camtrain.lazy import package_attribute
from camtrain.lift.base import (
    DEG,
    MM,
    JointJump,
    LiftCurve,
    LiftLaw,
    angle_grid,
    evaluate_on_grid,
)

#: every law's class and its parts by name -> the module under camtrain.lift that holds it:
#: imported on first use (PEP 562), so that a deck pays only for the lift law it uses
_LAZY = {
    "ExpPolyLift": "exp_poly", "FourPowerLift": "four_power", "MultipolLift": "multipol",
    "Segment": "multipol", "PolynomialLift": "polynomial", "polydyne_coefficients": "polynomial",
    "Ramps": "ramps", "SplineLift": "spline", "TableLift": "table", "TableNoise": "table",
    "ElementaryHalf": "williams", "LowJerkHalf": "williams",
    "WilliamsElementaryLift": "williams", "WilliamsLowJerkLift": "williams",
}

#: the deck's form names -> the name of the law's class (``REGISTRY``: the classes themselves)
FORMS = {
    "four_power": "FourPowerLift",
    "multipol": "MultipolLift",
    "table": "TableLift",
    "exp_poly": "ExpPolyLift",
    "polynomial": "PolynomialLift",
    "williams_elementary": "WilliamsElementaryLift",
    "williams_low_jerk": "WilliamsLowJerkLift",
    "spline": "SplineLift",
}


def __getattr__(name: str):
    if name == "REGISTRY":      # every law's class: imports them all
        globals()[name] = {form: __getattr__(cls) for form, cls in FORMS.items()}
        return globals()[name]
    return package_attribute(__name__, _LAZY, name, globals())


__all__ = [
    "DEG", "MM", "REGISTRY", "ElementaryHalf", "ExpPolyLift", "FourPowerLift", "JointJump",
    "LiftCurve", "LiftLaw", "LowJerkHalf", "MultipolLift", "PolynomialLift", "Ramps", "Segment",
    "SplineLift", "TableLift", "TableNoise", "WilliamsElementaryLift", "WilliamsLowJerkLift", "angle_grid",
    "evaluate_on_grid", "polydyne_coefficients",
]
