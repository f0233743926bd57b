"""Many sweep cases of the valve-train chain at once, by the code of a single run.

The cases of a batch share the deck except for scalars the chain uses elementwise (speed, base
radius, spring, valve-side mass, lubricant, boundary coefficient, materials, cam width); each
such scalar becomes a column of shape (cases, 1) (:func:`columns`, :func:`contact_of`) and
broadcasts against the angle grid through the pieces a single run calls: the translating
follower's kinematics builder, the rigid-train load and Ball's friction/load iteration
(:func:`camtrain.loads.iteration.iterate_cases`), the pair's contact model, the torques, the
geometry predicates, and the metric functions of the kinematics, loads, hertz, film, friction,
power and guides effects (:mod:`camtrain.metric_rows`). Nothing of the chain is written here
a second time: :func:`run_chain` calls those pieces in the plan's order.
:mod:`camtrain.study.batch` decides which sweeps qualify and runs everything else case by case.
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
                 taper_angle=taper, shape=_face_shape(mech), cases=n)


def _face_shape(mech) -> str:
    """The face shape of a single run: a roller is cylindrical (camtrain.assemble.mechanism)."""
    if mech.type == "flat":
        return "spherical"
    return "cylindrical" if mech.follower == "roller" else mech.follower_shape


def geometry_ok(datum, kin) -> np.ndarray:
    """Per case: the geometry checks of a single run pass
    (:func:`camtrain.mechanisms.checks.cases_pass`). A case that fails runs alone and reports
    the error."""
    from camtrain.mechanisms.checks import cases_pass

    mech = datum.mechanism
    return cases_pass(kin, flat=mech.type == "flat", face_length=mech.face_length,
                      min_concave_radius=mech.grinding_wheel_radius)


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


def run_chain(datum, valve, scal: dict, n: int) -> dict:
    """Every case's chain kinematics -> loads -> hertz -> film -> friction -> power (-> guides)
    by the physics and the metric definitions of the effects, on (cases, angles) arrays;
    returns the kinematics, load, Hertz field and film, which cases converged and the
    metrics (:class:`camtrain.metric_rows.CaseMetric`, in the effects' order)."""
    from camtrain.effects import film as film_effect
    from camtrain.effects import friction as friction_effect
    from camtrain.effects import hertz as hertz_effect
    from camtrain.effects import kinematics as kinematics_effect
    from camtrain.effects import loads as loads_effect
    from camtrain.effects import power as power_effect
    from camtrain.loads import contact_load, contact_mask
    from camtrain.loads.bounce import bounce_speeds
    from camtrain.loads.iteration import iterate_cases

    kin = translating_kinematics(datum, valve, scal, n)
    kw = dict(loads_effect.load_inputs(datum), rate=scal["rate"], valve_mass=scal["valve_mass"],
              preload_compression=scal["preload_compression"])
    spring = {k: v for k, v in kw.items() if k not in ("clearance", "base_load")}
    mu_b = scal["boundary_friction"]
    contact = contact_of(datum, scal)

    def load_of_mu(mu):
        return np.broadcast_to(contact_load(kin, mu, **kw), kin.theta.shape)

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
    load = sol.load
    inside = contact_mask(kin.valve_lift, kw["clearance"])
    load0 = np.maximum(load, 0.0)
    hz = contact.hertz(kin, load0)
    film = contact.film(kin, load0)
    force = contact.friction(kin, load0, hz, film).force
    tf, total, power, dissipation = power_effect.pair_torques(kin, load0, force)
    mu = sol.mu if sol.friction is not None else mu_b   # as the loads effect takes it
    speeds = bounce_speeds(kin, mu, clearance=kw["clearance"], **spring)
    theta, nose = kin.theta, kin.nose
    zeros = kinematics_effect.zero_crossings_rows(valve.theta, kin.entrainment)
    metrics = (kinematics_effect.pair_metrics(kin, "", datum.mechanism.type == "flat", zeros)
               + loads_effect.load_metrics(theta, load, inside, sol.iterations,
                                           solver.friction_tolerance, speeds)
               + hertz_effect.hertz_metrics(theta, hz.pmax, nose)
               + film_effect.film_metrics(theta, film.min, nose)
               + friction_effect.friction_metrics(load0, force, mu_b)
               + power_effect.power_metrics(theta, tf, power, dissipation, total)
               + _guide_metrics(datum, kin, contact))
    return dict(kin=kin, load=load, hertz=hz, film=film, converged=sol.converged,
                metrics=metrics)


def _guide_metrics(datum, kin, contact) -> list:
    """The guides effect's metrics of every case (none when the deck has no [guides])."""
    if datum.guides is None:
        return []
    from types import SimpleNamespace

    from camtrain.contact.guides import guide_losses
    from camtrain.effects.guides import guide_metrics

    deck = SimpleNamespace(guides=datum.guides, lubricant=contact.lubricant,
                           mechanism=datum.mechanism)
    return guide_metrics(guide_losses(deck, kin))
