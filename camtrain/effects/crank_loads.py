"""Crank-train loads effect: the load diagram of every big-end and main bearing of an engine deck.

Slider-crank loads of each cylinder (Yang 1992 eqs 1.1-1.5: gas force, reciprocating and
rotating inertia of the two-mass rod, side thrust), the big-end load in rod axes with the
crank-pin speed relative to the rod (eq. 2.1, or the exact swing), and the main-bearing loads
by the statically determinate bay split with the out-of-balance forces and the flywheel weight
(§1.2.2), in block axes, on the crank-angle grid of one cycle (:mod:`camtrain.engine.loads`).
"""
from __future__ import annotations


def missing(deck) -> list[str]:
    """A bare engine deck (correlations only) leaves the crank train out."""
    e = deck.engine
    lack = [name for name, absent in (
        ("[[cylinders]]", not deck.cylinders), ("[[pressure]]", not deck.pressure),
        ("engine.rod_length", e.rod_length is None), ("engine.piston_mass", e.piston_mass is None),
        ("engine.rod_mass", e.rod_mass is None), ("engine.bay_lengths", e.bay_lengths is None))
        if absent]
    return lack


def reason(deck, planned) -> str:
    s = deck.solver
    return (f"{len(deck.cylinders)} cylinders, {len(deck.engine.bay_lengths)} bays at "
            f"{deck.rpm:g} rpm; {s.pressure_interpolation} pressure, {s.rod_speed} rod speed, "
            f"{deck.solver.crank_step * 57.29577951308232:g} deg step")


def run(deck, inputs, result):
    from functools import partial

    import numpy as np

    from camtrain.assemble import engine as build
    from camtrain.engine import crank_train_loads

    for message in deck.advisories():
        result.warn(message)
    s = deck.solver
    loads = crank_train_loads(build.engine(deck), deck.speed.omega, s.crank_step,
                              interpolation=s.pressure_interpolation, rod_speed=s.rod_speed)
    th = loads.angle
    result.add_axis("crank_angle", th, "rad", "crank angle from the firing TDC of cylinder 1")
    peak = (0.0, 0.0, "")
    for i, c in enumerate(loads.cylinders):
        comp = f"big_end_{i + 1}"
        col = partial(result.add_column, component=comp, axis="crank_angle")
        what = f"cylinder {i + 1}"
        col("pressure", c.pressure, "Pa", f"{what}: cylinder pressure (gauge)")
        col("gas_force", c.gas_force, "N", f"{what}: gas force on the piston (eq. 1.1)")
        col("axial_force", c.axial_force, "N",
            f"{what}: gas minus reciprocating inertia along the cylinder (compression +)")
        col("side_thrust", c.side_thrust, "N", f"{what}: piston side thrust (eq. 1.5)")
        col("load_x", c.load_x, "N", f"big-end {i + 1}: load on the film, rod axis x_r")
        col("load_y", c.load_y, "N", f"big-end {i + 1}: load on the film, along the rod")
        col("load", c.load, "N", f"big-end {i + 1}: load magnitude")
        col("journal_speed", np.broadcast_to(c.omega_journal, th.shape), "rad/s",
            f"big-end {i + 1}: crank-pin speed relative to the rod")
        j = int(np.argmax(c.load))
        result.add_metric("max_load", c.load[j], "N", f"big-end {i + 1}: peak load", th[j],
                          component=comp)
        if c.load[j] > peak[0] * (1.0 + 1e-9):  # equal cylinders: the first one
            peak = (float(c.load[j]), float(th[j]), comp)
    for k in range(loads.mains.load_x.shape[0]):
        comp = f"main_{k + 1}"
        col = partial(result.add_column, component=comp, axis="crank_angle")
        mag = loads.mains.load[k]
        col("load_x", loads.mains.load_x[k], "N", f"main {k + 1}: load on the film, block x")
        col("load_y", loads.mains.load_y[k], "N",
            f"main {k + 1}: load on the film, block y (along the cylinders)")
        col("load", mag, "N", f"main {k + 1}: load magnitude")
        j = int(np.argmax(mag))
        result.add_metric("max_load", mag[j], "N", f"main {k + 1}: peak load", th[j],
                          component=comp)
    result.add_metric("big_end_max_load", peak[0], "N",
                      f"largest big-end load (on {peak[2].replace('_', ' ')})", peak[1])
    return loads
