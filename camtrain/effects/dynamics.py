"""Dynamics effect: the elastic valve train marched in time to its periodic state; its contact
load replaces the rigid train's (rank 1 over ``loads``), so Hertz, film, friction, power and the
camshaft run unchanged on it.

Physics in :mod:`camtrain.dynamics` (lumped train, integrators), the deck's [dynamics] section
turned into it in :mod:`camtrain.assemble.dynamics`. Writes the dynamic load, follower and valve
motion, spring and seat forces, contact status and the rigid load beside them; events for every
separation and re-contact during the lift event and every seat impact; warnings for bounce.
With ``dynamics.roller = "marched"`` it hands on the roller's speed marched with the train
(``RollerSpin``; its speed None otherwise), which the roller effect takes as the run's.
"""
from __future__ import annotations

MODEL = "elastic valve train in time (lumped masses, unilateral contact and seat)"


def missing(deck) -> list[str]:
    out = []
    if getattr(deck, "dynamics", None) is None:
        out.append("dynamics (the [dynamics] section)")
    if deck.spring is None:
        out.append("spring (rate, preload_compression)")
    if deck.masses is None:
        out.append("masses (valve_side)")
    return out


def model(deck, planned) -> str:
    """The train this effect marches, as far as the report's panels follow from it, as its
    optional parts joined by "+": a hydraulic lash adjuster (``lash_adjuster``, or
    ``lash_adjuster_ball`` with the dynamic check ball) and the roller's spin marched with the
    train (``roller``); "" for the train alone."""
    from camtrain.assemble.roller import marches_roller

    h = deck.dynamics.lash_adjuster if getattr(deck, "dynamics", None) is not None else None
    parts = []
    if h is not None:
        parts.append("lash_adjuster_ball" if h.check_valve == "ball" else "lash_adjuster")
    if marches_roller(deck):
        parts.append("roller")
    return "+".join(parts)


def reason(deck, planned) -> str:
    d = deck.dynamics
    spring = (f"{d.spring_elements}-element spring chain" if d.spring_elements else
              "single-rate spring")
    hla = ", hydraulic lash adjuster" if d.lash_adjuster is not None else ""
    spin = ", roller speed marched with the train" if model(deck, planned) else ""
    return f"[dynamics] given: elastic train, {d.integrator}, {spring}{hla}{spin}"


def makes(deck, planned) -> tuple[str, ...]:
    """The optional columns it writes (EffectSpec.optional_columns): the spring force at the
    retainer end of a spring chain (dynamics.spring_elements > 0), where surge sets it apart
    from the head's."""
    return ("spring_force_retainer",) if deck.dynamics.spring_elements > 0 else ()


def _separations(res, found) -> None:
    """Separations are the cam losing the follower while the valve is in flight (a jump); the
    contact opening after the valve has landed on its seat (taking up the lash at the end of the
    lift, or a rebound of the valve off its seat, which the seat-impact count reports) is a
    landing, reported with the valve's landing speed but neither counted nor warned about."""
    import math

    flights = [s for s in found.separations if s.in_flight]
    landings = [s for s in found.separations if not s.in_flight]
    for s in flights:
        res.add_event("contact_loss", s.loss, "the cam loses the follower (elastic train)")
        res.add_event("contact_regained", s.regained, f"the follower lands on the cam again at "
                      f"{abs(s.speed):.3g} m/s")
    landed = found.seat_impacts[0][1] if found.seat_impacts else math.nan
    for s in landings:
        res.add_event("landing", s.loss, f"the valve is on its seat (landed at {landed:.3g} m/s); "
                      "the cam contact opens across the lash")
    res.add_metric("separations", len(flights), "-", "losses of the cam contact while the valve "
                   "is in flight (a follower jump; the contact opening once the valve has landed "
                   "on its seat is a landing, not a separation)")
    res.add_metric("landings", len(landings), "-", "openings of the cam contact after the valve "
                   "landed on its seat (the lash taken up, or a rebound off the seat)")
    if found.seat_impacts:
        res.add_metric("landing_speed", landed, "m/s", "valve speed at its first landing on the "
                       "seat", found.seat_impacts[0][0])
    if not flights:
        return
    dwell = min(s.dwell for s in flights)
    res.add_metric("separation_dwell_min", dwell, "rad", "shortest separation")
    res.add_metric("separation_angle", flights[0].loss, "rad", "first loss of contact in flight",
                   flights[0].loss)
    deg = ", ".join(f"{math.degrees(s.loss):.1f}" for s in flights[:6])
    res.warn(f"valve-train separation: the cam loses the follower {len(flights)} times per "
             f"revolution while the valve is in flight (at {deg} deg; shortest dwell "
             f"{math.degrees(dwell):.3g} deg); loads there are impacts, not a design load; "
             "a stiffer spring (spring.rate, spring.preload_compression) or a lower "
             "speed.camshaft keeps the contact")


