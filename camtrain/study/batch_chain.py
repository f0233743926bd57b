"""The valve-train chain for many sweep cases at once: (cases, angles) arrays.

The cases of a batch share the deck except for scalars the chain uses elementwise (speed, base
radius, spring, valve-side mass, lubricant, boundary coefficient, materials, cam width); each
such scalar becomes a column of shape (cases, 1) and broadcasts against the angle grid through
the same physics functions a single run calls: the flat follower's contact kernel
(:func:`camtrain.mechanisms.translating.translating_contact`), the rigid-train load
(:func:`camtrain.loads.contact_load`), the pair's contact model (Hertz, film, friction laws) and
the torque and power formulas. The metrics of each case are then read from its row, as the
effects write them for one run. :mod:`camtrain.study.batch` decides which sweeps qualify and runs
everything else case by case.
"""
from __future__ import annotations

import dataclasses

import numpy as np

#: scalars read from every case's model: name -> getter of the validated model (SI units)
SCALARS = {
    "omega": lambda m: m.speed.omega,
    "base_radius": lambda m: m.cam.base_radius,
    "width": lambda m: m.cam.width,
    "rate": lambda m: m.spring.rate,
    "preload_compression": lambda m: m.spring.preload_compression,
    "valve_mass": lambda m: m.masses.valve_side,
    "viscosity": lambda m: m.lubricant.viscosity,
    "pressure_viscosity": lambda m: m.lubricant.pressure_viscosity,
    "roughness": lambda m: m.lubricant.roughness,
    "boundary_friction": lambda m: m.tribology.boundary_friction,
    "follower_radius": lambda m: m.mechanism.follower_radius,
}


def columns(models: list) -> dict[str, object]:
    """Each scalar of the chain over the cases: a plain float when all cases share it (the
    physics then sees exactly the number a single run sees), else a (cases, 1) column."""
    from camtrain.contact.model import modulus

    getters = dict(SCALARS, reduced_modulus=modulus)
    out: dict[str, object] = {}
    for name, get in getters.items():
        values = [get(m) for m in models]
        first = values[0]
        if all(v == first for v in values):
            out[name] = first
        else:
            out[name] = np.array(values, dtype=float)[:, None]
    return out


def translating_kinematics(datum, valve, scal: dict, n: int):
    """Kinematics of a clockwise flat-faced or domed translating follower (a tapered cam too)
    for every case, by the builder a single run uses
    (:func:`camtrain.mechanisms.translating.translating_kinematics`), each array of shape
    (cases, angles)."""
    from camtrain.mechanisms.translating import translating_kinematics as build

    mech = datum.mechanism
    flat = mech.type == "flat"
    taper = None if flat or not datum.cam.taper_angle > 0.0 else float(datum.cam.taper_angle)
    return build(valve, mech.type, base_radius=scal["base_radius"],
                 follower_radius=np.inf if flat else scal["follower_radius"],
                 offset=0.0 if flat or taper is not None else mech.offset, omega=scal["omega"],
                 taper_angle=taper, shape="spherical" if flat else mech.follower_shape, cases=n)


def geometry_ok(datum, kin) -> np.ndarray:
    """Per case: the geometry checks of a single run pass (:mod:`camtrain.mechanisms.checks`:
    a convex cam under a flat face; no cusp and no concave flank tighter than the grinding
    wheel under a domed one; the contact on the face). A case that fails runs alone and
    reports the error."""
    mech = datum.mechanism
    rc = kin.cam_radius
    if mech.type == "flat":
        ok = np.all(rc > 0.0, axis=1)
    else:
        ok = ~np.any((rc <= 0.0) & (rc > -kin.follower_radius), axis=1)
        wheel = mech.grinding_wheel_radius
        if wheel is not None and wheel > 0.0:
            ok &= ~np.any((rc < 0.0) & (-rc < wheel), axis=1)
    if mech.face_length is not None:
        ok &= np.max(np.abs(kin.eccentricity), axis=1) <= 0.5 * mech.face_length
    return ok


def contact_of(datum, scal: dict):
    """The datum's contact model with the per-case columns in place of its scalars."""
    from camtrain.contact.model import CamContact

    base = CamContact.from_deck(datum)
    # every case scalar is set, also one the chunk shares: it may differ from the datum's
    lub = dataclasses.replace(base.lubricant) if base.lubricant is not None else None
    for name in ("viscosity", "pressure_viscosity", "roughness"):
        if lub is not None:
            object.__setattr__(lub, name, scal[name])
    trib = dataclasses.replace(base.tribology)
    object.__setattr__(trib, "boundary_friction", scal["boundary_friction"])
    return dataclasses.replace(base, reduced_modulus=scal["reduced_modulus"],
                               width=scal["width"], lubricant=lub, tribology=trib)


