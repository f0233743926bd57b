"""Kinematics effect: the lift law on the run's angle grid, then the follower kinematics.

Produces :class:`camtrain.mechanisms.TrainKinematics` (the only pair, or both pairs of a
desmodromic train). Like every effect module, its top level imports no physics: numpy and the
physics are imported where they are used, so that resolving a plan stays light.
"""
from __future__ import annotations

import math
from functools import lru_cache

from camtrain.identity_cache import by_identity
from camtrain.metric_rows import CaseMetric, at, one_case
from camtrain.tabulate.lift import lift_columns, lift_curve


def missing(deck) -> list[str]:
    return []


def reason(deck, planned) -> str:
    return f"always: {deck.lift.form} lift on a {deck.mechanism.type} follower"


#: Kinematics fields written to the result: name in the result, field, unit, description
_COLUMNS = (
    ("valve_lift", "valve_lift", "m", "valve lift"),
    ("valve_velocity", "valve_d1", "m/rad", "dl_v/dtheta"),
    ("valve_acceleration", "valve_d2", "m/rad^2", "d2l_v/dtheta2"),
    ("valve_jerk", "valve_d3", "m/rad^3", "d3l_v/dtheta3"),
    ("cam_lift", "cam_lift", "m", "lift of the follower that touches the cam"),
    ("contact_x", "contact_x", "m", "contact point on the cam profile, cam frame x"),
    ("contact_y", "contact_y", "m", "contact point on the cam profile, cam frame y"),
    ("profile_radius", "profile_r", "m", "polar radius of the cam profile at the contact"),
    ("profile_angle", "profile_angle", "rad", "polar angle of the cam profile point"),
    ("eccentricity", "eccentricity", "m", "contact position on the follower face"),
    ("cam_radius", "cam_radius", "m", "cam radius of curvature r_c (negative: concave)"),
    ("equivalent_radius", "equivalent_radius", "m", "equivalent radius R, 1/R = 1/r_c + 1/r_f"),
    ("radius_x", "radius_x", "m", "principal radius in the rolling direction"),
    ("radius_y", "radius_y", "m", "transverse principal radius (inf: line contact)"),
    ("v_cam", "v_cam", "m/s", "contact speed relative to the cam surface, V_c"),
    ("v_follower", "v_follower", "m/s", "contact speed relative to the follower surface, V_f"),
    ("entrainment", "entrainment", "m/s", "entrainment (mean) velocity (V_c + V_f)/2"),
    ("sliding", "sliding", "m/s", "sliding velocity V_c - V_f"),
    ("rocker_ratio", "rocker_ratio", "-", "contact load per valve force (no friction, inertia)"),
    ("pressure_angle", "pressure_angle", "rad", "pressure angle"),
    ("friction_arm", "friction_arm", "m", "arm of the friction force about the cam axis"),
)


def kinematics_columns(k, result, component: str | None = None) -> None:
    """Add the per-angle kinematics of a pair (``component``: None, or the closing pair of a
    desmodromic train)."""
    result.add_columns(_column_rows(k, component), component)


def kinematics_metrics(deck, k, result, component: str | None = None) -> None:
    """Scalar results a valve-train engineer looks for first."""
    model = deck.tribology.film_model
    carried = ("" if model == "steady" or deck.lubricant is None else
               f"; the squeeze film carries the load through it (tribology.film_model = {model})")
    metrics, zeros, warning = _metric_rows(k, component,
                                           deck.mechanism.type == "flat" and component is None,
                                           carried, deck.speed.omega > 0)
    result.add_metrics(metrics, component)
    for angle in zeros:
        result.add_event("zero_entrainment", angle, "the entrainment velocity passes through "
                         "zero: the steady EHL film vanishes" + carried, component=component)
    if warning:   # a finding an effect planned later may own (a turning roller's entrainment)
        result.warn(warning, finding="zero_entrainment")


@by_identity
def _metric_rows(k, component: str | None, convexity: bool, carried: str, moving: bool):
    """The metric rows, zero-entrainment angles and warning of :func:`kinematics_metrics`: they
    depend on the (shared, read-only) Kinematics and these few deck facts only, so they are
    formed once per Kinematics."""

    label = f" of the {component} pair" if component else ""
    zeros = tuple(zero_crossings(k.theta, k.entrainment))
    metrics = tuple(one_case(pair_metrics(k, label, convexity, [zeros])))
    from camtrain.effects.entrainment import zero_entrainment_warning

    warning = zero_entrainment_warning(zeros, label, carried) if moving else ""
    return metrics, zeros, warning


