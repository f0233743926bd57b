"""The deck's [dynamics] section turned into the lumped train, its cam input and its settings.

Everything is referred to the valve. The masses split the rigid train's: the follower node gets
``dynamics.follower_mass`` (taken out of ``masses.valve_side``), half the rocker's equivalent
mass I/B^2 (Teodorescu eqs A1-A3) and half a pivoted follower's mass; the valve node the rest. So
the rigid limit of the elastic train is the deck's rigid train (docs/dynamics.md).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from camtrain.assemble.mechanism import body_inertia, roller_inertia, valve_arm_length
from camtrain.dynamics import (
    CamInput,
    Settings,
    TimeBase,
    TrainModel,
    assemble_train,
    auto_steps,
    cam_input,
    rocker_equivalent_mass,
)
from camtrain.loads.forces import BASE_CIRCLE_TOLERANCE


@dataclass(frozen=True)
class DynamicSetup:
    """What a dynamic run needs: the train, its cam input, the time base, the settings and the
    valve-referred lash [m] and rocker ratio used for the push rod (1 otherwise)."""

    model: TrainModel
    cam: CamInput
    base: TimeBase
    settings: Settings
    lash: float
    pushrod_ratio: float


def valve_arm(deck) -> float | None:
    """Rocker arm on the valve side [m] (finger/rocker: B; push rod: D2), None without one."""
    mech = deck.mechanism
    if mech.type in ("finger", "rocker"):
        return valve_arm_length(mech)
    if mech.type == "pushrod":
        return mech.pushrod.rocker_valve_arm
    return None


def pushrod_ratio(deck) -> float:
    """Valve motion per push-rod motion, D2/D1 (1 for trains without a push rod)."""
    if deck.mechanism.type == "pushrod":
        p = deck.mechanism.pushrod
        return p.rocker_valve_arm / p.rocker_pushrod_arm
    return 1.0


def lash_of(deck) -> float:
    c = deck.clearance
    return 0.0 if (c is None or c.lash_adjuster) else c.valve_clearance


def build_model(deck, *, stiffness_scale: float = 1.0, kin=None) -> TrainModel:
    """The lumped train of the deck (``stiffness_scale`` multiplies the contact, element and seat
    stiffnesses, not the valve spring: the stiff limit of the tests). A Hertz line contact
    (``contact_model = "hertz_line"``) needs the kinematics ``kin`` (radii, load ratio)."""
    d, m, s = deck.dynamics, deck.masses, deck.spring
    arm = valve_arm(deck)
    body = 0.0
    if arm is not None:
        body = rocker_equivalent_mass(m.rocker_inertia + roller_inertia(deck.mechanism), arm)
        if deck.mechanism.type in ("finger", "rocker"):
            body += m.follower
    third = d.spring_mass / 3.0 if d.spring_elements > 0 else 0.0
    valve = m.valve_side - d.follower_mass - third
    follower = d.follower_mass
    if follower > 0.0:
        follower += 0.5 * body
        valve += 0.5 * body
    else:
        valve += body
    ratio = pushrod_ratio(deck)

    def scaled(k):
        return math.inf if k is None else k * stiffness_scale

    links = {}
    if d.pushrod_stiffness is not None:
        links["push rod"] = scaled(d.pushrod_stiffness / ratio ** 2)
    if d.rocker_stiffness is not None:
        links["rocker"] = scaled(d.rocker_stiffness)
    if d.stem_stiffness is not None:
        links["valve stem"] = scaled(d.stem_stiffness)
    if follower > 0.0 and not links:
        links["rigid link"] = math.inf
    c = deck.clearance
    adjuster = c.adjuster_load if (c is not None and c.lash_adjuster) else 0.0
    if d.lash_adjuster is not None:
        adjuster = 0.0   # the hydraulic adjuster replaces the constant load
    law = None
    contact = scaled(d.contact_stiffness)
    if d.contact_model == "hertz_line":
        law, contact = hertz_law(deck, kin, stiffness_scale)
    model = assemble_train(
        valve_mass=valve, follower_mass=follower, contact_stiffness=contact, cam_law=law,
        follower_stiffness=scaled(d.follower_stiffness), links=links,
        seat_stiffness=scaled(d.seat_stiffness), spring_rate=s.rate,
        spring_preload=s.rate * s.preload_compression, lash=lash_of(deck),
        damping_ratio=d.damping_ratio, seat_damping_ratio=d.seat_damping_ratio,
        spring_mass=d.spring_mass or 0.0, spring_elements=d.spring_elements,
        spring_damping_ratio=d.spring_damping_ratio, adjuster_load=adjuster,
        damping=damping_values(d))
    if d.lash_adjuster is None:
        return model
    from camtrain.dynamics.hla import with_lash_adjuster

    return with_lash_adjuster(model, lash_adjuster(deck), adjuster_ratio(deck, kin))


def with_roller(deck, kin, model: TrainModel, omega: float | None = None) -> TrainModel:
    """The train with its roller's spin tables (:mod:`camtrain.dynamics.spin`) when the deck
    marches the roller (:func:`camtrain.assemble.roller.marches_roller`), else unchanged. The
    tables reach LOAD_CAP_FACTOR x the rigid train's largest load at that speed."""
    from dataclasses import replace

    from camtrain.assemble.roller import LOAD_CAP_FACTOR, marches_roller, spin_tables

    if not marches_roller(deck):
        return model
    import numpy as np

    cap = LOAD_CAP_FACTOR * max(float(np.max(rigid_load(deck, kin, omega))), 1.0)
    return replace(model, roller=spin_tables(deck, kin, cap))


