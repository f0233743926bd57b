"""Film-thickness registry and dispatcher.

``film_thickness(method=..., **inputs)`` calls one published formula by name;
``film_thickness_methods(**inputs)`` lists the formulas whose inputs are present and whose
validity ranges contain the operating point (every element, for arrays). Inputs are keyword
arguments with the names used throughout the package:

* line contact: ``w`` [N/m], ``R`` [m];
* point contact, entrainment along x: ``W`` [N], ``Rx``, ``Ry`` [m], optional ``k``;
* point contact, entrainment at an angle: ``W``, ``R_e``, ``R_s`` [m];
* always: ``u`` [m/s] (mean entrainment speed), ``eta0`` [Pa s]; and usually ``alpha``
  [1/Pa], ``E_r`` [Pa].

Validity ranges are in each formula's own dimensionless groups: U, G, W (and k for point
contacts), plus Moes' M and L for line contacts. Where the original paper's bounds were not
available the range is marked ``range_source="nominal"``: a camtrain judgement, not a
published limit.
"""
from __future__ import annotations

import functools
import inspect

import numpy as np

from . import film_line as fl
from . import film_point as fp
from ._util import out
from .registry import Method, Registry

__all__ = ["FILM_METHODS", "film_thickness", "film_thicknesses", "film_thickness_methods",
           "film_groups"]

_LINE = ("w", "R", "u", "eta0", "alpha", "E_r")
_POINT = ("W", "Rx", "Ry", "u", "eta0", "alpha", "E_r")
_ANGLED = ("W", "R_e", "R_s", "u", "eta0", "alpha", "E_r")
_EHL_LINE = {"W": (1e-6, 1e-3), "U": (1e-14, 1e-9), "G": (1000.0, 10000.0)}
_EHL_POINT = {"k": (1.0, 8.0), "U": (1e-12, 1e-10), "W": (1e-7, 1e-5), "G": (2000.0, 6000.0)}
_HD_SOURCE = ("Hamrock & Dowson 1977 abstract (k 1-8); U, W, G spans approximate the 34 cases "
              "(U ~2 decades, W ~1 decade)")

FILM_METHODS = Registry("film thickness", [
    Method("dowson_higginson_1977", fl.dowson_higginson_1977, "line/minimum", _LINE, _EHL_LINE,
           reference="Dowson & Higginson (1977); Ball (1988) eq. 4.1"),
    Method("dowson_toyoda_1979", fl.dowson_toyoda_1979, "line/central", _LINE, _EHL_LINE,
           reference="Dowson & Toyoda (1979); Ball (1988) eq. 4.2", aliases=("dowson_toyoda_1978",)),
    Method("dowson_higginson_1966", fl.dowson_higginson_1966, "line/minimum", _LINE, _EHL_LINE,
           reference="Dowson & Higginson (1966); Göçmen (2013) eq. 2.1"),
    Method("pan_hamrock_1989_min", fl.pan_hamrock_1989_min, "line/minimum", _LINE, _EHL_LINE,
           reference="Pan & Hamrock (1989) ASME J. Tribol. 111:246"),
    Method("pan_hamrock_1989_cen", fl.pan_hamrock_1989_cen, "line/central", _LINE, _EHL_LINE,
           reference="Pan & Hamrock (1989) ASME J. Tribol. 111:246"),
    Method("moes_1992", fl.moes_1992, "line/central", _LINE, {"M": (0.1, 1e4), "L": (0.0, 25.0)},
           reference="Moes (1992) Wear 159:57 (all regimes)"),
    Method("martin_1916", fl.martin_1916, "line/minimum", ("w", "R", "u", "eta0"),
           {"M": (0.0, 1.0), "L": (0.0, 1.0)}, reference="Martin (1916), rigid-isoviscous"),
    Method("dowson_dunn_taylor_1983", fl.dowson_dunn_taylor_1983, "line/minimum",
           ("R", "u", "eta0", "alpha"), {"M": (0.0, 3.0)},
           reference="Ball (1988) eq. 4.3 (Blok limitation, Dowson, Dunn & Taylor 1983)",
           aliases=("blok", "blok_rigid_piezoviscous")),
    Method("rahnejat_1984", fl.rahnejat_1984, "line/central", _LINE, _EHL_LINE,
           reference="Rahnejat (1984); Teodorescu et al. (2005) eq. 5 (load exponent -0.059)"),
    Method("hamrock_dowson_1977_min", fp.hamrock_dowson_1977_min, "point/minimum", _POINT,
           _EHL_POINT, _HD_SOURCE, "Hamrock & Dowson (1977) Part III"),
    Method("hamrock_dowson_1977_cen", fp.hamrock_dowson_1977_cen, "point/central", _POINT,
           _EHL_POINT, _HD_SOURCE, "Hamrock & Dowson (1977) Part III"),
    Method("chittenden_1985_min", fp.chittenden_1985_min, "point/minimum", _ANGLED,
           {"U": (1e-12, 1e-10), "W": (1e-7, 1e-5), "G": (2000.0, 6000.0)},
           reference="Chittenden et al. (1985); Yang (1992) eq. 3.21"),
    Method("chittenden_1985_cen", fp.chittenden_1985_cen, "point/central", _ANGLED,
           {"U": (1e-12, 1e-10), "W": (1e-7, 1e-5), "G": (2000.0, 6000.0)},
           reference="Chittenden et al. (1985); Yang (1992) eq. 3.22"),
])

