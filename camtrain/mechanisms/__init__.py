"""Follower kinematics: valve-lift law -> contact kinematics at every cam angle.

One module per follower family; every builder returns a :class:`Kinematics` (SI units) and
raises :class:`camtrain.errors.GeometryError` when the geometry cannot work.
"""
from camtrain.mechanisms.base import ANTICLOCKWISE, CLOCKWISE, Kinematics, TrainKinematics, analyse
from camtrain.mechanisms.conversion import valve_lift_from_cam_lift
from camtrain.mechanisms.desmodromic import DesmodromicKinematics, desmodromic
from camtrain.mechanisms.pivot_geometry import PivotGeometry, rescale_pivot_geometry
from camtrain.mechanisms.pivoted import centrally_pivoted, end_pivoted, pivoted
from camtrain.mechanisms.pushrod import FourBarGeometry, RockerGeometry, pushrod_four_bar, pushrod_simple
from camtrain.mechanisms.translating import domed, flat_faced, tapered_domed

__all__ = [
    "ANTICLOCKWISE", "CLOCKWISE", "DesmodromicKinematics", "FourBarGeometry", "Kinematics",
    "PivotGeometry", "RockerGeometry", "analyse", "centrally_pivoted", "desmodromic", "domed",
    "end_pivoted", "flat_faced", "pivoted", "pushrod_four_bar", "pushrod_simple",
    "rescale_pivot_geometry", "tapered_domed", "TrainKinematics", "valve_lift_from_cam_lift",
]