def pair_metrics(k, label: str, convexity: bool, zeros: list) -> list:
    """The kinematics metrics of one pair (:class:`camtrain.metric_rows.CaseMetric`), for a run
    or every case of a sweep batch (a Kinematics of (cases, angles) arrays); ``zeros``: each
    case's zero-entrainment angles (:func:`zero_crossings_rows`)."""
    import numpy as np


    theta = k.theta
    nose = k.nose
    at_nose = at(theta, nose)
    i = k.cam_radius.argmin(axis=-1)
    j = np.abs(k.eccentricity).argmax(axis=-1)
    m = np.abs(k.pressure_angle).argmax(axis=-1)
    metrics = [
        CaseMetric("max_valve_lift", at(k.valve_lift, nose), "m", "maximum valve lift" + label,
                   at_nose),
        CaseMetric("cam_radius_at_max_lift", at(k.cam_radius, nose), "m",
                   "cam radius of curvature at maximum lift" + label, at_nose),
        CaseMetric("equivalent_radius_at_max_lift", at(k.equivalent_radius, nose), "m",
                   "equivalent radius at maximum lift" + label, at_nose),
        CaseMetric("cam_radius_min", at(k.cam_radius, i), "m",
                   "smallest cam radius of curvature (most negative: tightest concave flank)"
                   + label, at(theta, i)),
        CaseMetric("eccentricity_max", abs(at(k.eccentricity, j)), "m",
                   "largest distance of the contact from the face centre" + label, at(theta, j)),
        CaseMetric("pressure_angle_max", abs(at(k.pressure_angle, m)), "rad",
                   "largest pressure angle" + label, at(theta, m)),
    ]
    if convexity:
        # Ball (1988) §2.2.1: the cam is convex (r_c > 0) only if r_B > -min(l + l'')
        metrics.append(CaseMetric(
            "min_base_radius_convex", (-(k.valve_lift + k.valve_d2)).max(axis=-1), "m",
            "smallest base radius for which the cam stays convex under a flat follower"))
    for n in range(max(map(len, zeros), default=0)):
        angles = np.array([z[n] if n < len(z) else np.nan for z in zeros])
        present = np.array([n < len(z) for z in zeros])
        if theta.ndim == 1:   # a run: one case
            angles, present = angles[0], present[0]
        metrics.append(CaseMetric(
            f"zero_entrainment_{n + 1}", angles, "rad",
            f"cam angle where the entrainment velocity passes through zero{label}", angles,
            present))
    return metrics


def zero_crossings(theta, values) -> list[float]:
    """Angles where a periodic per-angle quantity changes sign (linear interpolation); a run of
    exact zeros is reported once, at its start (:func:`zero_crossings_rows` of one row)."""
    import numpy as np

    return zero_crossings_rows(theta, np.asarray(values, dtype=float)[None, :])[0]


def zero_crossings_rows(theta, values) -> list[list[float]]:
    """Per row of ``values`` (cases, angles) over the 1-D grid ``theta``, the angles where the
    periodic quantity changes sign (linear interpolation); a run of exact zeros is reported
    once, at its start."""
    import numpy as np

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


@lru_cache(maxsize=32)
def _cached_valve_lift(lift_model, mechanism, base_radius: float, points: int):
    """Cam lift converted to valve lift: depends only on the lift, the pivot geometry and the
    grid, so a sweep over other parameters converts once (the conversion is a root search per
    angle). The arrays are made read-only because they are shared between runs."""
    from camtrain.assemble.mechanism import valve_lift

    curve = lift_curve(lift_model, points)
    valve = valve_lift(lift_model, mechanism, base_radius, curve)
    for arr in (valve.theta, valve.lift, valve.d1, valve.d2, valve.d3):
        arr.flags.writeable = False
    return valve


@lru_cache(maxsize=8)   # (36 arrays each: a few per process, not a sweep's worth)
def _cached_kinematics(lift_model, mechanism, cam, speed, points: int):
    """The pairs' Kinematics (opening, closing or None) on the run's grid: they depend only on
    the [lift], [mechanism], [cam] and [speed] models and the grid, like the lift curve they come
    from, so a sweep over anything else (spring, masses, lubricant, materials) or a second run
    of a deck forms them once. Their arrays are read-only, shared between runs. A geometry
    error is not kept: it is raised again on every run."""
    from camtrain.assemble.mechanism import train_kinematics

    valve = lift_curve(lift_model, points) if lift_model.measured_at == "valve" else \
        _cached_valve_lift(lift_model, mechanism, cam.base_radius, points)
    return train_kinematics(mechanism, cam, speed, valve)


