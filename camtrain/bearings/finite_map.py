"""Finite-length mobility map: the orbit's Booker mobility computed from the Reynolds solution.

Route (Booker 1965's mobility method with a numerical film, as in Childs, Moes & van Leeuwen
1977's impedance approach): the quasi-static film force depends only on the eccentricity and the
journal-centre velocity ``w`` seen from the frame turning at wbar, and is positively homogeneous
in ``w`` for the half-Sommerfeld and Swift-Stieber conditions. So one table over (eps, delta),
delta the direction of ``w`` from the line of centres, describes every load, speed and orbit of
one b/d.

Table: the finite film force is written as camtrain's short-bearing force times a smooth
complex correction, ``G(eps, delta) = K_short(eps, delta) C(eps, delta)`` (``G`` per unit
``(2/3)(b/d)^3 12 eta R^4 |w| / c^2``, i.e. ``C = 1`` is Ocvirk's pi film). The short-bearing
factor carries the singular growth as eps -> 1 in closed form; ``log C`` is smooth and is
solved on a coarse (eps, delta) grid (mirror symmetry: delta in [0, pi] suffices) and
interpolated by bicubic splines. The mobility map (:class:`~.mobility_map.MobilityMap`) is then
filled on a fine polar grid by inverting ``G`` for the direction of the load (arg G is monotone
in delta because the film's squeeze work is positive).

Costs: ~200 Reynolds solutions per (b/d, cavitation, mesh); kept per process and, when the cache
directory is writable, on disk (``$CAMTRAIN_CACHE`` or ``~/.cache/camtrain``).
"""
from __future__ import annotations

import hashlib
import math
import os
from functools import lru_cache
from pathlib import Path

import numpy as np

from camtrain.errors import field_error

from .geometry import JournalBearing
from .mobility_map import MobilityMap

__all__ = ["MAP_EPS", "correction_table", "finite_impedance", "finite_mobility_map",
           "bearing_mobility_map",
           "short_impedance"]

#: Eccentricities of the Reynolds solutions behind a map (denser towards the wall).
MAP_EPS = (0.0, 0.15, 0.3, 0.45, 0.6, 0.7, 0.78, 0.85, 0.9, 0.93, 0.95, 0.965, 0.975, 0.983,
           0.99)
MAP_DELTAS = 13  # 0 .. pi every 15 deg
_VERSION = 1


def _sommerfeld(beta, eps):
    m = np.rint(beta / (2.0 * np.pi))
    b0 = beta - 2.0 * np.pi * m
    k = np.sqrt((1.0 - eps) / (1.0 + eps))
    return 2.0 * np.arctan2(k * np.sin(0.5 * b0), np.cos(0.5 * b0)) + 2.0 * np.pi * m


def short_impedance(eps, delta):
    """Complex pi-film short-bearing force K w for unit w at angle delta from the line of
    centres (vectorised :func:`camtrain.bearings.mobility.squeeze_force`)."""
    eps, delta = np.broadcast_arrays(np.asarray(eps, float), np.asarray(delta, float))
    a = delta + 0.5 * np.pi
    g0, g1 = _sommerfeld(a, eps), _sommerfeld(a + np.pi, eps)
    s0, c0, s1, c1 = np.sin(g0), np.cos(g0), np.sin(g1), np.cos(g1)
    q = 1.0 - eps * eps
    dg = g1 - g0
    d2 = 0.5 * (s1 * c1 - s0 * c0)
    icc = (0.5 * dg + d2 - 2.0 * eps * (s1 - s0) + eps * eps * dg) / q ** 2.5
    ics = (0.5 * (s1 * s1 - s0 * s0) + eps * (c1 - c0)) / q ** 2
    iss = (0.5 * dg - d2) / q ** 1.5
    cd, sd = np.cos(delta), np.sin(delta)
    return (icc * cd + ics * sd) + 1j * (ics * cd + iss * sd)


def _mesh_for(eps: float, n_theta: int, n_z: int) -> tuple[int, int]:
    """Circumferential nodes grow as 1/sqrt(1 - eps): the pressure peak narrows with the film."""
    need = 4 * math.ceil(6.0 / math.sqrt(1.0 - eps))
    return max(n_theta, need), n_z


def _cache_file(key: str) -> Path | None:
    root = os.environ.get("CAMTRAIN_CACHE")
    base = Path(root) if root else Path.home() / ".cache" / "camtrain"
    return base / "bearing_maps" / f"{key}.npz"


def correction_table(b_over_d: float, cavitation: str = "reynolds", n_theta: int = 72,
                     n_z: int = 6, disk: bool = True):
    """log C on (MAP_EPS x delta in [0, pi]); cached per process and on disk."""
    return _correction_table(round(float(b_over_d), 12), cavitation, int(n_theta), int(n_z),
                             bool(disk))