def lash_adjuster(deck):
    """The deck's [dynamics.lash_adjuster] as a :class:`camtrain.dynamics.hla.LashAdjuster`
    (SI; the annulus' oil the lubricant's unless the section names a viscosity)."""
    from camtrain.dynamics.hla import LashAdjuster

    h = deck.dynamics.lash_adjuster
    return LashAdjuster(
        plunger_diameter=h.plunger_diameter, radial_clearance=h.radial_clearance,
        leak_length=h.leak_length, eccentricity=h.eccentricity,
        viscosity=h.viscosity if h.viscosity is not None else deck.lubricant.viscosity,
        dead_volume=h.chamber_volume, stroke=h.stroke, rest_extension=h.rest_extension,
        plunger_mass=h.plunger_mass, spring_rate=h.spring_rate,
        spring_preload=h.spring_preload, supply_pressure=h.supply_pressure,
        cracking_pressure=h.cracking_pressure, check_area=h.check_valve_area,
        full_open=h.full_open_pressure, discharge_coefficient=h.discharge_coefficient,
        oil_density=h.oil_density, bulk_modulus=h.bulk_modulus, air_fraction=h.air_fraction,
        polytropic_index=h.polytropic_index, stop_stiffness=h.stop_stiffness,
        vapour_pressure=h.vapour_pressure, bulk_model=h.bulk_model, scheme=h.chamber_scheme,
        check_valve=h.check_valve, ball_mass=h.ball_mass, ball_spring_rate=h.ball_spring_rate,
        ball_preload=h.ball_preload, seat_diameter=h.seat_diameter, ball_lift=h.ball_lift,
        ball_damping_ratio=h.ball_damping_ratio)


def adjuster_ratio(deck, kin=None) -> float:
    """Plunger motion per valve-referred motion: 1 in a bucket tappet, D1/D2 in a push-rod
    lifter, the lever ratio 1/(R - 1) under the pivot of an end-pivoted finger follower (R the
    valve motion per cam-contact motion on the base circle: the kinematics' load ratio, or B/A
    without kinematics)."""
    from camtrain.dynamics.hla import pivot_ratio

    location = deck.dynamics.lash_adjuster.location
    mech = deck.mechanism
    if location == "pivot" or (location == "auto" and mech.type == "finger"):
        if kin is not None:
            import numpy as np

            rest = int(np.argmin(kin.valve_lift))
            return pivot_ratio(float(np.asarray(kin.rocker_ratio)[rest]))
        return pivot_ratio(mech.B / mech.A)
    return 1.0 / pushrod_ratio(deck)


def hertz_law(deck, kin, stiffness_scale: float = 1.0):
    """The cam contact as a Hertz line contact (contact_law.HertzLineLaw: Johnson 1985, the
    approach of cylinders in line contact) from the deck's materials, the cam width, the
    follower's radius and the cam's radius of curvature, and its largest tangent stiffness over
    the cycle at the rigid train's load (valve-referred) [N/m]."""
    import numpy as np

    from camtrain.dynamics.contact_law import HertzLineLaw
    from camtrain.errors import field_error

    if kin is None:
        raise ValueError("a Hertz line cam contact needs the kinematics")
    r2 = np.asarray(kin.follower_radius, dtype=float)
    if not np.all(np.isfinite(r2)) or np.any(r2 <= 0):
        raise field_error("dynamics.contact_model", "a flat follower face has no radius, so "
                          "the line contact's approach is not defined", "hertz_line",
                          "contact_model = \"linear\" with a contact_stiffness")
    rc = np.asarray(kin.cam_radius, dtype=float)
    if not np.all(np.isfinite(rc)) or np.any(rc <= 0):
        raise field_error("dynamics.contact_model", "the cam has a flat or concave flank, where "
                          "the two-cylinder approach does not hold", "hertz_line",
                          "contact_model = \"linear\" with a contact_stiffness")
    m = deck.materials
    rest = int(np.argmin(kin.valve_lift))
    ratio = np.asarray(kin.rocker_ratio, dtype=float)
    law = HertzLineLaw(c1=(1 - m.cam_poisson ** 2) / m.cam_modulus / stiffness_scale,
                       c2=(1 - m.follower_poisson ** 2) / m.follower_modulus / stiffness_scale,
                       length=deck.cam.width, follower_radius=float(np.median(r2)),
                       base_radius=float(rc[rest]), base_ratio=float(ratio[rest]))
    force = np.maximum(rigid_load(deck, kin) / ratio, 1.0)
    tangent = max(law.stiffness(float(f), float(r), float(q))
                  for f, r, q in zip(force, rc, ratio, strict=True))
    return law, tangent


