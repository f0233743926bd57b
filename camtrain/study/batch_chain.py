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


def _broadcast(fields: dict, shape: tuple[int, int]) -> dict:
    return {k: np.broadcast_to(v, shape) if isinstance(v, np.ndarray) else v
            for k, v in fields.items()}


def flat_kinematics(valve, scal: dict, n: int):
    """Kinematics of a clockwise flat-faced follower for every case (Ball 1988 eqs 3.4-3.6 by
    the kernel a single run uses), each array of shape (cases, angles)."""
    from camtrain.mechanisms import Kinematics
    from camtrain.mechanisms.translating import translating_contact

    shape = (n, valve.theta.size)
    fields = translating_contact(valve.theta, valve.lift, valve.d1, valve.d2,
                                 base_radius=scal["base_radius"], follower_radius=np.inf,
                                 offset=0.0, omega=scal["omega"])
    with np.errstate(divide="ignore"):
        ratio = 1.0 / fields["arm_normal"]
    lc = valve
    arrays = _broadcast(dict(
        theta=lc.theta, valve_lift=lc.lift, valve_d1=lc.d1, valve_d2=lc.d2, valve_d3=lc.d3,
        cam_lift=lc.lift, cam_d1=lc.d1, cam_d2=lc.d2, rocker_ratio=ratio,
        arm_valve=np.ones_like(lc.lift), q=lc.lift, q_d1=lc.d1, q_d2=lc.d2, **fields), shape)
    return Kinematics(mechanism="flat-faced translating", rotation="clockwise",
                      omega=scal["omega"], inertia={"follower_mass": np.broadcast_to(lc.d2, shape)},
                      **arrays)


def flat_geometry_ok(kin, face_length) -> np.ndarray:
    """Per case: the checks of a flat follower pass (convex cam, contact on the face;
    :mod:`camtrain.mechanisms.checks`). A case that fails runs alone and reports the error."""
    ok = np.all(kin.cam_radius > 0.0, axis=1)
    if face_length is not None:
        ok &= np.max(np.abs(kin.eccentricity), axis=1) <= 0.5 * face_length
    return ok


def contact_of(datum, scal: dict):
    """The datum's contact model with the per-case columns in place of its scalars."""
    from camtrain.contact.model import CamContact

    base = CamContact.from_deck(datum)
    lub = dataclasses.replace(base.lubricant) if base.lubricant is not None else None
    for name in ("viscosity", "pressure_viscosity", "roughness"):
        if lub is not None and isinstance(scal[name], np.ndarray):
            object.__setattr__(lub, name, scal[name])
    trib = base.tribology
    if isinstance(scal["boundary_friction"], np.ndarray):
        trib = dataclasses.replace(trib)
        object.__setattr__(trib, "boundary_friction", scal["boundary_friction"])
    return dataclasses.replace(base, reduced_modulus=scal["reduced_modulus"],
                               width=scal["width"], lubricant=lub, tribology=trib)


def _rows(values, index) -> np.ndarray:
    """values[r, index[r]] for every row r."""
    return np.take_along_axis(np.broadcast_to(values, index.shape[:1] + values.shape[-1:]),
                              index[:, None], axis=1)[:, 0]


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

    kin = flat_kinematics(valve, scal, n)
    c = datum.clearance
    lash = c is not None and c.lash_adjuster
    clearance = 0.0 if (c is None or lash) else c.valve_clearance
    spring = datum.spring
    load_kw = dict(rate=scal["rate"], preload_compression=scal["preload_compression"],
                   valve_mass=scal["valve_mass"], body_inertia=body_inertia(datum),
                   progressive=(spring.progressive_quadratic, spring.progressive_cubic))
    mu_b = scal["boundary_friction"]
    # no friction arm (flat face): one pass at the boundary coefficient, as iterate_load does
    load = np.asarray(contact_load(kin, np.asarray(mu_b, dtype=float), clearance=clearance,
                                   base_load=c.adjuster_load if lash else 0.0, **load_kw),
                      dtype=float)
    load = np.broadcast_to(load, kin.theta.shape)
    inside = contact_mask(kin.valve_lift, clearance)
    contact = contact_of(datum, scal)
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
                load_kw=load_kw, clearance=clearance, mu=mu_b)


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
    load, inside = out["load"], out["inside"]
    i_max = np.argmax(load, axis=1)
    has_inside = bool(np.any(inside))
    i_min = np.argmin(np.where(inside, load, np.inf), axis=1)
    speeds = bounce_speeds(kin, out["mu"], clearance=out["clearance"], **out["load_kw"])
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
             ("pressure_angle_max", col["pressure_angle_max"], "rad"),
             ("min_base_radius_convex", convex, "m")]
        m += [(f"zero_entrainment_{j + 1}", a, "rad")
              for j, a in enumerate(zeros[r])]
        m.append(("load_max", col["load_max"], "N"))
        if has_inside:
            m.append(("load_min", col["load_min"], "N"))
        m.append(("load_iterations", 1.0, "-"))
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
        per_case.append(m)
    return per_case
