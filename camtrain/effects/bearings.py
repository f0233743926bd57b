"""Bearings effect: camshaft bearing loads and orbits.

The lobe forces of the camshaft effect and the drive hub load (:func:`camtrain.camshaft.
pulley_load`, from the summed torque) are shared between the bearings as statically determinate
beams (Ball 1988 §6.3; Yang 1992 §3.3.1, Fig. 3.6). Each bearing's load diagram over one camshaft
revolution then gives the journal orbit by Booker's mobility method (Yang eqs 1.12-1.16; Ball
eqs 6.1-6.6), marched until periodic; or the steady-load locus (Yang eq. 1.13); or Petroff's
concentric power (eq. 1.19). The film is the deck's ``camshaft.bearing_model``: the short-bearing
pi film (Ocvirk, as Ball and Yang) or the finite-length Reynolds film
(:mod:`camtrain.bearings.models`); ``auto`` picks per bearing by its land b/d. Power uses the pi
or 2 pi shear film (Yang eqs 1.21, 1.22). The orbit solver and its result columns are shared with
the stand-alone bearing deck (:mod:`camtrain.tabulate.bearing`).
"""
from __future__ import annotations

import math

TWO_PI = 2.0 * math.pi


def missing(deck) -> list[str]:
    if deck.camshaft is None:
        return ["[camshaft] section"]
    out = [] if deck.camshaft.bearings else ["[[camshaft.bearings]]"]
    if deck.camshaft.viscosity is None and deck.lubricant is None:
        out.append("camshaft.viscosity or lubricant.viscosity")
    return out


def _journal(deck, i, b):
    from camtrain.bearings import JournalBearing

    cs = deck.camshaft
    viscosity = cs.viscosity if cs.viscosity is not None else deck.lubricant.viscosity
    return JournalBearing(b.diameter, b.length, b.clearance, viscosity, b.groove_width,
                          name=f"camshaft.bearings[{i}]")


def reason(deck, planned) -> str:
    cs = deck.camshaft
    split = ("loads from the elastic camshaft" if "ElasticCamshaft" in planned
             else "loads split as simply supported bays")
    head = f"{len(cs.bearings)} bearings given; {split}; {cs.method} method"
    if cs.method == "mobility" and cs.orbit_points:
        head += (f", orbits marched on {cs.orbit_points} load angles per revolution "
                 "(camshaft.orbit_points)")
    if cs.method == "petroff":
        return head + " (concentric power, no film model)"
    from camtrain.deck.schema_bearing_model import film_model_options
    from camtrain.tabulate.bearing import model_reason

    options = film_model_options(cs, "bearing_")
    groups: dict[str, list[int]] = {}
    for i, b in enumerate(cs.bearings):
        groups.setdefault(model_reason(_journal(deck, i, b), options)[1], []).append(i + 1)
    parts = [f"bearing{'s' if len(ks) > 1 else ''} {', '.join(map(str, ks))}: {why}"
             for why, ks in groups.items()]
    return head + "; " + "; ".join(parts)


def bearing_loads(deck, shaft, res):
    """Loads on every camshaft bearing's film, (n_bearings, n_angles) each for x and y [N]."""
    import numpy as np

    from camtrain.camshaft import shaft_forces, split_beam_loads

    cs = deck.camshaft
    drive = None
    if cs.drive is not None:
        drive = (cs.drive.position, cs.drive.radius, cs.drive.hub_load_angle, cs.drive.preload)
    else:
        res.warn("no [camshaft.drive]: the drive hub load is left out, so the bearing "
                          "next to the drive is under-loaded")
    positions, fx, fy = shaft_forces(shaft.lobe_positions, shaft.lobe_forces, shaft.torque,
                                     drive)
    n = res["cam_angle"].size
    if not positions:
        zero = np.zeros((len(cs.bearings), n))
        return zero, zero.copy()
    return split_beam_loads([b.position for b in cs.bearings], positions, fx, fy, cs.overhang)


def run(deck, inputs, res):
    from functools import partial

    import numpy as np

    from camtrain.bearings import bearing_petroff_power
    from camtrain.bearings.product import BearingOrbits
    from camtrain.camshaft.product import CamshaftLoads, ElasticCamshaft
    from camtrain.deck.schema_bearing_model import film_model_options
    from camtrain.errors import ConvergenceError
    from camtrain.progress import detail
    from camtrain.tabulate.bearing import (
        CAMSHAFT_DECK_TERMS,
        add_orbit,
        deck_terms,
        model_reason,
        solve_bearing,
    )

    cs = deck.camshaft
    shaft = inputs[CamshaftLoads]
    theta = res["cam_angle"]
    omega = shaft.omega  # signed by the shaft rotation
    options = film_model_options(cs, "bearing_")
    elastic = inputs.get(ElasticCamshaft)
    if elastic is not None:  # the elastic shaft shared the loads ([camshaft.flexibility])
        bx, by = elastic.bearing_x, elastic.bearing_y
    else:
        bx, by = bearing_loads(deck, shaft, res)
    orbits, total = [], 0.0
    for i, b in enumerate(cs.bearings):
        k = i + 1
        detail(f"bearing {k} of {len(cs.bearings)}")
        what, comp = f"bearing {k}", f"bearing_{k}"
        met = partial(res.add_metric, component=comp)
        brg = _journal(deck, i, b)
        res.add_column("load_x", bx[i], "N", f"{what}: load on the film, x",
                       component=comp)
        res.add_column("load_y", by[i], "N", f"{what}: load on the film, y",
                       component=comp)
        mag = np.hypot(bx[i], by[i])
        j = int(np.argmax(mag))
        met("max_load", mag[j], "N", f"{what}: largest load", theta[j])
        petroff = float(bearing_petroff_power(brg, omega))
        met("petroff_power", petroff, "W", f"{what}: Petroff power (concentric journal)")
        # step error 1e-3 of the periodicity tolerance: the free steps' global error on these
        # decks is about 300 step errors (measured: 1.5e-6 to 3.8e-6 at 1e-8), below it
        try:
            with deck_terms(CAMSHAFT_DECK_TERMS, f"camshaft.bearings[{i}] (its load)"):
                orbit = solve_bearing(brg, bx[i], by[i], theta, omega, 0.0, angle_rate=abs(omega),
                                      period=TWO_PI, method=cs.method, film=cs.film,
                                      mobility=cs.mobility,
                                      tol=min(1e-8, 1e-3 * cs.bearing_tolerance),
                                      period_tol=cs.bearing_tolerance, max_cycles=cs.max_cycles,
                                      options=options, march_points=cs.orbit_points)
        except ConvergenceError as exc:
            res.warn(f"{what}: {exc}; no orbit reported")
            orbits.append(None)
            continue
        orbits.append(orbit)
        if orbit is None:
            met("power_mean", petroff, "W", f"{what}: Petroff power (method = petroff)")
            total += petroff
            continue
        add_orbit(res, orbit, comp, what, model_reason(brg, options)[0])
        total += orbit.mean_power
    res.add_metric("bearings_power_total", total, "W",
                   "cycle-mean friction power of all camshaft bearings")
    return BearingOrbits(tuple(orbits))


