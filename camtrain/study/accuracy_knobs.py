"""The resolution knobs `camtrain accuracy` studies: the deck field each sets, its ladder and the
deck options it needs (camtrain.study.accuracy runs them). Which knobs a deck offers is declared by
the effects of its plan (EffectSpec.knobs), and the metrics read on every rung likewise
(EffectSpec.accuracy_metrics); a knob's ``applies`` only narrows it by the deck's options.

Plain data and small predicates on a raw deck dictionary; nothing here imports numpy.
"""
from __future__ import annotations

import copy
from collections.abc import Callable
from dataclasses import dataclass


@dataclass(frozen=True)
class Knob:
    """One resolution knob: the deck field it sets and its ladder, coarsest first.

    ``step`` maps a knob value to the discretisation size h (smaller is finer), so the ladder's
    refinement ratio and the observed order are in terms of h.
    """

    name: str
    path: str
    ladder: tuple[float, ...]
    step: Callable[[float], float]
    applies: Callable[[dict], bool]
    description: str
    integer: bool = False
    #: sets the knob's value in a raw deck when one path is not enough (default: set_path)
    setter: Callable[[dict, object], dict] | None = None
    #: time a rung's second run (caches warm): for knobs whose first run builds a table
    warm: bool = False
    #: a deck-specific ladder (None: ``ladder``), e.g. a cheaper one where a rung is costly
    ladder_for: Callable[[dict], tuple | None] | None = None

    def ladder_of(self, raw: dict) -> tuple:
        """The ladder this knob climbs on the deck ``raw``."""
        special = self.ladder_for(raw) if self.ladder_for is not None else None
        return tuple(special) if special else self.ladder


def _always(raw: dict) -> bool:
    """The knob applies wherever an effect of the plan declares it."""
    return True


def _engine_orbits(raw: dict) -> bool:
    methods = raw.get("solver", {}).get("methods", ("dynamic",))
    return "dynamic" in methods


def _choice_step(choices: tuple[str, ...]) -> Callable[[str], float]:
    """A model choice has no step size: the rungs are ranked in ladder order (the last, the
    default, is the reference), so errors are differences from the default model."""
    return lambda v: float(len(choices) - choices.index(v))


def _lift_form(raw: dict) -> str:
    return str(raw.get("lift", {}).get("form", ""))


def _iterates(raw: dict) -> bool:
    # Only followers whose contact load depends on friction iterate (pivoted, pushrod, desmo).
    return raw.get("mechanism", {}).get("type") in ("finger", "rocker", "pushrod", "desmodromic")


def _coupled_camshaft(raw: dict) -> bool:
    """Every lobe's elastic train on the elastic shaft (two-way coupling)."""
    return raw.get("camshaft", {}).get("flexibility", {}).get("coupling") == "two_way"


def _staggered_camshaft(raw: dict) -> bool:
    """The coupled camshaft marched by the staggered solver."""
    flex = raw.get("camshaft", {}).get("flexibility", {})
    return _coupled_camshaft(raw) and flex.get("coupling_solver") == "staggered"


#: ladders of the coupled camshaft (one rung marches every lobe's train with the shaft; 8
#: stations per span cost twelve times the default, 2 steps per degree leave the contact
#: ringing unresolved)
COUPLED_LADDERS = {"shaft_stations": (0, 1, 2, 4), "steps_per_degree": (6.0, 12.0, 24.0, 48.0)}


def _coupled_ladder(name: str) -> Callable[[dict], tuple | None]:
    return lambda raw: COUPLED_LADDERS[name] if _coupled_camshaft(raw) else None


def _smoothing_spline(raw: dict) -> bool:
    table = raw.get("lift", {}).get("table", {})
    return _lift_form(raw) == "table" and table.get("derivative", "smoothing_spline") == \
        "smoothing_spline"