#: Preferred method when none is named, by the inputs given.
_DEFAULTS = (
    (("w", "R"), "dowson_higginson_1977"),
    (("R_e", "R_s", "W"), "chittenden_1985_min"),
    (("Rx", "Ry", "W"), "hamrock_dowson_1977_min"),
    (("R",), "dowson_dunn_taylor_1983"),
)


def film_groups(**inputs) -> dict[str, np.ndarray]:
    """Dimensionless groups the registry's validity ranges refer to, from whatever is given.

    Line contact: U, G, W, M, L. Point contact: U, G, W, k (entraining radius R_x or R_e).
    Groups that cannot be formed from the inputs are omitted.
    """
    g: dict[str, np.ndarray] = {}
    u, eta0, alpha, E_r = (inputs.get(n) for n in ("u", "eta0", "alpha", "E_r"))
    if u is None or eta0 is None or E_r is None:
        return g
    alpha = 0.0 if alpha is None else alpha
    if inputs.get("R") is not None:
        U, G, W = fl.line_groups(inputs.get("w"), inputs["R"], u, eta0, alpha, E_r)
        g.update(U=U, G=G)
        if W is not None:
            g["W"] = W
            g["M"], g["L"] = fl.moes_groups(inputs["w"], inputs["R"], u, eta0, alpha, E_r)
        else:
            g["L"] = G * (2.0 * U) ** 0.25
    for radius_name, other in (("Rx", "Ry"), ("R_e", "R_s")):
        if inputs.get(radius_name) is not None and inputs.get("W") is not None:
            U, G, W = fp.point_groups(inputs["W"], inputs[radius_name], u, eta0, alpha, E_r)
            g.update(U=U, G=G, W=W)
            if inputs.get("k") is not None:
                g["k"] = np.asarray(inputs["k"], dtype=float)
            elif inputs.get(other) is not None:
                g["k"] = np.asarray(fp.hamrock_dowson_ellipticity(inputs[radius_name],
                                                                  inputs[other]))
    return g


def _default_method(provided: set[str]) -> str:
    for needed, name in _DEFAULTS:
        if set(needed) <= provided:
            return name
    raise ValueError("give R (and w) for a line contact or W with Rx, Ry (or R_e, R_s) for a "
                     "point contact")


def film_thickness(method: str | None = None, **inputs):
    """Film thickness [m] by the named published formula (see :data:`FILM_METHODS`).

    Args:
        method: registry name or alias; default by geometry: ``dowson_higginson_1977`` (line,
            load given), ``dowson_dunn_taylor_1983`` (line, no load), ``hamrock_dowson_1977_min``
            (point) or ``chittenden_1985_min`` (point with R_e, R_s).
        **inputs: the named inputs (see module docstring). Extra inputs that the chosen formula
            does not take are ignored, so one dictionary can feed every method.

    Returns:
        h [m], float or array.

    Example:
        >>> round(film_thickness(w=2e5, R=0.02, u=1.0, eta0=0.04, alpha=2e-8, E_r=2.26e11,
        ...                      method="dowson_higginson_1977") * 1e9, 1)
        336.5
    """
    provided = {k for k, v in inputs.items() if v is not None}
    m = FILM_METHODS.get_method(method or _default_method(provided))
    missing = [r for r in m.requires if r not in provided]
    if missing:
        raise ValueError(f"method {m.name!r} needs {', '.join(missing)}")
    params = _parameters(m.func)
    return out(m.func(**{k: v for k, v in inputs.items() if k in params and v is not None}))


def film_thicknesses(methods: tuple[str, ...], **inputs) -> tuple:
    """:func:`film_thickness` of several methods on the same inputs (e.g. the minimum and the
    central film of one contact). Power-law line fits share one evaluation of their
    dimensionless groups, as the formulas are written; other methods run one by one."""
    chosen = [FILM_METHODS.get_method(name) for name in methods]
    laws = [getattr(m.func, "power_law", None) for m in chosen]
    if len(chosen) < 2 or None in laws or any(inputs.get(k) is None for k in _LINE):
        return tuple(film_thickness(method=name, **inputs) for name in methods)
    R = inputs["R"]
    groups = fl.line_groups(inputs["w"], R, inputs["u"], inputs["eta0"], inputs["alpha"],
                            inputs["E_r"])
    R = np.asarray(R, dtype=float)
    return tuple(fl.power_film_of_groups(law, R, *groups) for law in laws)


@functools.cache
def _parameters(func) -> frozenset[str]:
    """Argument names of a registered formula (cached: inspecting a signature costs more than
    evaluating a film formula over a whole cam cycle)."""
    return frozenset(inspect.signature(func).parameters)


def film_thickness_methods(check_ranges: bool = True, kind: str | None = None, **inputs):
    """Names of the film formulas applicable to the given inputs.

    Args:
        check_ranges: if True, keep only methods whose validity ranges contain every element
            of the dimensionless groups (see :func:`film_groups`).
        kind: optional filter, e.g. ``"line/central"`` or ``"point/minimum"``.
        **inputs: as :func:`film_thickness`.

    Returns:
        list of method names, in registry order.
    """
    provided = {k for k, v in inputs.items() if v is not None}
    groups = film_groups(**inputs) if check_ranges else {}
    kinds = None if kind is None else (kind,)
    return FILM_METHODS.applicable(provided, groups, check_ranges, kinds)