def _lash_adjuster(deck, run_setup, resp, res) -> None:
    """A hydraulic lash adjuster's columns, metrics and pump-up warning; the lift loss against
    the same train with the constant-load adjuster, marched alike."""
    from dataclasses import replace

    from camtrain.dynamics import march
    from camtrain.dynamics.hla import rigid_adjuster
    from camtrain.dynamics.hla.findings import adjuster_findings, adjuster_rows

    model = run_setup.model
    rigid = march(replace(rigid_adjuster(model), roller=None), run_setup.cam, run_setup.base,
                  run_setup.settings)
    height = deck.dynamics.lash_adjuster.checking_height
    found = adjuster_findings(resp, rigid, model, height)
    cols, mets, warns = adjuster_rows(resp, found, model, height)
    res.add_columns(cols)
    res.add_metrics(mets)
    for text in warns:
        res.warn(text)


def _roller(kin, tables, spin, load, res) -> None:
    """The marched roller's columns and metrics, and a warning where the marched load passed
    the roller's tables."""
    from camtrain.dynamics.spin.findings import spin_metrics, spin_rows

    res.add_columns(spin_rows(kin, tables, spin))
    res.add_metrics(spin_metrics(kin, tables, spin, load))
    top = float(load.max())
    if top > tables.load_cap:
        res.warn(f"roller: the marched contact load reaches {top:.4g} N, above the "
                 f"{tables.load_cap:.4g} N of the roller's traction and pin tables (3 x the rigid "
                 "train's largest load), where they are held: the roller speed there is "
                 "approximate")