def _bearing_section(raw: dict) -> tuple[str, str] | None:
    """(section path, field prefix) of the deck's journal-bearing film options, or None when
    the deck has no bearing with a film (no bearings, or the Petroff method only)."""
    if raw.get("kind") == "journal_bearing":
        where = ("solver", "")
    elif raw.get("camshaft", {}).get("bearings"):
        where = ("camshaft", "bearing_")
    elif raw.get("kind") == "engine":
        where = ("solver", "bearing_")
        if list(raw.get("solver", {}).get("methods", ("dynamic",))) == ["petroff"]:
            return None
    else:
        return None
    node = raw.get(where[0], {})
    return None if node.get("method", "mobility") == "petroff" else where


def _camshaft_orbits(raw: dict) -> bool:
    """The deck marches camshaft-bearing orbits (the mobility method)."""
    cs = raw.get("camshaft", {})
    return bool(cs.get("bearings")) and cs.get("method", "mobility") == "mobility"


def _set_film(raw: dict, **fields) -> dict:
    section, prefix = _bearing_section(raw)
    out = copy.deepcopy(raw)
    out.setdefault(section, {}).update({prefix + k: v for k, v in fields.items()})
    return out


def _mesh_rung(raw: dict, n_theta) -> dict:
    """The finite film at n_theta around and n_theta/12 along a half land (the default 72 x 6)."""
    return _set_film(raw, model="finite", n_theta=int(n_theta), n_z=max(2, round(n_theta / 12)))


#: rungs of the model knob: the short film, the finite film at the deck's mesh, and the finite
#: film at the finest mesh of the bearing_mesh ladder (the reference)
MODEL_RUNGS = ("short", "finite", "finite:288")


def _model_step(value) -> float:
    """Steps of the model rungs: short 1, finite at the deck's mesh 0.5, finite:N 1/N (unequal
    ratios, so no order is read across models)."""
    model, _, n_theta = str(value).partition(":")
    return 1.0 / int(n_theta) if n_theta else (1.0 if model == "short" else 0.5)


def _model_rung(raw: dict, value) -> dict:
    model, _, n_theta = str(value).partition(":")
    return _mesh_rung(raw, int(n_theta)) if n_theta else _set_film(raw, model=model)


def _film_model(raw: dict) -> str:
    return str(raw.get("tribology", {}).get("film_model", "steady"))


def _transient_film(raw: dict) -> bool:
    return _film_model(raw) in ("squeeze", "averaged_reynolds")


def _averaged_reynolds(raw: dict) -> bool:
    return _film_model(raw) == "averaged_reynolds"


def _elastic_film(raw: dict) -> bool:
    return _film_model(raw) == "ehl"


def _spring_chain(raw: dict) -> bool:
    return int(raw.get("dynamics", {}).get("spring_elements", 0)) > 0


def _lash_adjuster(raw: dict) -> bool:
    return bool(raw.get("dynamics", {}).get("lash_adjuster"))


def _adaptive(raw: dict) -> bool:
    return raw.get("dynamics", {}).get("integrator") in ("lsoda", "radau")


def _roller_march(raw: dict) -> bool:
    """The roller's speed is marched (roller.solver = inertial)."""
    return raw.get("roller", {}).get("solver", "quasi_static") == "inertial"


