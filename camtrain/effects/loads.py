"""Loads effect: cam/follower contact load per angle, friction/load iteration, loss of contact.

Reads the train's kinematics and the deck's spring, masses and clearance; returns a
:class:`camtrain.loads.ContactLoad` (model: the rigid train, Ball 1988 §4.2; or Ball App D for a
desmodromic train) and writes ``load[N]`` and ``valve_force[N]`` columns, the load metrics and the
camshaft speed of valve bounce. Physics lives in :mod:`camtrain.loads`; the friction of the
friction/load iteration is the contact model's (:mod:`camtrain.contact.friction`).
"""
from __future__ import annotations

import math

from camtrain.identity_cache import by_identity
from camtrain.metric_rows import CaseMetric, anywhere, at, one_case

RIGID = "rigid valve train, D'Alembert balance (Ball 1988 §4.2)"
DESMODROMIC = "rigid desmodromic train, both pairs (Ball 1988 App D)"


def missing(deck) -> list[str]:
    out = []
    if deck.spring is None:
        out.append("spring (rate, preload_compression)")
    if deck.masses is None:
        out.append("masses (valve_side)")
    return out


def reason(deck, planned) -> str:
    return "spring and masses given"


def body_inertia(deck) -> dict[str, float]:
    """J_b for the inertia keys of the mechanisms, from the deck's masses (Ball Table 3.1; the
    roller of a roller finger follower or rocker included: assemble.mechanism.body_inertia)."""
    from camtrain.assemble.mechanism import body_inertia as of_deck

    return of_deck(deck)


def load_inputs(deck) -> dict:
    """Keyword arguments of :func:`camtrain.loads.contact_load` from the deck."""
    c = deck.clearance
    lash = c is not None and c.lash_adjuster
    return dict(rate=deck.spring.rate, preload_compression=deck.spring.preload_compression,
                valve_mass=deck.masses.valve_side, body_inertia=body_inertia(deck),
                progressive=(deck.spring.progressive_quadratic, deck.spring.progressive_cubic),
                clearance=0.0 if (c is None or lash) else c.valve_clearance,
                base_load=c.adjuster_load if lash else 0.0)


_SPRING = ("rate", "preload_compression", "valve_mass", "body_inertia", "progressive")


@by_identity
def _load_arguments(deck) -> tuple[dict, dict]:
    """:func:`load_inputs` of a deck and the spring/inertia part of them (the arguments of
    :func:`camtrain.loads.forces.load_parts`): deck values, formed once per deck model."""
    kw = load_inputs(deck)
    return kw, {k: kw[k] for k in _SPRING}


def _friction_callback(deck, kin):
    """F(W) for the iteration when the friction chain has its data, else None (mu fixed)."""
    if deck.lubricant is None or deck.cam.width is None:
        return None
    from camtrain.contact.model import CamContact

    contact = CamContact.from_deck(deck)
    return lambda load: contact.solve(kin, load).force


def solve_loads(deck, kin, kw: dict | None = None, parts=None, depends: bool | None = None):
    """LoadSolution for the deck: one pass for followers without a friction arm, otherwise
    Ball's friction/load iteration (§4.2.3.2) started at the boundary coefficient. ``kw``
    (:func:`load_inputs`), ``parts`` (its :func:`camtrain.loads.forces.load_parts`) and
    ``depends`` (the follower has a friction arm) are formed here unless given."""
    from camtrain.loads.forces import contact_load
    from camtrain.loads.iteration import iterate_load

    kw = load_inputs(deck) if kw is None else kw
    trib = deck.tribology
    if depends is None:
        depends = bool((kin.arm_friction != 0.0).any())
    return iterate_load(lambda mu: contact_load(kin, mu, parts=parts, **kw),
                        _friction_callback(deck, kin) if depends else None,
                        mu0=trib.boundary_friction, tolerance=deck.solver.friction_tolerance,
                        max_iterations=deck.solver.friction_max_iterations,
                        depends_on_mu=depends)


