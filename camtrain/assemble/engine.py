"""Build the crank train and its bearings from an engine deck (deck model -> camtrain.engine)."""
from __future__ import annotations

from camtrain.deck.schema_engine import EngineDeck
from camtrain.engine import (
    YANG1992_MOBILITY_SCALE,
    BearingSpec,
    CrankComponent,
    CrankTrain,
    Cylinder,
    Engine,
    PressureTable,
    SolverOptions,
)
from camtrain.errors import GeometryError


def raw_pressure_table(deck: EngineDeck) -> PressureTable:
    """The cylinder-pressure table of the run speed as the deck gives it, in Pa."""
    t = deck.pressure_table()
    i = deck.pressure.index(t)
    cycle = deck.engine.strokes / 2.0 * 2.0 * 3.141592653589793
    return PressureTable(t.angles, t.pascal, cycle, t.reference == "absolute", t.crankcase_pa,
                         f"pressure[{i}]")


def pressure_table(deck: EngineDeck) -> PressureTable:
    """The cylinder-pressure table of the run, in Pa (gauge inside the physics), scaled to the
    deck's [load] when it has one."""
    from camtrain.engine.pressure import scaled

    table = raw_pressure_table(deck)
    factor = load_factor(deck)
    return table if factor == 1.0 else scaled(table, factor)


def engine(deck: EngineDeck) -> Engine:
    """The crank train; a rod no longer than the crank radius cannot turn the crank (exit 3)."""
    e = deck.engine
    if e.rod_length <= e.crank_radius:
        raise GeometryError(f"engine.rod_length: a {e.rod_length * 1e3:g} mm rod cannot turn a "
                            f"{e.crank_radius * 1e3:g} mm crank (the rod must be longer than "
                            "the crank radius)")
    crank = CrankTrain(e.bore, e.crank_radius, e.rod_length, e.piston_mass, e.rod_mass,
                       e.strokes)
    p = pressure_table(deck)
    cyl = tuple(Cylinder(c.bay - 1, c.position, c.firing_angle, p, f"cylinder {i + 1}")
                for i, c in enumerate(deck.cylinders))
    comps = tuple(CrankComponent(c.bay - 1, c.position, c.unbalance, c.angle,
                                 f"crank component {i + 1}")
                  for i, c in enumerate(deck.crank_components))
    return Engine(crank, tuple(e.bay_lengths), cyl, comps, e.flywheel_mass)


def check_geometry(deck: EngineDeck) -> tuple[str, list[str]]:
    """``camtrain check`` of an engine deck: the crank train assembles (rod longer than the
    crank radius, exit 3 otherwise) and every cylinder has its bay and pressure table."""
    if not deck.has_crank_train:
        return "no crank train to check (a bare engine deck: the correlations alone)", []
    engine(deck)
    return "geometry checked (crank train)", []


def bearing(deck: EngineDeck, which: str) -> BearingSpec:
    """``which`` = "big_end" or "main": the bearing with its viscosity at the run speed."""
    from camtrain.assemble.oil import flame_oil_factor

    b = getattr(deck.bearings, which)
    eta = b.viscosity_at(deck.speed.omega) * flame_oil_factor(deck)
    return BearingSpec(b.diameter, b.length, b.clearance, eta,
                       b.grooving, b.groove_width, which.replace("_", "-"))


def mobility_scale(deck: EngineDeck) -> float:
    """1.0 (the physics as printed) or Yang's program's 0.5 (compatibility option)."""
    return YANG1992_MOBILITY_SCALE if deck.solver.mobility_factor == "yang1992_program" else 1.0


def solver_options(deck: EngineDeck) -> SolverOptions:
    s = deck.solver
    return SolverOptions(crank_step=s.crank_step, pressure_interpolation=s.pressure_interpolation,
                         rod_speed=s.rod_speed, mobility=s.mobility,
                         mobility_scale=mobility_scale(deck), film=s.film, terms=s.terms,
                         tol=s.step_tolerance, period_tol=s.period_tolerance,
                         max_cycles=s.max_cycles, start=s.start, methods=tuple(s.methods),
                         model=s.bearing_model, cavitation=s.bearing_cavitation,
                         n_theta=s.bearing_n_theta, n_z=s.bearing_n_z)


def load_factor(deck) -> float:
    """Factor on the run's gauge pressure diagram that [load] asks for (1 without [load])."""
    load = getattr(deck, "load", None)
    if load is None:
        return 1.0
    from camtrain.engine.pressure import net_imep
    from camtrain.errors import GeometryError

    table = raw_pressure_table(deck)
    if load.measure == "peak_pressure":
        base = float(max(table.gauge()))
    else:
        base = net_imep(table, deck.engine.crank_radius, deck.engine.rod_length,
                        deck.solver.pressure_interpolation)
    if not base > 0.0:
        raise GeometryError(f"load.measure: the run's pressure diagram has a "
                            f"{load.measure.replace('_', ' ')} of {base / 1e5:.4g} bar; it "
                            "cannot be scaled to a positive value")
    return load.value / base
