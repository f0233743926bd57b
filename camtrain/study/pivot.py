"""Ball's geometry rules for pivoted followers inside a sweep.

When r_B or r_f of a finger or rocker changes, Ball (1988, §5) keeps the pivot and the valve where
they are and moves the cam centre / pad centre instead, so A, D, kappa and lambda change with them.
The geometry itself is computed by :func:`camtrain.mechanisms.pivot_geometry.rescale_pivot_geometry`;
this module only translates between the raw deck (mm, deg) and that function (SI).
"""
from __future__ import annotations

import math

PIVOTED = {"finger": "end", "rocker": "central"}
TRIGGERS = ("cam.base_radius", "mechanism.follower_radius")
#: deck path -> (geometry attribute, deck unit factor to SI)
DERIVED = {
    "mechanism.A": ("A", 1e-3),
    "mechanism.D": ("D", 1e-3),
    "mechanism.kappa": ("kappa", math.pi / 180.0),
    "mechanism.lambda": ("lam", math.pi / 180.0),
}


def apply_pivot_rules(datum: dict, new: dict, changed: set[str]) -> None:
    """Rewrite A, D, kappa, lambda of ``new`` (in place) for the r_B / r_f it holds.

    Does nothing unless the deck is a finger or rocker and r_B or r_f was changed. Fields the
    user sweeps explicitly are left as given. Raises GeometryError if the new follower cannot
    touch the base circle.
    """
    mech, cam = datum.get("mechanism") or {}, datum.get("cam") or {}
    kind = PIVOTED.get(mech.get("type"))
    if kind is None or not any(path in changed for path in TRIGGERS):
        return
    needed = ("A", "B", "D", "kappa", "lambda", "follower_radius")
    if any(not isinstance(mech.get(k), int | float) for k in needed) \
            or not isinstance(cam.get("base_radius"), int | float):
        return  # an incomplete deck: validation names what is missing
    from camtrain.mechanisms.pivot_geometry import PivotGeometry, rescale_pivot_geometry

    deg = math.pi / 180.0
    geometry = PivotGeometry(A=mech["A"] * 1e-3, B=mech["B"] * 1e-3, D=mech["D"] * 1e-3,
                             follower_radius=mech["follower_radius"] * 1e-3,
                             base_radius=cam["base_radius"] * 1e-3,
                             kappa=mech["kappa"] * deg, lam=mech["lambda"] * deg, kind=kind)
    rescaled = rescale_pivot_geometry(geometry, base_radius=new["cam"]["base_radius"] * 1e-3,
                                      follower_radius=new["mechanism"]["follower_radius"] * 1e-3)
    for path, (attr, factor) in DERIVED.items():
        if path not in changed:
            # 12 significant figures: far below any tolerance, and identical on every executor
            new["mechanism"][path.split(".")[1]] = float(f"{getattr(rescaled, attr) / factor:.12g}")
