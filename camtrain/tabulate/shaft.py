"""Result columns and metrics of an elastic camshaft's answer (used by the one-way and the
coupled camshaft effects; not an effect itself)."""
from __future__ import annotations

import math

#: a load order within this fraction of a natural frequency is reported as near resonance
NEAR_RESONANCE = 0.1


def add_orders(res, name: str, rows, unit: str, what: str, orders: int, plane=None) -> None:
    """The harmonic orders 0..``orders`` of one curve per component (``rows``: component ->
    curve over the revolution) on the result's ``order`` axis (its own table,
    cycle_order.csv): the amplitude of each order, of the vector (curve, ``plane`` curve) when a
    second plane is given."""
    import numpy as np

    from camtrain.camshaft import harmonic_orders

    count = None
    for comp, curve in rows.items():
        amplitude = harmonic_orders(curve).amplitude
        if plane is not None:
            amplitude = np.hypot(amplitude, harmonic_orders(plane[comp]).amplitude)
        count = min(orders, amplitude.size - 1) + 1
        if "order" not in res.axes:
            res.add_axis("order", np.arange(count, dtype=float), "-",
                         "harmonic order (cycles per camshaft revolution)")
        label = comp.replace("_", " ")
        res.add_column(f"{name}_orders", amplitude[:count], unit,
                       f"{label}: {what}, amplitude of each order", component=comp,
                       axis="order")


def add_shaft(res, shaft, answer, theta, orders: int, omega: float) -> None:
    """Reactions per bearing with their orders, deflection and twist per lobe with theirs, the
    largest of each, the first natural frequencies and a warning near resonance."""
    import numpy as np

    from camtrain.camshaft import harmonic_orders

    bx, by = answer.bearing_x, answer.bearing_y
    for i in range(bx.shape[0]):
        comp, what = f"bearing_{i + 1}", f"bearing {i + 1}"
        res.add_column("reaction_x", bx[i], "N", f"{what}: load from the shaft, x",
                       component=comp)
        res.add_column("reaction_y", by[i], "N", f"{what}: load from the shaft, y",
                       component=comp)
        mag = np.hypot(bx[i], by[i])
        j = int(np.argmax(mag))
        res.add_metric("reaction_max", mag[j], "N", f"{what}: largest load from the shaft",
                       theta[j], component=comp)
        hx, hy = harmonic_orders(bx[i]), harmonic_orders(by[i])
        amplitude = np.hypot(hx.amplitude, hy.amplitude)
        for n in range(1, min(orders, amplitude.size - 1) + 1):
            res.add_metric(f"reaction_order_{n}", amplitude[n], "N",
                           f"{what}: order {n} amplitude of the load vector", component=comp)
    dx, dy, twist = answer.deflection_x, answer.deflection_y, answer.twist
    for i in range(dx.shape[0]):
        comp, what = f"lobe_{i + 1}", f"lobe {i + 1}"
        res.add_column("deflection_x", dx[i], "m", f"{what}: shaft deflection, x",
                       component=comp)
        res.add_column("deflection_y", dy[i], "m", f"{what}: shaft deflection, y",
                       component=comp)
        res.add_column("twist", twist[i], "rad",
                       f"{what}: twist against the drive (positive with the rotation)",
                       component=comp)
    add_orders(res, "reaction", {f"bearing_{i + 1}": bx[i] for i in range(bx.shape[0])}, "N",
               "load from the shaft (vector)", orders,
               plane={f"bearing_{i + 1}": by[i] for i in range(by.shape[0])})
    lobes = [f"lobe_{i + 1}" for i in range(dx.shape[0])]
    add_orders(res, "deflection", dict(zip(lobes, dx, strict=True)), "m",
               "shaft deflection (vector)", orders, plane=dict(zip(lobes, dy, strict=True)))
    add_orders(res, "twist", dict(zip(lobes, twist, strict=True)), "rad",
               "twist against the drive", orders)
    defl = np.hypot(dx, dy)
    i, j = np.unravel_index(int(np.argmax(defl)), defl.shape)
    res.add_metric("shaft_deflection_max", defl[i, j], "m",
                   f"largest shaft deflection at a lobe (lobe {i + 1})", theta[j])
    i, j = np.unravel_index(int(np.argmax(np.abs(twist))), twist.shape)
    res.add_metric("shaft_twist_max", abs(twist[i, j]), "rad",
                   f"largest twist of a lobe against the drive (lobe {i + 1})", theta[j])
    bending = float(shaft.beam.natural_frequencies(1)[0])
    twisting = float(shaft.torsion.natural_frequencies()[0])
    res.add_metric("shaft_bending_frequency_1", bending / (2.0 * math.pi), "Hz",
                   "first bending natural frequency of the camshaft")
    res.add_metric("shaft_torsion_frequency_1", twisting / (2.0 * math.pi), "Hz",
                   "first torsional natural frequency of the camshaft")
    for name, w in (("bending", bending), ("torsional", twisting)):
        near = [k for k in range(1, orders + 1)
                if omega > 0 and abs(k * omega - w) < NEAR_RESONANCE * w]
        if near:
            res.warn(f"camshaft: load order(s) {near} within {NEAR_RESONANCE:.0%} of the first "
                     f"{name} natural frequency ({w / (2 * math.pi):.0f} Hz): resonant shaft")


