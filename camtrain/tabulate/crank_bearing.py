"""Columns and metrics of one crank bearing (shared by the crank-bearing effect; not an effect).

A bearing is a result component (``big_end_1``, ``main_3``). A bearing with one grooving
treatment gets plain columns (``eccentricity``, ``min_film``, ``power``, ...); a partially
grooved one gets both extremes with a suffix (``eccentricity_ungrooved``, ``_grooved``), its
powers being their mean (FLAME). Steady-locus columns carry a ``steady_`` prefix.
"""
from __future__ import annotations

from functools import partial


def add_bearing(result, b) -> None:
    comp = f"{b.kind}_{b.index + 1}"
    what = f"{b.kind.replace('_', '-')} {b.index + 1}"
    col = partial(result.add_column, component=comp, axis="crank_angle")
    met = partial(result.add_metric, component=comp)
    several = len(b.variants) > 1
    for tag, v in b.variants.items():
        sfx = f"_{tag}" if several else ""
        label = f"{what} ({tag})" if several else what
        for prefix, orbit, how in (("", v.dynamic, "mobility orbit"),
                                   ("steady_", v.steady, "steady locus")):
            if orbit is None:
                continue
            col(f"{prefix}eccentricity{sfx}", orbit.eccentricity, "-",
                f"{label}: eccentricity ratio ({how})")
            col(f"{prefix}min_film{sfx}", orbit.h_min, "m", f"{label}: minimum film ({how})")
            col(f"{prefix}min_film_position{sfx}", orbit.position, "rad",
                f"{label}: direction of the minimum film in the bearing frame ({how})")
            col(f"{prefix}power{sfx}", orbit.power, "W", f"{label}: friction power ({how}, "
                f"{orbit.film} film)")
            if several:
                met(f"{prefix}min_film{sfx}", orbit.min_film, "m",
                    f"{label}: smallest film ({how})", orbit.min_film_angle)
        if v.dynamic is not None:
            met(f"max_eccentricity{sfx}", v.dynamic.max_eccentricity, "-",
                f"{label}: largest eccentricity ratio (orbit)")
            met(f"cycles{sfx}", v.dynamic.cycles, "-", f"{label}: engine cycles marched")
    for method, how in (("dynamic", "mobility orbit"), ("steady", "steady locus"),
                        ("petroff", "Petroff")):
        p = getattr(b, f"power_{method}")
        if p is not None:
            mean = " (mean of ungrooved and grooved)" if several else ""
            met(f"power_{method}", p, "W", f"{what}: cycle-mean power, {how}{mean}")
    for method, how in (("dynamic", "mobility orbit"), ("steady", "steady locus")):
        h, at = getattr(b, f"min_film_{method}")
        if h is not None:
            met(f"min_film_{method}", h, "m", f"{what}: smallest film ({how}; thinner "
                "treatment); angle = where on the cycle", at)
