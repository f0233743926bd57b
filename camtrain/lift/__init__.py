"""Lift laws: periodic valve (or cam) lift and its first three derivatives on a cam-angle grid."""
from camtrain.lift.base import LiftCurve, angle_grid

__all__ = ["LiftCurve", "angle_grid"]