def run_desmodromic(deck, train, res):
    """Ball App D loads of both pairs; no bounce speed: the closing cam controls the valve."""
    import numpy as np

    from camtrain.components import CLOSING, MAIN
    from camtrain.loads import ContactLoad, desmodromic_loads

    kin, closing = train[MAIN], train[CLOSING]
    s = deck.spring.rate * deck.spring.preload_compression
    kw = load_inputs(deck)
    d = desmodromic_loads(kin, closing, closing_spring=s, valve_mass=deck.masses.valve_side,
                          clearance=kw["clearance"])
    res.add_column("valve_force", d.valve_force, "N", "valve-side force M x'' + S with the "
                   "constant closing spring S (0 while the valve is seated)")
    res.add_column("load", d.opening, "N", "opening cam/follower load (Ball App D; 0 while the "
                   "closing cam controls the valve)")
    res.add_column("load", d.closing, "N", "closing cam/follower load (Ball App D: "
                   "RR_c S, or RR_c |M x''| while the closing cam drives the valve)",
                   component=CLOSING)
    res.add_column("in_control", d.in_control, "-", "cam in control of the valve: +1 opening, "
                   "-1 closing (the closing spring holds the seated valve)")
    res.add_metric("closing_spring_force", s, "N", "constant closing spring force S = k delta "
                   "(Ball App F)")
    for component, load in ((None, d.opening), (CLOSING, d.closing)):
        i = int(np.argmax(load))
        res.add_metric("load_max", load[i], "N", "largest contact load"
                       + (" of the closing pair" if component else " of the opening pair"),
                       kin.theta[i], component=component)
    for j, angle in enumerate(d.handovers):
        res.add_metric(f"handover_{j + 1}", angle, "rad", "cam angle where control of the valve "
                       "passes between the opening and the closing cam (M x'' + S = 0)", angle)
        res.add_event("handover", angle, "control of the valve passes between the opening and "
                      "the closing cam")
    where = ", ".join(f"{np.degrees(a):.1f}" for a in d.handovers) or "nowhere"
    res.warn(f"desmodromic train: control of the valve passes between the cams at {where} deg "
             "(Ball App D); no bounce speed: the closing cam controls the valve")
    if np.any(d.jammed):
        deg = np.degrees(kin.theta[d.jammed])
        res.warn(f"desmodromic train jams: a pair cannot carry its load (load ratio <= 0) at "
                 f"{int(d.jammed.sum())} angles between {deg.min():.1f} and {deg.max():.1f} deg")
    return ContactLoad(load=d.opening, in_contact=np.asarray(d.in_control) > 0,
                       model=DESMODROMIC, closing=d.closing)


def load_metrics(theta, load, inside, iterations, tolerance: float, speeds) -> list:
    """The rigid train's load metrics (:class:`camtrain.metric_rows.CaseMetric`), for a run or
    for every case of a sweep batch (arrays with a leading case axis): largest load, smallest
    while the cam drives the valve, iterations, and the camshaft speed of first loss of contact
    from the per-angle ``speeds`` of :func:`camtrain.loads.bounce.bounce_speeds`."""
    import numpy as np

    from camtrain.units import rad_s_to_rpm

    i = load.argmax(axis=-1)
    j = np.where(inside, load, np.inf).argmin(axis=-1)
    b = speeds.argmin(axis=-1)
    bounce = at(speeds, b)
    if load.ndim == 1:   # a run: plain numbers
        bounce = float(bounce)
        finite = math.isfinite(bounce)
    else:
        finite = np.isfinite(bounce)
    bounce = np.where(finite, bounce, 0.0) if load.ndim > 1 else bounce if finite else 0.0
    return [
        CaseMetric("load_max", at(load, i), "N", "largest contact load", at(theta, i)),
        CaseMetric("load_min", at(load, j), "N", "smallest contact load while the cam drives "
                   "the valve", at(theta, j), anywhere(inside)),
        CaseMetric("load_iterations", iterations, "-",
                   f"friction/load iterations (tolerance {tolerance:g})"),
        CaseMetric("bounce_speed", rad_s_to_rpm(bounce), "rpm",
                   "camshaft speed at which the rigid train first loses contact",
                   at(theta, b), finite)]


