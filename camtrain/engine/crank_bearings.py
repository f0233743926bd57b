"""Big-end and main-bearing orbits, films and friction power of a whole in-line engine.

Each bearing's load diagram (:mod:`camtrain.engine.loads`) goes through the existing journal
kernel: Booker's mobility orbit (Yang 1992 §1.3, eqs 1.12-1.16; :func:`bearing_orbit`) marched
over the engine cycle (4 pi for a 4-stroke) until periodic, the steady-load locus (eq. 1.13) and
Petroff's concentric power (eq. 1.19, relative speed = engine speed as in Yang's Tables 2.1-2.4).
Big-ends are solved in rod axes with the pin speed relative to the rod (eq. 2.1), mains in
block axes at the engine speed (eq. 2.2).

Grooving (Yang §2.4, §5.1): ``none`` (full length), ``central`` (two lands, each a short bearing
carrying half the load; shear over both lands) and ``partial``, FLAME's treatment: the mean of
the ungrooved and grooved results (the program could model only the two extremes).

Yang's program used half the mobility of his printed eqs 1.15/1.16 (reference notes §7 and the
Ruston check): ``mobility_scale = 0.5`` (:data:`YANG1992_MOBILITY_SCALE`) reproduces his
printed films; 1.0, the physics as printed, is the default.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, fields, replace

import numpy as np

from camtrain.bearings import JournalBearing, JournalOrbit, bearing_orbit, bearing_petroff_power, steady_orbit
from camtrain.errors import field_error
from camtrain.progress import detail

from .loads import CrankLoads, MainLoads, crank_train_loads
from .model import Engine

__all__ = ["BearingSpec", "SolverOptions", "BearingVariant", "BearingResult",
           "EngineBearings", "solve_engine_bearings", "solve_crank_bearings", "GROOVINGS",
           "METHODS", "MODELS", "YANG1992_MOBILITY_SCALE"]

GROOVINGS = ("none", "central", "partial")
METHODS = ("dynamic", "steady", "petroff")
#: Film model of every crank bearing: Ocvirk's short bearing (Yang), the finite Reynolds film,
#: or auto (finite unless the land is short; :func:`camtrain.bearings.models.choose_model`).
MODELS = ("auto", "short", "finite")
#: Mobility factor of Yang's (1992) program (compatibility option; the physics is 1.0).
YANG1992_MOBILITY_SCALE = 0.5


@dataclass(frozen=True)
class BearingSpec:
    """One crankshaft bearing (SI): diameter d, overall length b, radial clearance c, effective
    viscosity, grooving and the groove width (central and partial grooves)."""

    diameter: float
    length: float
    clearance: float
    viscosity: float
    grooving: str = "none"
    groove_width: float = 0.0
    name: str = "bearing"

    def __post_init__(self):
        if self.grooving not in GROOVINGS:
            raise field_error(f"{self.name}.grooving", "unknown grooving", self.grooving,
                              " or ".join(GROOVINGS))
        if self.grooving != "none" and not self.groove_width > 0:
            raise field_error(f"{self.name}.groove_width", "a grooved bearing needs a groove "
                              "width > 0", self.groove_width)

    def variants(self) -> dict:
        """Bearing geometry per treatment: {'ungrooved': ..., 'grooved': ...} as needed."""
        out = {}
        if self.grooving in ("none", "partial"):
            out["ungrooved"] = JournalBearing(self.diameter, self.length, self.clearance,
                                              self.viscosity, 0.0, self.name)
        if self.grooving in ("central", "partial"):
            out["grooved"] = JournalBearing(self.diameter, self.length, self.clearance,
                                            self.viscosity, self.groove_width, self.name)
        return out


@dataclass(frozen=True)
class SolverOptions:
    """Resolution knobs and model options of the crank-bearing calculation.

    crank_step [rad]; pressure_interpolation "periodic_cubic" | "linear"; rod_speed
    "small_angle" (Yang eq. 2.1) | "exact"; mobility "exact" | "booker"; mobility_scale (1.0
    physics, 0.5 Yang's program); film "2pi" (Yang's tables) | "pi"; terms "shear" | "all";
    tol per step on eps; period_tol cycle-to-cycle change; start "centre" (Yang) | "steady";
    model "short" (Ocvirk, Yang's tables) | "finite" (Reynolds over the whole bearing,
    :mod:`camtrain.bearings.models`) | "auto"; cavitation, n_theta, n_z of the finite film.
    """

    crank_step: float = math.radians(0.5)
    pressure_interpolation: str = "periodic_cubic"
    rod_speed: str = "small_angle"
    mobility: str = "exact"
    mobility_scale: float = 1.0
    film: str = "2pi"
    terms: str = "shear"
    tol: float = 1e-7
    period_tol: float = 1e-5
    max_cycles: int = 20
    start: str = "centre"
    methods: tuple = METHODS
    reuse_shifted: bool = True
    model: str = "short"
    cavitation: str = "reynolds"
    n_theta: int = 72
    n_z: int = 6

    def __post_init__(self):
        if self.model not in MODELS:
            raise field_error("solver.bearing_model", "unknown bearing model", self.model,
                              " or ".join(MODELS))
        for m in self.methods:
            if m not in METHODS:
                raise field_error("engine.solver.methods", "unknown method", m,
                                  ", ".join(METHODS))


@dataclass(frozen=True)
class BearingVariant:
    """One grooving treatment of one bearing: orbits (None if not asked) and Petroff [W]."""

    bearing: JournalBearing
    dynamic: JournalOrbit | None
    steady: JournalOrbit | None
    petroff: float | None


@dataclass(frozen=True)
class BearingResult:
    """One big-end or main: its load diagram (bearing frame), speeds and per-treatment results.

    Summary properties average the treatments (FLAME's partial-groove mean for powers); the
    film of a partially grooved bearing is reported for both extremes (``variants``) and the
    summary takes the thinner one.
    """

    name: str
    kind: str
    index: int
    load_x: np.ndarray
    load_y: np.ndarray
    omega_journal: np.ndarray
    variants: dict = field(default_factory=dict)

    def _mean(self, attr):
        vals = [getattr(v, attr) for v in self.variants.values()]
        if any(x is None for x in vals):
            return None
        return float(np.mean([x if isinstance(x, float) else x.mean_power for x in vals]))

    @property
    def power_dynamic(self) -> float | None:
        return self._mean("dynamic")

    @property
    def power_steady(self) -> float | None:
        return self._mean("steady")

    @property
    def power_petroff(self) -> float | None:
        return self._mean("petroff")

    def _film(self, attr):
        orbits = [getattr(v, attr) for v in self.variants.values()]
        if any(o is None for o in orbits):
            return None, None
        o = min(orbits, key=lambda o: o.min_film)
        return o.min_film, o.min_film_angle

    @property
    def min_film_dynamic(self):
        """(h_min [m], crank angle [rad]) of the dynamic orbit (thinner treatment)."""
        return self._film("dynamic")

    @property
    def min_film_steady(self):
        return self._film("steady")


@dataclass(frozen=True)
class EngineBearings:
    """Every crankshaft bearing of an engine at one speed, with the load diagrams."""

    omega: float
    angle: np.ndarray
    cylinders: list
    mains_loads: MainLoads
    big_ends: list
    mains: list
    options: SolverOptions

    @property
    def bearings(self) -> list:
        return self.big_ends + self.mains

    def total(self, method: str) -> float | None:
        """Engine total power [W] of ``method`` (dynamic, steady, petroff)."""
        vals = [getattr(b, f"power_{method}") for b in self.bearings]
        return None if any(v is None for v in vals) else float(sum(vals))


def _same_shifted(a: np.ndarray, b: np.ndarray, k: int) -> bool:
    scale = max(float(np.max(np.abs(a))), 1.0)
    return bool(np.allclose(np.roll(a, k), b, rtol=0.0, atol=1e-9 * scale))


def _shift_orbit(orbit: JournalOrbit, k: int) -> JournalOrbit:
    """The periodic orbit of a load diagram rolled by k grid steps (same bearing and speeds)."""
    keep = {"angle", "time"}
    changes = {f.name: np.roll(getattr(orbit, f.name), k) for f in fields(orbit)
               if isinstance(getattr(orbit, f.name), np.ndarray) and f.name not in keep}
    return replace(orbit, **changes)


def _solve(brg: JournalBearing, lx, ly, wj, angle, omega, period, opt: SolverOptions):
    dyn = stdy = pet = None
    common = dict(angle_rate=omega, period=period, film=opt.film, terms=opt.terms)
    from camtrain.bearings.models import choose_model, finite_steady_orbit, orbit_mobility

    used = choose_model(brg, opt.model)[0]
    mesh = dict(cavitation=opt.cavitation, n_theta=opt.n_theta, n_z=opt.n_z)
    if "dynamic" in opt.methods:
        mobility = (orbit_mobility(brg, used, opt.mobility, opt.cavitation, opt.n_theta,
                                   opt.n_z) if used == "finite" else opt.mobility)
        dyn = bearing_orbit(brg, lx, ly, angle, wj, 0.0, mobility=mobility,
                            mobility_scale=opt.mobility_scale, tol=opt.tol,
                            period_tol=opt.period_tol, max_cycles=opt.max_cycles,
                            start=opt.start, **common)
    if "steady" in opt.methods:
        stdy = (finite_steady_orbit(brg, lx, ly, angle, wj, 0.0, **common, **mesh)
                if used == "finite" else steady_orbit(brg, lx, ly, angle, wj, 0.0, **common))
    if "petroff" in opt.methods:
        pet = float(bearing_petroff_power(brg, omega))
    return BearingVariant(brg, dyn, stdy, pet)


def _bearing(spec: BearingSpec, kind, index, lx, ly, wj, angle, omega, period, opt, done):
    """Solve one bearing, reusing an identical earlier one shifted in crank angle."""
    variants = {}
    for tag, brg in spec.variants().items():
        hit = None
        if opt.reuse_shifted:
            for (brg0, lx0, ly0, wj0, var0) in done.get(tag, ()):
                if replace(brg0, name="") != replace(brg, name=""):
                    continue
                for k in _candidate_shifts(lx0, lx):
                    if (_same_shifted(lx0, lx, k) and _same_shifted(ly0, ly, k)
                            and _same_shifted(np.broadcast_to(wj0, lx0.shape),
                                              np.broadcast_to(wj, lx.shape), k)):
                        hit = _shift_variant(var0, k)
                        break
                if hit is not None:
                    break
        if hit is None:
            hit = _solve(brg, lx, ly, wj, angle, omega, period, opt)
            done.setdefault(tag, []).append((brg, lx, ly, wj, hit))
        variants[tag] = hit
    return BearingResult(spec.name, kind, index, lx, ly, np.broadcast_to(wj, lx.shape).copy(),
                         variants)


def _candidate_shifts(a: np.ndarray, b: np.ndarray) -> list:
    """Grid shifts k with roll(a, k) matching b at the peak (cheap pre-filter)."""
    i = int(np.argmax(np.abs(b)))
    return [int((i - j) % a.size) for j in np.flatnonzero(np.isclose(a, b[i], rtol=1e-9,
                                                                     atol=0.0))]


def _shift_variant(v: BearingVariant, k: int) -> BearingVariant:
    return BearingVariant(v.bearing, None if v.dynamic is None else _shift_orbit(v.dynamic, k),
                          None if v.steady is None else _shift_orbit(v.steady, k), v.petroff)


def solve_engine_bearings(engine: Engine, omega: float, big_end: BearingSpec, mains,
                          options: SolverOptions | None = None) -> EngineBearings:
    """Loads, orbits and power of every big-end and main bearing at engine speed ``omega``.

    Args:
        engine: the crank train (:class:`~camtrain.engine.model.Engine`).
        omega: engine speed [rad/s], > 0.
        big_end: the big-end bearing (the same for every rod).
        mains: one :class:`BearingSpec` for every main, or a list front to rear.
        options: :class:`SolverOptions`.
    """
    opt = options or SolverOptions()
    loads = crank_train_loads(engine, omega, opt.crank_step,
                              interpolation=opt.pressure_interpolation, rod_speed=opt.rod_speed)
    return solve_crank_bearings(loads, big_end, mains, opt)


def solve_crank_bearings(loads: CrankLoads, big_end: BearingSpec, mains,
                         options: SolverOptions | None = None) -> EngineBearings:
    """Orbits and power of every big-end and main under the load diagrams ``loads``
    (:func:`~camtrain.engine.loads.crank_train_loads`); ``mains`` as in
    :func:`solve_engine_bearings`."""
    opt = options or SolverOptions()
    engine, omega, angle = loads.engine, loads.omega, loads.angle
    if isinstance(mains, BearingSpec):
        mains = [replace(mains, name=f"{mains.name} {i + 1}") for i in range(engine.n_mains)]
    if len(mains) != engine.n_mains:
        raise field_error("bearings.mains", "one main bearing per bay end", len(mains),
                          f"{engine.n_mains} (bays + 1)")
    period = engine.crank.cycle
    cyl, ml = list(loads.cylinders), loads.mains
    done: dict = {}
    big = []
    for i, c in enumerate(cyl):
        detail(f"big-end {i + 1} of {len(cyl)}")
        big.append(_bearing(replace(big_end, name=f"{big_end.name} {i + 1}"), "big_end", i,
                            c.load_x, c.load_y, c.omega_journal, angle, omega, period, opt,
                            done))
    done = {}
    mb = []
    for i, spec in enumerate(mains):
        detail(f"main {i + 1} of {len(mains)}")
        mb.append(_bearing(spec, "main", i, ml.load_x[i], ml.load_y[i], omega, angle, omega,
                           period, opt, done))
    return EngineBearings(omega, angle, cyl, ml, big, mb, opt)