def add_coupled(res, problem, r, orders: int) -> None:
    """The coupled camshaft's outputs (:mod:`camtrain.coupled`: ``problem`` and its result
    ``r``): the shaft's; every lobe's coupled load and valve acceleration with their orders;
    the summed load; the solver's convergence; what only some solvers give (missed staggered
    steps, the marched film, the gap to a monolithic start, every lobe's separations)."""
    import numpy as np

    add_shaft(res, problem.shaft, r.shaft, problem.theta, orders, problem.omega)
    lobes = [f"lobe_{j + 1}" for j in range(len(r.loads))]
    for j, (comp, load) in enumerate(zip(lobes, r.loads, strict=True)):
        i, k = int(np.argmax(load)), f"lobe {j + 1}"
        res.add_columns([("load", load, "N", f"{k}: contact load of its elastic train on the "
                          f"elastic shaft ({r.solver})"), ("valve_acceleration",
                         r.valve_acceleration[j], "m/s^2", f"{k}: valve acceleration")], comp)
        res.add_metric("load_max", load[i], "N", f"{k}: largest contact load", problem.theta[i],
                       component=comp)
    res.add_column("camshaft_load_sum", np.sum(r.loads, axis=0), "N",
                   "sum of the lobes' contact loads")
    add_orders(res, "load", dict(zip(lobes, r.loads, strict=True)), "N", "contact load", orders)
    add_orders(res, "valve_acceleration", dict(zip(lobes, r.valve_acceleration, strict=True)),
               "m/s^2", "valve acceleration", orders)
    res.add_metrics([("coupling_passes", r.passes, "-", f"passes of the {r.solver}"),
                     ("coupling_change", r.change, "-", "relative change between the last two "
                      f"passes of the {r.solver}")])
    if not r.converged:
        res.warn(f"camshaft coupling: no periodic state after {r.passes} passes of the "
                 f"{r.solver} (last change {r.change:.3g} > {problem.coupling.tolerance:g}); "
                 "the results are the last pass's")
    if r.missed is not None:
        res.add_metric("coupling_step_misses", r.missed, "-", "steps of the last revolution "
                       "whose staggered passes did not agree with their predicted loads")
    if r.missed:
        res.warn(f"camshaft coupling: {r.missed} steps of the staggered march kept a load that "
                 f"differs from the shaft's after {problem.coupling.iterations} passes (give "
                 "more coupling_iterations, or a smaller step)")
    for j, load in enumerate(r.loads if r.film is not None else ()):
        res.add_column("film", np.where(load > 0.0, r.film[j], np.nan), "m", f"lobe {j + 1}: "
                       "level-1 squeeze film of its cam contact, marched with the coupled trains "
                       "at every step (NaN: out of contact)", component=f"lobe_{j + 1}")
    if r.start_gap is not None:
        res.add_metric("coupling_start_gap", r.start_gap, "-", "largest difference of any "
                       "lobe's load between the waveform iteration and the monolithic march it "
                       "started from, over the largest marched load")
    for j, angles in enumerate(r.separations or ()):
        res.add_metric("separations", len(angles), "-", f"lobe {j + 1}: losses of the cam "
                       "contact while the valve is in flight (not its landing on the seat)",
                       component=lobes[j])
        for at in angles:
            res.add_event("contact_loss", at, f"lobe {j + 1}: the cam loses the follower",
                          component=lobes[j])