KNOBS: dict[str, Knob] = {k.name: k for k in (
    Knob("angle_points", "solver.angle_points", (180, 360, 720, 1440, 2880, 5760),
         lambda v: 1.0 / v, _always,
         "cam angles over one revolution (angle step 360 deg / n)", integer=True),
    Knob("friction_tolerance", "solver.friction_tolerance",
         (1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8), lambda v: v, _iterates,
         "relative tolerance of the friction/load iteration"),
    Knob("table_smoothing", "lift.table.smoothing", (4.0, 2.0, 1.0, 0.5, 0.25),
         lambda v: v, _smoothing_spline,
         "smoothing level of the lift-table spline (relative to the data precision)"),
    Knob("shaft_stations", "camshaft.flexibility.nodes_per_span", (0, 1, 2, 4, 8),
         lambda v: 1.0 / (v + 1), _always,
         "extra stations per span of the elastic camshaft (element length / (n + 1))",
         integer=True, ladder_for=_coupled_ladder("shaft_stations")),
    Knob("bearing_mesh", "solver.n_theta | camshaft.bearing_n_theta (n_z = n_theta / 12)",
         (36, 72, 144, 288), lambda v: 1.0 / v, lambda raw: _bearing_section(raw) is not None,
         "finite journal-bearing film mesh, model = finite (time: the orbit with the map "
         "cached; building a map costs ~200 Reynolds solutions once per b/d and mesh)",
         integer=True, setter=_mesh_rung, warm=True),
    Knob("bearing_model", "solver.model | camshaft.bearing_model | engine solver.bearing_model",
         MODEL_RUNGS,
         _model_step,
         lambda raw: _bearing_section(raw) is not None,
         "journal-bearing film model: short (Ocvirk) and finite at the deck's mesh against "
         "the finite film at 288 x 24", setter=_model_rung, warm=True),
    Knob("orbit_points", "camshaft.orbit_points", (90, 180, 360, 720, 1440), lambda v: 1.0 / v,
         _camshaft_orbits, "load-diagram angles per revolution the camshaft-bearing orbits are "
         "marched on (the run's grid resampled; a rung at or above the run's grid marches on "
         "it)", integer=True),
    Knob("crank_step", "solver.crank_step", (4.0, 2.0, 1.0, 0.5, 0.25), lambda v: v, _always,
         "crank-angle step of the load diagrams and orbits [deg]"),
    Knob("period_tolerance", "solver.period_tolerance", (1e-3, 1e-4, 1e-5, 1e-6, 1e-7),
         lambda v: v, _engine_orbits,
         "cycle-to-cycle change of eps that counts as a periodic crank-bearing orbit"),
    Knob("step_tolerance", "solver.step_tolerance", (1e-5, 1e-6, 1e-7, 1e-8, 1e-9),
         lambda v: v, _engine_orbits, "error per time step of the crank-bearing orbit march"),
    Knob("pressure_interpolation", "solver.pressure_interpolation",
         ("linear", "periodic_cubic"), _choice_step(("linear", "periodic_cubic")), _always,
         "cylinder pressure between table angles (model choice; reference: periodic_cubic)"),
    Knob("mobility", "solver.mobility", ("booker", "exact"),
         _choice_step(("booker", "exact")), _engine_orbits,
         "short-bearing mobility (model choice; reference: the exact pi-film inversion)"),
    # transient film (docs/transient_film.md)
    Knob("film_angle_step", "solver.film_angle_step", (2.0, 1.0, 0.5, 0.25, 0.125),
         lambda v: v, _transient_film, "cam-angle step of the transient film march [deg]"),
    Knob("film_nodes", "solver.film_nodes", (51, 101, 201, 401, 801, 1601),
         lambda v: 1.0 / (v - 1), _averaged_reynolds,
         "nodes across the contact zone of the averaged Reynolds film", integer=True),
    Knob("film_zone_width", "solver.film_zone_width", (2.0, 4.0, 8.0, 16.0),
         lambda v: 1.0 / v, _averaged_reynolds,
         "half width of the averaged Reynolds zone in Hertz half widths"),
    Knob("film_tolerance", "solver.film_tolerance", (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8),
         lambda v: v, _averaged_reynolds, "load-balance tolerance of the averaged Reynolds film"),
    # elastic film (docs/ehl.md)
    Knob("ehl_nodes", "solver.ehl_nodes", (128, 256, 512, 1024), lambda v: 1.0 / (v - 1),
         _elastic_film, "grid points of the elastic film's domain (matrix-free Newton from 384 "
         "points: cost ~ n log n, docs/ehl.md)", integer=True),
    Knob("ehl_inlet", "solver.ehl_inlet", (3.0, 4.5, 9.0, 18.0), lambda v: 1.0 / v,
         _elastic_film, "half length of the elastic film's domain in Hertz half widths (at "
         "fixed points a longer domain is a coarser grid)"),
    Knob("ehl_angle_step", "solver.ehl_angle_step", (2.0, 1.0, 0.5, 0.25), lambda v: v,
         _elastic_film, "cam-angle step of the elastic film's time march [deg] (cost ~ 1/step)"),
    Knob("ehl_tolerance", "solver.ehl_tolerance", (1e-3, 1e-4, 1e-5, 1e-6, 1e-7),
         lambda v: v, _elastic_film, "Newton tolerance of the elastic film (a decade: about "
         "one chord step per angle)"),
    Knob("piston_crank_step", "piston.solver.crank_step", (4.0, 2.0, 1.0, 0.5),
         lambda v: v, _always,
         "crank-angle step of the inter-ring gas and ring-film marches [deg]"),
    Knob("ring_tolerance", "piston.solver.ring_tolerance", (1e-2, 1e-3, 1e-4, 1e-5, 1e-6),
         lambda v: v, _always,
         "cyclic tolerance of the ring-film march"),
    Knob("pass_tolerance", "piston.solver.pass_tolerance", (1e-1, 1e-2, 1e-3, 1e-4),
         lambda v: v, lambda raw: raw["piston"].get("solver", {}).get(
             "pass_mode", "converged") == "converged",
         "tolerance of the ring pack's starved passes to their fixed point"),
    Knob("gas_tolerance", "piston.solver.gas_tolerance", (1e-3, 1e-4, 1e-5, 1e-6, 1e-7),
         lambda v: v, _always,
         "iteration and cyclic tolerance of the inter-ring gas march"),
    # roller rotation (docs/rollers.md)
    Knob("roller_substeps", "roller.substeps", (1, 2, 4, 8, 16), lambda v: 1.0 / v,
         _roller_march, "implicit-Euler steps of the roller's speed per cam-angle grid step",
         integer=True),
    Knob("roller_table_points", "roller.table_points", (51, 101, 201, 401, 801),
         lambda v: 1.0 / (v - 1), _roller_march,
         "points of the roller's traction and pin-torque tables", integer=True),
    Knob("roller_tolerance", "roller.periodic_tolerance", (1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7),
         lambda v: v, _roller_march,
         "change of the roller speed over a revolution that counts as periodic"),
    Knob("steps_per_degree", "dynamics.steps_per_degree", (2.0, 4.0, 8.0, 16.0, 32.0, 64.0),
         lambda v: 1.0 / v, lambda raw: not _adaptive(raw),
         "time steps per degree of cam of the valve-train dynamics",
         ladder_for=_coupled_ladder("steps_per_degree")),
    Knob("coupling_iterations", "camshaft.flexibility.coupling_iterations", (1, 2, 4, 10),
         lambda v: 1.0 / v, _staggered_camshaft,
         "passes of a staggered shaft/train step at most (1: loosely coupled)", integer=True),
    Knob("spring_elements", "dynamics.spring_elements", (4, 8, 16, 32), lambda v: 1.0 / v,
         _spring_chain, "elements of the valve-spring chain (surge)", integer=True),
    Knob("dynamics_rtol", "dynamics.rtol", (1e-5, 1e-6, 1e-7, 1e-8, 1e-9), lambda v: v,
         _adaptive, "relative tolerance of the adaptive dynamics integrator"),
    Knob("adjuster_cycles", "dynamics.cycles_max", (4, 8, 16, 32, 64), lambda v: 1.0 / v,
         _lash_adjuster, "revolutions marched at most towards the periodic state (a hydraulic "
         "lash adjuster's leak-down and refill balance over many)", integer=True),
)}