@by_identity
def _deck_kinematics(deck):
    """:func:`_cached_kinematics` of a deck model, found by its identity on a repeated run
    (hashing its models costs more than the look-up)."""
    return _cached_kinematics(deck.lift, deck.mechanism, deck.cam, deck.speed,
                              deck.solver.angle_points)


@by_identity
def _column_rows(k, component: str | None):
    """The (name, values, unit, description) rows of a Kinematics, formed once per (shared)
    Kinematics."""
    import numpy as np

    tag = f" ({component} pair)" if component else ""
    tabulate_y = np.count_nonzero(np.isfinite(k.radius_y))   # none finite: line contact
    return tuple((name, getattr(k, attr), unit, description + tag)
                 for name, attr, unit, description in _COLUMNS
                 if tabulate_y or name != "radius_y")


def run(deck, inputs, result):
    from camtrain.components import CLOSING, MAIN
    from camtrain.mechanisms.base import TrainKinematics

    lift_columns(deck, result)
    opening, closing = _deck_kinematics(deck)
    kinematics_columns(opening, result)
    kinematics_metrics(deck, opening, result)
    pairs = ((MAIN, opening),)
    if closing is not None:
        kinematics_columns(closing, result, CLOSING)
        kinematics_metrics(deck, closing, result, CLOSING)
        pairs += ((CLOSING, closing),)
    return TrainKinematics(pairs)


def cases_refused(deck, swept: tuple[str, ...]) -> str:
    """Why :func:`run_cases` cannot take this deck's cases ("" when it can): it builds the
    kinematics of clockwise translating flat-faced and domed followers over a case axis."""
    from camtrain.mechanisms.base import CLOCKWISE, normalise_rotation

    mech = deck.mechanism
    if mech.type not in ("flat", "domed"):
        return (f"a {mech.type} follower: its kinematics are solved case by case (the batch "
                "covers translating flat-faced and domed followers)")
    if normalise_rotation(mech.rotation) != CLOCKWISE:
        return "an anticlockwise cam (the batch covers clockwise rotation)"
    if mech.roller is not None and mech.roller.crown_radius is not None:
        return "a crowned roller: its elliptical contact is solved case by case"
    return ""


def _face_shape(mech) -> str:
    """The face shape of a single run: a roller is cylindrical (camtrain.assemble.mechanism)."""
    if mech.type == "flat":
        return "spherical"
    return "cylindrical" if mech.follower == "roller" else mech.follower_shape


@by_identity
def _lift_metrics(deck) -> tuple:
    """The lift law's metrics of a run (:func:`lift_columns`), as the CaseMetric every case of
    a batch shares: formed once per deck model, not once per batch."""
    from camtrain.result import Result

    lift = Result()
    lift_columns(deck, lift)
    return tuple(CaseMetric(name, m.value, m.unit, m.description, m.angle)
                 for name, m in lift.metrics.items())


def run_cases(deck, inputs, cases):
    """:func:`run` over a leading case axis (:class:`camtrain.assemble.cases.Cases`): the
    lift law's metrics, and the kinematics of every case by the builder a single run's
    translating follower uses (:func:`camtrain.mechanisms.translating.translating_kinematics`),
    each array of shape (cases, angles). A case whose geometry fails a single run's check
    (:func:`camtrain.mechanisms.checks.cases_pass`) is set aside: alone, it reports the error."""
    from camtrain.components import MAIN
    from camtrain.mechanisms.base import TrainKinematics
    from camtrain.mechanisms.checks import cases_pass
    from camtrain.mechanisms.translating import translating_kinematics
    cases.add_metrics(_lift_metrics(deck))
    valve = lift_curve(deck.lift, deck.solver.angle_points)
    mech, scal = deck.mechanism, cases.scalars
    flat = mech.type == "flat"
    taper = None if flat or not deck.cam.taper_angle > 0.0 else float(deck.cam.taper_angle)
    kin = translating_kinematics(
        valve, mech.type, base_radius=scal["base_radius"],
        follower_radius=math.inf if flat else scal["follower_radius"],
        offset=0.0 if flat or taper is not None else mech.offset, omega=scal["omega"],
        taper_angle=taper, shape=_face_shape(mech), cases=cases.n)
    cases.set_aside(~cases_pass(kin, flat=flat, face_length=mech.face_length,
                                min_concave_radius=mech.grinding_wheel_radius))
    zeros = zero_crossings_rows(valve.theta, kin.entrainment)
    cases.add_metrics(pair_metrics(kin, "", flat, zeros))
    return TrainKinematics(((MAIN, kin),))