def run(deck, inputs, res):
    import numpy as np

    from camtrain.loads.bounce import bounce_speeds
    from camtrain.loads.forces import contact_mask, load_parts, valve_force
    from camtrain.loads.product import ContactLoad, runs
    from camtrain.mechanisms.base import TrainKinematics

    train = inputs[TrainKinematics]
    if deck.mechanism.type == "desmodromic":
        return run_desmodromic(deck, train, res)
    kin = train.main
    kw, spring = _load_arguments(deck)
    # the speed-independent and omega^2 parts of the load balance serve the load (every pass of
    # the iteration) and the bounce speed alike: formed once
    parts = load_parts(kin, **spring)
    depends = np.count_nonzero(kin.arm_friction) > 0
    sol = solve_loads(deck, kin, kw, parts, depends)
    load = sol.load
    inside = contact_mask(kin.valve_lift, kw["clearance"])
    fv = valve_force(kin.valve_lift, kin.valve_d2, kin.omega, rate=kw["rate"],
                     preload_compression=kw["preload_compression"],
                     valve_mass=kw["valve_mass"], progressive=kw["progressive"])
    res.add_column("valve_force", np.where(inside, fv, 0.0), "N",
                   "valve-side force, spring + valve-side inertia (0 while the valve is seated)")
    res.add_column("load", load, "N", "normal cam/follower contact load (rigid train; 0 before "
                   "the cam takes up the valve clearance; negative = loss of contact)")
    mu = sol.mu if sol.friction is not None else deck.tribology.boundary_friction
    speeds = bounce_speeds(kin, mu, clearance=kw["clearance"], parts=parts, **spring)
    res.add_metrics(one_case(load_metrics(kin.theta, load, inside, sol.iterations,
                                          sol.tolerance, speeds)))
    lost = inside & (load <= 0.0)
    if np.count_nonzero(lost):
        for start, end in runs(lost, kin.theta):
            res.add_event("contact_loss", start,
                          "the cam loses contact with the follower (W <= 0)")
            res.add_event("contact_regained", end, "last angle without contact before the "
                          "cam carries the follower again")
        deg = np.degrees(kin.theta[lost])
        res.warn(f"valve bounce: the cam loses contact (W <= 0) at {int(lost.sum())} angles "
                 f"between {deg.min():.1f} and {deg.max():.1f} deg; the rigid-train results "
                 "there are not physical; a stiffer spring (spring.rate, "
                 "spring.preload_compression) or a lower speed.camshaft keeps the contact")
    if sol.friction is None and depends:
        res.warn("friction/load iteration skipped (no lubricant or cam width): loads use the "
                 f"boundary coefficient {deck.tribology.boundary_friction:g} everywhere")
    return ContactLoad(load=load, in_contact=inside, model=RIGID,
                       friction=sol.friction, mu=sol.mu, iterations=sol.iterations)


def run_cases(deck, inputs, cases):
    """:func:`run` over a leading case axis (:class:`camtrain.assemble.cases.Cases`): the
    rigid train's load of every case by :func:`camtrain.loads.contact_load` and Ball's
    friction/load iteration (:func:`camtrain.loads.iteration.iterate_cases`, each case held at
    its own convergence; one pass at the boundary coefficient without a friction arm), the load
    metrics and the bounce speeds. A case that does not converge or loses contact is set aside:
    alone, it reports the error or the lost contact."""
    import numpy as np

    from camtrain.loads import contact_load, contact_mask
    from camtrain.loads.bounce import bounce_speeds
    from camtrain.loads.iteration import iterate_cases
    from camtrain.loads.product import ContactLoad
    from camtrain.mechanisms.base import TrainKinematics

    kin = inputs[TrainKinematics].main
    scal = cases.scalars
    kw = dict(_load_arguments(deck)[0], rate=scal["rate"], valve_mass=scal["valve_mass"],
              preload_compression=scal["preload_compression"])
    spring = {k: v for k, v in kw.items() if k not in ("clearance", "base_load")}
    mu_b = scal["boundary_friction"]
    depends = np.any(kin.arm_friction != 0.0, axis=1)
    if np.any(depends) and not np.all(depends):
        raise ValueError("cases with and without a friction arm")   # run them alone
    with_friction = deck.lubricant is not None and deck.cam.width is not None   # as run's
    contact = cases.contact
    solver = deck.solver
    sol = iterate_cases(
        lambda mu: np.broadcast_to(contact_load(kin, mu, **kw), kin.theta.shape),
        (lambda w: contact.solve(kin, w).force) if with_friction and np.all(depends)
        else None,
        mu0=mu_b, tolerance=solver.friction_tolerance,
        max_iterations=solver.friction_max_iterations)
    inside = contact_mask(kin.valve_lift, kw["clearance"])
    mu = sol.mu if sol.friction is not None else mu_b   # as a single run takes it
    speeds = bounce_speeds(kin, mu, clearance=kw["clearance"], **spring)
    cases.add_metrics(load_metrics(kin.theta, sol.load, inside, sol.iterations,
                                   solver.friction_tolerance, speeds))
    cases.set_aside(~sol.converged | np.any(inside & (sol.load <= 0.0), axis=-1))
    return ContactLoad(load=sol.load, in_contact=inside, model=RIGID, friction=sol.friction,
                       mu=sol.mu, iterations=sol.iterations)