def zero_crossings_rows(theta, values) -> list[list[float]]:
    """Per row, the angles where the periodic ``values`` change sign: the arithmetic of
    :func:`camtrain.effects.kinematics.zero_crossings`, on every row at once."""
    v = np.asarray(values, dtype=float)
    v_next = np.roll(v, -1, axis=-1)
    t_next = np.roll(theta, -1).copy()
    t_next[-1] += 2.0 * np.pi
    rows, idx = np.nonzero((v == 0.0) | (np.sign(v) * np.sign(v_next) < 0))
    here, after = v[rows, idx], v_next[rows, idx]
    with np.errstate(divide="ignore", invalid="ignore"):
        angle = theta[idx] + here / (here - after) * (t_next[idx] - theta[idx])
    angle = (angle + np.pi) % (2.0 * np.pi) - np.pi
    before = v[rows, idx - 1]
    out: list[list[float]] = [[] for _ in range(v.shape[0])]
    for r, i, h, b, a in zip(rows.tolist(), idx.tolist(), here.tolist(), before.tolist(),
                             angle.tolist(), strict=True):
        if h == 0.0:
            if b != 0.0:   # a run of exact zeros is reported once, at its start
                out[r].append(float(theta[i]))
            continue
        out[r].append(a)
    return out


def run_chain(datum, valve, scal: dict, n: int):
    """Every case's per-angle physics of the chain kinematics -> loads -> hertz -> film ->
    friction -> power; returns a dict of (cases, angles) arrays and the products."""
    from camtrain.effects.loads import body_inertia
    from camtrain.formulas import cam_torque, friction_torque
    from camtrain.loads import contact_load, contact_mask
    from camtrain.loads.iteration import iterate_cases

    kin = translating_kinematics(datum, valve, scal, n)
    c = datum.clearance
    lash = c is not None and c.lash_adjuster
    clearance = 0.0 if (c is None or lash) else c.valve_clearance
    spring = datum.spring
    load_kw = dict(rate=scal["rate"], preload_compression=scal["preload_compression"],
                   valve_mass=scal["valve_mass"], body_inertia=body_inertia(datum),
                   progressive=(spring.progressive_quadratic, spring.progressive_cubic))
    mu_b = scal["boundary_friction"]
    base_load = c.adjuster_load if lash else 0.0
    contact = contact_of(datum, scal)

    def load_of_mu(mu):
        return np.broadcast_to(contact_load(kin, mu, clearance=clearance, base_load=base_load,
                                            **load_kw), kin.theta.shape)

    depends = np.any(kin.arm_friction != 0.0, axis=1)
    if np.any(depends) and not np.all(depends):
        raise ValueError("cases with and without a friction arm")   # run them alone
    # Ball's friction/load iteration, each case converging on its own; one pass at the
    # boundary coefficient without a friction arm (flat face), as a single run does
    solver = datum.solver
    sol = iterate_cases(load_of_mu, (lambda w: contact.solve(kin, w).force)
                        if np.all(depends) else None, mu0=mu_b,
                        tolerance=solver.friction_tolerance,
                        max_iterations=solver.friction_max_iterations)
    load, mu_solved, iterations, converged = sol.load, sol.mu, sol.iterations, sol.converged
    inside = contact_mask(kin.valve_lift, clearance)
    load0 = np.maximum(load, 0.0)
    hz = contact.hertz(kin, load0)
    film = contact.film(kin, load0)
    friction = contact.friction(kin, load0, hz, film)
    force = friction.force
    tf = np.asarray(friction_torque(force, kin.friction_arm), dtype=float)
    total = np.asarray(cam_torque(load0, kin.torque_arm_normal, force, kin.friction_arm),
                       dtype=float)
    return dict(kin=kin, load=load, load0=load0, inside=inside, hertz=hz, film=film,
                force=force, friction_torque=tf, cam_torque=total,
                power=tf * np.abs(scal["omega"]), dissipation=force * np.abs(kin.sliding),
                load_kw=load_kw, clearance=clearance, mu=mu_b, mu_solved=mu_solved,
                iterations=iterations, converged=converged,
                guides=_guides(datum, kin, contact))


def _guides(datum, kin, contact):
    """The guide losses (:func:`camtrain.contact.guides.guide_losses`) of every case, or None
    when the deck has no [guides]."""
    if datum.guides is None:
        return None
    from types import SimpleNamespace

    from camtrain.contact.guides import guide_losses

    deck = SimpleNamespace(guides=datum.guides, lubricant=contact.lubricant,
                           mechanism=datum.mechanism)
    return guide_losses(deck, kin)


def _guide_metrics(losses, n: int) -> list[tuple[str, list[float]]]:
    """The guides effect's metrics per case: each guide's cycle-mean power and their sum."""
    if losses is None:
        return []
    from camtrain.formulas import cycle_mean

    out, total = [], np.zeros(n)
    for name, power in (("follower_guide", losses.follower_guide),
                        ("valve_guide", losses.valve_guide)):
        if power is None:
            continue
        mean = np.asarray(cycle_mean(np.broadcast_to(power, (n, np.shape(power)[-1]))),
                          dtype=float)
        total = total + mean
        out.append((f"{name}_power_mean", mean.tolist()))
    out.append(("guide_power_mean", total.tolist()))
    return out