def run(deck, inputs, res):
    import math

    import numpy as np

    from camtrain.assemble.dynamics import rigid_load, setup
    from camtrain.dynamics import StepTooLarge, march
    from camtrain.dynamics.findings import findings
    from camtrain.dynamics.spin.product import RollerSpin
    from camtrain.errors import field_error
    from camtrain.loads import ContactLoad, contact_mask
    from camtrain.mechanisms import TrainKinematics

    kin = inputs[TrainKinematics].main
    run_setup = setup(deck, kin)
    model, settings = run_setup.model, run_setup.settings
    try:
        resp = march(model, run_setup.cam, run_setup.base, settings)
    except StepTooLarge as exc:
        raise field_error("dynamics.steps_per_degree", str(exc),
                          deck.dynamics.steps_per_degree,
                          "a step below the stability limit") from None
    ratio = np.asarray(kin.rocker_ratio)
    load = resp.contact_force[0] * ratio
    rigid = rigid_load(deck, kin)
    inside = contact_mask(kin.valve_lift, run_setup.lash)
    f, v = model.follower, model.valve
    cols = (
        ("load", load, "N", "normal cam/follower contact load of the elastic train (0 while "
         "the follower is off the cam)"),
        ("rigid_load", rigid, "N", "contact load of the rigid train (quasi-static limit)"),
        ("follower_lift", resp.u[f], "m", "follower displacement referred to the valve"),
        ("follower_velocity", resp.v[f], "m/s", "follower velocity referred to the valve"),
        ("follower_acceleration", resp.a[f], "m/s^2", "follower acceleration referred to the "
         "valve"),
        ("valve_lift_dynamic", resp.u[v], "m", "valve displacement from rest on its seat"),
        ("valve_velocity", resp.v[v], "m/s", "valve velocity"),
        ("valve_acceleration", resp.a[v], "m/s^2", "valve acceleration"),
        ("spring_force", model.spring_force_at_head(resp.u), "N", "valve-spring force on the "
         "cylinder head"),
        ("seat_force", resp.contact_force[1], "N", "valve-seat force"),
        ("contact_status", (resp.contact_force[0] > 0.0).astype(float), "-",
         "1 while the cam touches the follower, 0 while separated"),
    )
    for name, values, unit, text in cols:
        res.add_column(name, values, unit, text)
    if model.chain:
        res.add_column("spring_force_retainer", model.spring_force_at_retainer(resp.u), "N",
                       "valve-spring force on the retainer (differs from the head's by surge)")
    res.add_axis("time", resp.time, "s", "time from the start of the last revolution marched")
    res.add_column("load", load, "N", "dynamic contact load against time", axis="time")
    res.add_column("valve_acceleration", resp.a[v], "m/s^2", "valve acceleration against time",
                   axis="time")
    i = int(np.argmax(load))
    res.add_metric("load_max", load[i], "N", "largest dynamic contact load", kin.theta[i])
    res.add_metric("rigid_load_max", float(np.max(rigid)), "N", "largest rigid-train load")
    res.add_metric("dynamic_load_ratio", load[i] / max(float(np.max(rigid)), 1e-300), "-",
                   "largest dynamic load / largest rigid load")
    res.add_metric("valve_acceleration_max", float(np.max(np.abs(resp.a[v]))), "m/s^2",
                   "largest valve acceleration")
    res.add_metric("natural_frequency_max", model.omega_max() / (2 * math.pi), "Hz",
                   "highest natural frequency of the train (contacts closed)")
    res.add_metric("time_step", run_setup.base.period / resp.steps, "s",
                   f"time step ({resp.steps} steps per revolution)")
    res.add_metric("cycles", resp.cycles, "-", "camshaft revolutions marched")
    res.add_metric("period_change", resp.change, "-", "change between the last two revolutions")
    found = findings(resp)
    _separations(res, found)
    if found.seat_impacts:
        speeds = [s for _, s in found.seat_impacts]
        res.add_metric("seat_impacts", len(speeds), "-", "valve landings on the seat")
        res.add_metric("seat_impact_speed_max", max(speeds), "m/s", "fastest valve landing")
        if len(speeds) > 1:
            res.warn(f"valve bounce: the valve lands on its seat {len(speeds)} times per "
                     f"revolution (fastest {max(speeds):.3g} m/s; dynamics.damping_ratio damps "
                     "the rebound, a gentler closing ramp, lift.ramps, lowers the landing speed)")
    if found.base_circle_changes:
        res.warn(f"zero lash: the follower touches and leaves the cam {found.base_circle_changes}"
                 " times on the base circle (ringing at no load; clearance.valve_clearance or "
                 "clearance.adjuster_load settles the base-circle contact)")
    if not resp.converged:
        res.warn(f"dynamics: no periodic state after {resp.cycles} revolutions (last change "
                 f"{resp.change:.3g} > period_tol {settings.period_tol:g}); results are the "
                 "last revolution")
    if model.series is not None:
        _lash_adjuster(deck, run_setup, resp, res)
    spin = RollerSpin()
    if resp.roller is not None:
        _roller(kin, model.roller, resp.roller, load, res)
        spin = RollerSpin(speed=np.asarray(resp.roller[0], dtype=float),
                          traction=np.asarray(resp.roller[2], dtype=float),
                          inertia=float(model.roller.inertia))
    if resp.cut_switches:
        res.warn(f"dynamics: {resp.cut_switches} steps had more contact changes than the "
                 "integrator locates per step (chattering); refine steps_per_degree")
    return ContactLoad(load=load, in_contact=inside, model=MODEL), spin