@lru_cache(maxsize=32)
def _correction_table(b_over_d, cavitation, n_theta, n_z, disk):
    from .reynolds import CAVITATION, FilmGrid, solve_film

    if cavitation not in ("half_sommerfeld", "reynolds"):
        raise field_error("cavitation", "a mobility map needs a quasi-static film condition",
                          cavitation, "half_sommerfeld or reynolds",
                          "the mass-conserving film (jfo) has a history; use it at steady load")
    assert cavitation in CAVITATION
    key = hashlib.sha1(repr((_VERSION, b_over_d, cavitation, n_theta, n_z, MAP_EPS,
                             MAP_DELTAS)).encode()).hexdigest()[:16]
    path = _cache_file(key) if disk else None
    if path is not None and path.exists():
        try:
            with np.load(path) as data:
                return data["eps"], data["delta"], data["log_c"]
        except (OSError, ValueError, KeyError):
            pass
    eps = np.array(MAP_EPS)
    delta = np.linspace(0.0, np.pi, MAP_DELTAS)
    log_c = np.empty((eps.size, delta.size), dtype=complex)
    scale = 2.0 / 3.0 * b_over_d ** 3
    for i, e in enumerate(eps):
        grid = FilmGrid(b_over_d, *_mesh_for(e, n_theta, n_z))
        for j, d in enumerate(delta):
            f = solve_film(grid, float(e), w_r=math.cos(d), w_t=math.sin(d),
                           cavitation=cavitation)
            log_c[i, j] = np.log(complex(f.force_r, f.force_t) / scale
                                 / complex(short_impedance(e, d)))
    if path is not None:
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.with_suffix(f".{os.getpid()}.tmp.npz")
            np.savez(tmp, eps=eps, delta=delta, log_c=log_c)
            os.replace(tmp, path)
        except OSError:
            pass
    return eps, delta, log_c


def _spline(eps, delta, log_c):
    """Bicubic splines of Re and Im log C over eps and a periodic, mirrored delta axis."""
    from scipy.interpolate import RectBivariateSpline

    d_half = delta[1:]
    d_full = np.concatenate([-d_half[::-1], delta])  # [-pi, pi]
    c_full = np.concatenate([np.conj(log_c[:, 1:][:, ::-1]), log_c], axis=1)
    d_ext = np.concatenate([d_full[:-1] - 2 * np.pi, d_full, d_full[1:] + 2 * np.pi])
    c_ext = np.concatenate([c_full[:, :-1], c_full, c_full[:, 1:]], axis=1)
    re = RectBivariateSpline(eps, d_ext, c_ext.real, kx=3, ky=3)
    im = RectBivariateSpline(eps, d_ext, c_ext.imag, kx=3, ky=3)

    def log_correction(e, d):
        d = np.mod(np.asarray(d) + np.pi, 2 * np.pi) - np.pi
        return re(e, d, grid=False) + 1j * im(e, d, grid=False)

    return log_correction


def finite_impedance(b_over_d: float, eps, delta, cavitation: str = "reynolds",
                     n_theta: int = 72, n_z: int = 6):
    """Interpolated finite-film force G = K_short C (units of :func:`short_impedance`)."""
    table = correction_table(b_over_d, cavitation, n_theta, n_z)
    lc = _spline(*table)
    return short_impedance(eps, delta) * np.exp(lc(eps, delta))


@lru_cache(maxsize=32)
def finite_mobility_map(b_over_d: float, *, lands: int = 1, length_ratio: float | None = None,
                        cavitation: str = "reynolds", n_theta: int = 72, n_z: int = 6,
                        n_eps: int = 160, n_angle: int = 144) -> MobilityMap:
    """Booker mobility map of a finite bearing whose lands have ratio ``b_over_d``.

    Args:
        b_over_d: land length / diameter (the whole length when ungrooved).
        lands: 1, or 2 for a full central groove (each land carries half the load).
        length_ratio: overall b/d used by the map's normalisation (default lands * b_over_d;
            give it when a groove makes the overall length longer than the lands).
        n_theta, n_z: Reynolds mesh of the table (n_theta grows as 1/sqrt(1 - eps)).
        n_eps, n_angle: resolution of the interpolated polar map.
    """
    if lands not in (1, 2):
        raise field_error("lands", "must be 1 or 2", lands)
    overall = lands * b_over_d if length_ratio is None else float(length_ratio)
    eps_t, delta_t, log_c = correction_table(b_over_d, cavitation, n_theta, n_z)
    lc = _spline(eps_t, delta_t, log_c)
    top = float(eps_t[-1])
    s = np.linspace(0.0, 1.0, n_eps)
    eps = top * (1.0 - (1.0 - s) ** 2)  # denser near the wall
    eps[0] = 0.0
    d_fine = np.linspace(-np.pi, np.pi, 721)
    ang = np.arange(n_angle) * (2.0 * np.pi / n_angle)
    tau = np.mod(-ang + np.pi, 2 * np.pi) - np.pi  # load direction from the line of centres
    m_xi = np.empty((n_eps, n_angle))
    m_mu = np.empty((n_eps, n_angle))
    for i, e in enumerate(eps):
        g = short_impedance(e, d_fine) * np.exp(lc(np.full_like(d_fine, e), d_fine))
        arg = np.unwrap(np.angle(g))
        # arg G rises by 2 pi over one turn of delta; place tau inside the branch
        t = np.where(tau < arg[0], tau + 2 * np.pi, tau)
        t = np.where(t > arg[-1], t - 2 * np.pi, t)
        delta = np.interp(t, arg, d_fine)
        gmag = np.abs(short_impedance(e, delta) * np.exp(lc(np.full_like(delta, e), delta)))
        m = overall / (2.0 * lands * b_over_d ** 3 * gmag)
        m_xi[i] = m * np.cos(ang + delta)
        m_mu[i] = m * np.sin(ang + delta)
    return MobilityMap(eps, m_xi, m_mu, f"finite-{cavitation}(b/d={b_over_d:g})")


def bearing_mobility_map(bearing: JournalBearing, cavitation: str = "reynolds",
                         n_theta: int = 72, n_z: int = 6) -> MobilityMap:
    """The finite map of ``bearing`` (its lands, its groove), normalised by its overall length."""
    lands = 2 if bearing.grooved else 1
    return finite_mobility_map(bearing.land / bearing.diameter, lands=lands,
                               length_ratio=bearing.length / bearing.diameter,
                               cavitation=cavitation, n_theta=n_theta, n_z=n_z)
