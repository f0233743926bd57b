"""Piston-assembly effect (engine decks): inter-ring gas, compression-ring films, oil-control ring
and skirt of one cylinder over the cycle, and the friction power of every piston of the engine
(Yang 1992 Part III; physics :mod:`camtrain.piston`).

Every cylinder runs the same pressure table phased by its firing angle, so one assembly stands
for all of them (Yang's FLAME does the same).
"""
from __future__ import annotations


def missing(deck) -> list[str]:
    return [] if getattr(deck, "piston", None) is not None else [
        "[piston] section (rings, gas, temperatures, oil)"]


def reason(deck, planned) -> str:
    p = deck.piston
    s = p.solver
    passes = (f"starved passes to the pack's fixed point (within {s.pass_tolerance:g})"
              if s.pass_mode == "converged" else
              f"{s.passes} starved passes (yang1992, Table 6.1)")
    parts = [f"{len(p.rings)} compression rings, gas labyrinth ({s.gas_march}), flooded "
             f"then {passes} (Yang 1992 §5.2-5.4)"]
    parts.append("oil-control ring" if p.oil_control_ring is not None else "no oil-control ring")
    parts.append("skirt (eq. 5.37)" if p.skirt is not None else
                 "skirt skipped (no [piston.skirt] geometry)")
    return "; ".join(parts)


def makes(deck, planned) -> tuple[str, ...]:
    """The optional columns it writes (EffectSpec.optional_columns): the gas pressure between
    each two successive compression rings, and the oil-control ring's and the skirt's friction
    when the deck has their sections."""
    p = deck.piston
    out = [f"inter_ring_pressure_{i}" for i in range(1, len(p.rings))]
    if p.oil_control_ring is not None:
        out.append("oil_control_ring_friction")
    if p.skirt is not None:
        out.append("skirt_friction")
    return tuple(out)


def _interp(speeds, values, rpm: float) -> float:
    import numpy as np

    return float(np.interp(rpm, speeds, values))


def piston_case(deck):
    """The :class:`~camtrain.piston.cycle.PistonCase` of the deck at its run speed."""
    from camtrain.assemble.oil import flame_oil_factor
    from camtrain.piston.cycle import CompressionRing, PistonCase
    from camtrain.piston.ring import Ring
    from camtrain.piston.thermal import ViscosityLaw
    from camtrain.units import from_si

    p, e = deck.piston, deck.engine
    rpm = from_si(deck.speed.engine, "rpm")
    speeds = [from_si(s, "rpm") for s in p.temperatures.speeds]
    top = p.rings[0].groove_position
    rings = tuple(CompressionRing(Ring(r.height, r.face_radius, r.offset, r.tension, r.roughness),
                                  r.gap, top - r.groove_position,
                                  _interp(speeds, r.groove_temperatures, rpm))
                  for r in p.rings)
    t = p.temperatures
    liner = tuple(_interp(speeds, getattr(t, k), rpm)
                  for k in ("liner_top", "liner_middle", "liner_bottom"))
    ocr, skirt, g = p.oil_control_ring, p.skirt, p.gas
    return PistonCase(
        bore=e.bore, crank_radius=e.crank_radius, rod_length=e.rod_length, rings=rings,
        radial_clearance=g.radial_clearance, separations=g.separations,
        chamber_temperature=_interp(speeds, t.chamber, rpm), liner_temperatures=liner,
        viscosity=ViscosityLaw(p.oil.temperatures,
                               tuple(v * flame_oil_factor(deck) for v in p.oil.viscosities),
                               p.oil.law),
        liner_roughness=p.liner_roughness, volumes=g.volumes, areas=g.orifice_areas,
        k=g.heat_ratio, discharge=g.discharge, gas_constant=g.gas_constant,
        crankcase_pressure=g.crankcase_pressure,
        ocr_tension=None if ocr is None else ocr.tension,
        ocr_height=None if ocr is None else ocr.height,
        ocr_friction=0.08 if ocr is None else ocr.friction_coefficient,
        skirt_height=None if skirt is None else skirt.height,
        skirt_depth=0.0 if skirt is None else skirt.depth,
        skirt_x=None if skirt is None else skirt.positions,
        skirt_clearance=None if skirt is None else skirt.clearances,
    )


def cylinder_pressure(deck):
    """Gauge cylinder pressure [Pa] of the run speed's table as a function of crank angle."""
    from camtrain.assemble.engine import pressure_table

    table = pressure_table(deck)   # the run speed's table, scaled to [load] when given
    how = getattr(getattr(deck, "solver", None), "pressure_interpolation", "periodic_cubic")
    return lambda theta: table(theta, how)


