"""Follower kinematics: valve-lift law -> contact kinematics at every cam angle.

One module per follower family; every builder returns a :class:`Kinematics` (SI units) and
raises :class:`camtrain.errors.GeometryError` when the geometry cannot work. A family's module is
imported when one of its names is first asked for.
"""
from camtrain.lazy import package_attribute
from camtrain.mechanisms.base import ANTICLOCKWISE, CLOCKWISE, Kinematics, TrainKinematics, analyse

# `pivoted` and `desmodromic` name a module and the builder in it: importing the module (from
# anywhere) sets the package's attribute to the module, which a lazy name cannot undo, so the
# builders are bound here, after their modules
from camtrain.mechanisms.desmodromic import DesmodromicKinematics, desmodromic
from camtrain.mechanisms.pivot_geometry import PivotGeometry, rescale_pivot_geometry
from camtrain.mechanisms.pivoted import centrally_pivoted, end_pivoted, pivoted

#: the other families' builders and geometry by name -> the module under camtrain.mechanisms
#: that holds them: imported on first use (PEP 562), so that a deck pays only for its own
#: follower (a name here must not be a module's name, see above)
_LAZY = {
    "valve_lift_from_cam_lift": "conversion",
    "FourBarGeometry": "pushrod", "RockerGeometry": "pushrod", "pushrod_four_bar": "pushrod",
    "pushrod_simple": "pushrod",
    "domed": "translating", "flat_faced": "translating", "tapered_domed": "translating",
}


def __getattr__(name: str):
    return package_attribute(__name__, _LAZY, name, globals())


__all__ = [
    "ANTICLOCKWISE", "CLOCKWISE", "DesmodromicKinematics", "FourBarGeometry", "Kinematics",
    "PivotGeometry", "RockerGeometry", "analyse", "centrally_pivoted", "desmodromic", "domed",
    "end_pivoted", "flat_faced", "pivoted", "pushrod_four_bar", "pushrod_simple",
    "rescale_pivot_geometry", "tapered_domed", "TrainKinematics", "valve_lift_from_cam_lift",
]