def metrics(datum, out: dict, n: int) -> list[list[tuple[str, float, str]]]:
    """Per case, the metrics the kinematics, loads, hertz, film, friction and power effects
    write for a single run (names, order and units theirs; lift metrics are added by the
    caller), as lists of (name, value, unit)."""
    from camtrain.formulas import cycle_mean
    from camtrain.loads.bounce import bounce_speeds
    from camtrain.units import rad_s_to_rpm

    kin = out["kin"]
    rows = np.arange(n)
    theta = kin.theta[0]
    nose = int(np.argmax(kin.valve_lift[0]))
    rc, ecc, pa = kin.cam_radius, kin.eccentricity, kin.pressure_angle
    i_rc = np.argmin(rc, axis=1)
    i_ecc = np.argmax(np.abs(ecc), axis=1)
    i_pa = np.argmax(np.abs(pa), axis=1)
    convex = float(np.max(-(kin.valve_lift[0] + kin.valve_d2[0])))
    flat = datum.mechanism.type == "flat"
    load, inside = out["load"], out["inside"]
    i_max = np.argmax(load, axis=1)
    has_inside = bool(np.any(inside))
    i_min = np.argmin(np.where(inside, load, np.inf), axis=1)
    speeds = bounce_speeds(kin, out["mu_solved"], clearance=out["clearance"], **out["load_kw"])
    i_b = np.argmin(speeds, axis=1)
    pmax = out["hertz"].pmax
    i_h = np.argmax(np.where(np.isnan(pmax), -np.inf, pmax), axis=1)
    hmin = out["film"].min
    fin = np.isfinite(hmin)
    i_f = np.argmin(np.where(fin, hmin, np.inf), axis=1)
    any_fin = np.any(fin, axis=1)
    load0, force = out["load0"], out["force"]
    pos = load0 > 0.0
    capped = pos & (force >= out["mu"] * load0 * (1.0 - 1e-12))
    boundary = capped.sum(axis=1) / np.maximum(pos.sum(axis=1), 1)
    tf = out["friction_torque"]
    i_t = np.argmax(np.abs(tf), axis=1)
    means = [np.asarray(cycle_mean(out[k]), dtype=float) * np.ones(n)
             for k in ("power", "dissipation", "cam_torque")]
    columns = dict(
        cam_radius_at_max_lift=rc[:, nose], equivalent_radius_at_max_lift=kin.equivalent_radius[:, nose],
        cam_radius_min=rc[rows, i_rc], eccentricity_max=np.abs(ecc[rows, i_ecc]),
        pressure_angle_max=np.abs(pa[rows, i_pa]), load_max=load[rows, i_max],
        load_min=load[rows, i_min], bounce=speeds[rows, i_b], hertz_max=pmax[rows, i_h],
        hertz_at_max_lift=pmax[:, nose], film_min=hmin[rows, i_f], film_nose=hmin[:, nose],
        tf_peak=tf[rows, i_t])
    columns = {k: np.asarray(v, dtype=float).tolist() for k, v in columns.items()}
    boundary, means = boundary.tolist(), [m.tolist() for m in means]
    iterations = np.asarray(out["iterations"], dtype=float).tolist()
    guides = _guide_metrics(out["guides"], n)
    max_valve_lift = float(kin.valve_lift[0, nose])
    zeros = zero_crossings_rows(theta, kin.entrainment)
    per_case = []
    for r in range(n):
        col = {k: v[r] for k, v in columns.items()}
        m = [("max_valve_lift", max_valve_lift, "m"),
             ("cam_radius_at_max_lift", col["cam_radius_at_max_lift"], "m"),
             ("equivalent_radius_at_max_lift", col["equivalent_radius_at_max_lift"], "m"),
             ("cam_radius_min", col["cam_radius_min"], "m"),
             ("eccentricity_max", col["eccentricity_max"], "m"),
             ("pressure_angle_max", col["pressure_angle_max"], "rad")]
        if flat:   # Ball (1988) §2.2.1, as the kinematics effect reports it
            m.append(("min_base_radius_convex", convex, "m"))
        m += [(f"zero_entrainment_{j + 1}", a, "rad")
              for j, a in enumerate(zeros[r])]
        m.append(("load_max", col["load_max"], "N"))
        if has_inside:
            m.append(("load_min", col["load_min"], "N"))
        m.append(("load_iterations", iterations[r], "-"))
        if np.isfinite(col["bounce"]):
            m.append(("bounce_speed", float(rad_s_to_rpm(col["bounce"])), "rpm"))
        m += [("hertz_max", col["hertz_max"], "Pa"),
              ("hertz_at_max_lift", col["hertz_at_max_lift"], "Pa")]
        if any_fin[r]:
            m.append(("film_min", col["film_min"], "m"))
        m += [("film_min_at_max_lift", col["film_nose"], "m"),
              ("boundary_fraction", boundary[r], "-"),
              ("friction_torque_peak", col["tf_peak"], "N*m"),
              ("power_loss_mean", means[0][r], "W"),
              ("dissipation_mean", means[1][r], "W"),
              ("cam_torque_mean", means[2][r], "N*m")]
        m += [(name, values[r], "W") for name, values in guides]
        per_case.append(m)
    return per_case