def run(deck, inputs, result):
    import numpy as np

    from camtrain.piston.cycle import PistonOptions, solve_piston

    p = deck.piston
    if deck.engine.strokes != 4:
        from camtrain.errors import field_error

        raise field_error("engine.strokes", "the piston-assembly model is for 4-stroke engines "
                          "(Yang's ring pack passes)", deck.engine.strokes, "4")
    s = p.solver
    options = PistonOptions(step=s.crank_step, gas_march=s.gas_march,
                            gas_tolerance=s.gas_tolerance, ring_march=s.ring_march,
                            ring_tolerance=s.ring_tolerance, passes=s.passes,
                            pass_mode=s.pass_mode, pass_tolerance=s.pass_tolerance,
                            max_passes=s.max_passes,
                            roughness_rule=s.roughness_rule, power_mean=s.power_mean,
                            boundary_friction=s.boundary_friction)
    out = solve_piston(piston_case(deck), cylinder_pressure(deck), deck.speed.engine,
                       len(deck.cylinders), options)
    _flag_assumptions(deck, result)
    _write(out, deck, result, np)
    pk = out.pack
    result.add_metric("ring_passes", pk.passes, "-", "starved passes of the ring pack")
    result.add_metric("ring_pass_change", pk.pass_change, "-", "ring pack: largest relative "
                      "change of a ring's films or left layer in the last pass")
    if s.pass_mode == "converged" and not pk.converged:
        result.warn(f"piston: the ring pack did not reach its fixed point in {pk.passes} passes "
                    f"(last change {pk.pass_change:.2g} > piston.solver.pass_tolerance "
                    f"{s.pass_tolerance:g}); raise piston.solver.max_passes")
    for i, (most, capped) in enumerate(zip(pk.cycles_most, pk.unrepeated, strict=True)):
        result.add_metric("cycles_most", most, "-", f"ring {i + 1}: most cycles of any of its "
                          "starved marches", component=f"ring_{i + 1}")
        if capped:
            result.warn(f"piston: {capped} of ring {i + 1}'s starved marches stopped at their "
                        f"{most}-cycle cap before the film repeated within "
                        f"piston.solver.ring_tolerance {s.ring_tolerance:g}")
    return out


def _flag_assumptions(deck, result) -> None:
    g = deck.piston.gas
    if g.volumes is None:
        result.warn("piston.gas.volumes: not in the source; inter-ring volume taken as pi D x "
                    "radial clearance x ring separation (assumed)")
    if g.orifice_areas is None:
        result.warn("piston.gas.orifice_areas: not in the source; gap orifice taken as ring gap "
                    "x radial clearance (assumed)")
    if deck.piston.skirt is None:
        result.warn("piston.skirt: no skirt geometry (the source gives none); skirt friction "
                    "skipped, so the piston-assembly power is rings and oil-control ring only")


def _write(out, deck, result, np) -> None:
    from functools import partial

    from camtrain.piston.gas import ATMOSPHERE

    theta = out.theta
    result.add_axis("ring_angle", theta, "rad",
                    "crank angle from firing TDC (piston-assembly grid)")
    col = partial(result.add_column, axis="ring_angle")
    col("liner_speed", out.liner_speed, "m/s", "liner speed relative to the piston, + towards "
        "the crankcase (Yang eq. 5.16)")
    gas = out.gas.pressures[:, :-1] - ATMOSPHERE
    col("cylinder_pressure", gas[0], "Pa", "cylinder pressure, gauge")
    for i in range(1, gas.shape[0] - 1):
        col(f"inter_ring_pressure_{i}", gas[i], "Pa",
            f"gas pressure between rings {i} and {i + 1}, gauge (Yang §5.2)")
    for i, (rc, flooded, force) in enumerate(zip(out.pack.starved, out.pack.flooded,
                                                 out.ring_force, strict=True)):
        comp = f"ring_{i + 1}"
        c = partial(result.add_column, axis="ring_angle", component=comp)
        c("min_film", rc.h_min, "m", f"ring {i + 1}: minimum film (starved, final pass)")
        c("min_film_flooded", flooded.h_min, "m", f"ring {i + 1}: minimum film, flooded")
        c("friction", force, "N", f"ring {i + 1}: friction force on the ring, + towards the "
          "crankcase (starved)")
        c("friction_flooded", flooded.friction * np.pi * deck.engine.bore, "N",
          f"ring {i + 1}: friction force, flooded")
        c("power", force * out.liner_speed, "W", f"ring {i + 1}: friction power")
        j = int(np.argmin(rc.h_min))
        m = partial(result.add_metric, component=comp)
        m("min_film", rc.h_min[j], "m", f"ring {i + 1}: thinnest film (starved)", theta[j])
        j = int(np.argmin(flooded.h_min))
        m("min_film_flooded", flooded.h_min[j], "m", f"ring {i + 1}: thinnest film, flooded",
          theta[j])
        j = int(np.argmax(np.abs(force)))
        m("peak_friction", abs(force[j]), "N", f"ring {i + 1}: largest friction force", theta[j])
        m("power_mean", out.ring_power[i], "W", f"ring {i + 1}: cycle-mean friction power")
        m("boundary_share", float(np.mean(rc.boundary)), "-",
          f"ring {i + 1}: share of the cycle below the composite roughness")
        m("cycles", rc.cycles, "-", f"ring {i + 1}: cycles marched (last pass)")
    if out.ocr_force is not None:
        col("oil_control_ring_friction", out.ocr_force, "N", "oil-control ring friction "
            "(boundary, Yang §5.5)")
        result.add_metric("oil_control_ring_power_mean", out.ocr_power, "W",
                          "oil-control ring: cycle-mean friction power")
    if out.skirt_force is not None:
        col("skirt_friction", out.skirt_force, "N", "skirt Couette friction (Yang eq. 5.37)")
        result.add_metric("skirt_power_mean", out.skirt_power, "W",
                          "skirt: cycle-mean friction power")
    for i in range(1, gas.shape[0] - 1):
        j = int(np.argmax(gas[i]))
        result.add_metric(f"inter_ring_pressure_{i}_peak", gas[i][j], "Pa",
                          f"peak gas pressure between rings {i} and {i + 1}", theta[j])
    result.add_metric("gas_mass_residual", float(np.max(out.gas.mass_residual)), "-",
                      "gas: relative mass balance of the inter-ring volumes over the cycle")
    result.add_metric("piston_power_mean", out.power, "W",
                      "one piston assembly: cycle-mean friction power")
    result.add_metric("piston_power_total", out.engine_power, "W",
                      f"all {out.cylinders} piston assemblies: cycle-mean friction power")