def damping_values(d) -> dict[str, float]:
    """The damping the deck gives as values [N s/m] (referred to the valve), by element."""
    given = {"contact": d.contact_damping, "link": d.link_damping, "seat": d.seat_damping,
             "spring": d.spring_damping}
    return {key: value for key, value in given.items() if value is not None}


def time_base(deck, omega: float | None = None) -> TimeBase:
    d = deck.dynamics
    w = deck.speed.omega if omega is None else omega
    return TimeBase(w, d.speed_oscillation, d.speed_oscillation_order if d.speed_oscillation
                    else 0)


def setup(deck, kin, *, stiffness_scale: float = 1.0, omega: float | None = None,
          overrides: dict | None = None, spin: bool = True) -> DynamicSetup:
    """Model, cam input (the kinematics' valve lift), time base and settings of a run; with
    ``spin`` the roller's spin marched with the train where the deck asks for it
    (:func:`with_roller`)."""
    d = deck.dynamics
    model = build_model(deck, stiffness_scale=stiffness_scale, kin=kin)
    if spin:
        model = with_roller(deck, kin, model, omega)
    geometry = {}
    if model.cam_law is not None:
        geometry = {"radius": kin.cam_radius, "ratio": kin.rocker_ratio}
    cam = cam_input(kin.theta, kin.valve_lift, kin.valve_d1, kin.valve_d2,
                    BASE_CIRCLE_TOLERANCE, **geometry)
    base = time_base(deck, omega)
    spd = None if d.steps_per_degree is None else d.steps_per_degree
    sub = auto_steps(model, base, kin.theta.size, d.steps_per_period, spd)
    kw = dict(integrator=d.integrator, substeps=sub, cycles_max=d.cycles_max,
              period_tol=d.period_tol, rtol=d.rtol, atol=d.atol, max_step=d.max_step,
              stability_factor=d.stability_factor)
    kw.update(overrides or {})
    _check_step_count(deck, base, kin.theta.size * int(kw["substeps"]))
    return DynamicSetup(model, cam, base, Settings(**kw), lash_of(deck), pushrod_ratio(deck))


#: Most time steps per camshaft revolution a march may take. The shipped decks take about 10^4
#: (the stiff-limit tests 3e6); the march keeps about ten float64 values per step (time, cam
#: input and its rates, geometry), so this bound keeps its arrays below about a GB instead of
#: letting a very low speed (or a huge ``steps_per_degree``) ask for tens of GB.
MAX_STEPS_PER_REVOLUTION = 8_000_000


def _check_step_count(deck, base: TimeBase, steps: int) -> None:
    """Refuse a march whose step count per revolution exceeds the bound, naming the knobs."""
    if steps <= MAX_STEPS_PER_REVOLUTION:
        return
    from camtrain.errors import field_error
    from camtrain.units import from_si

    d = deck.dynamics
    rpm = from_si(2.0 * math.pi / base.period, "rpm")
    if d.steps_per_degree is not None:
        field, value = "dynamics.steps_per_degree", d.steps_per_degree
        hint = "fewer steps per degree"
    else:
        field, value = "speed.camshaft", f"{rpm:.6g} rpm"
        hint = ("a higher camshaft speed (the step follows the train's shortest natural "
                "period, so a slow revolution takes proportionally more steps), or "
                "dynamics.steps_per_degree to fix the step count, or dynamics.steps_per_period "
                "lower")
    raise field_error(field, f"the dynamic march would take {steps:.3g} time steps per "
                      f"camshaft revolution at {rpm:.6g} rpm, more than its bound of "
                      f"{MAX_STEPS_PER_REVOLUTION:.3g}", value, hint)


def rigid_load(deck, kin, omega: float | None = None):
    """The rigid train's contact load [N] on the grid (Ball 1988 §4.2, friction arm at the
    boundary coefficient): the quasi-static limit printed beside the dynamic load."""
    import numpy as np

    from camtrain.loads import contact_load

    m, s = deck.masses, deck.spring
    body = body_inertia(deck)
    c = deck.clearance
    lash = c is not None and c.lash_adjuster
    return contact_load(kin, np.full(kin.theta.shape, deck.tribology.boundary_friction),
                        rate=s.rate, preload_compression=s.preload_compression,
                        valve_mass=m.valve_side, body_inertia=body, clearance=lash_of(deck),
                        base_load=c.adjuster_load if lash else 0.0, omega=omega)


def separation_check(deck, kin, *, stiffness_scale: float = 1.0, overrides: dict | None = None):
    """``separates(omega) -> (separated, first loss angle)``: in the periodic response at
    camshaft speed omega [rad/s] the cam loses the follower while the valve is off its seat
    (rebounds of the valve landing on its seat do not count: the rigid train has no seat)."""
    from camtrain.dynamics import march
    from camtrain.dynamics.findings import findings

    def separates(omega):
        s = setup(deck, kin, stiffness_scale=stiffness_scale, omega=omega, overrides=overrides,
                  spin=False)
        flights = [x for x in findings(march(s.model, s.cam, s.base, s.settings)).separations
                   if x.in_flight]
        if not flights:
            return False, None
        return True, flights[0].loss

    return separates
