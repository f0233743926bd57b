"""Roller effect: the follower's roller turning on its pin, and the film and friction it makes.

Physics in :mod:`camtrain.roller`: the roller's speed from its torque balance (quasi-static or
marched to a periodic state), slip and slide-roll ratio, cam-roller traction and rolling
resistance, pin friction. The effect reads only the chain's kinematics (cam and follower surface
speeds, follower radius, line contact), the contact load and the Hertz field, so any mechanism
whose kinematics describe a line contact on a curved face carries a roller. When the elastic
train marched the roller's speed (the dynamics effect's ``RollerSpin``, dynamics.roller =
"marched") the effect takes that speed, and the traction the march balanced it with, as the
run's, and solves none of its own (docs/rollers.md).

It offers the film and the friction of the cam contact at the roller's speed as rank-1
alternatives of ``ContactFilm`` and ``ContactFriction``: the power, camshaft and bearing effects
downstream run on them unchanged. The friction force handed on is the tangential force on the
cam, positive against the non-rotating follower's sliding V_s0 (as the chain's): the traction,
plus the rolling resistance as the force that dissipates F_R |u_e| at the sliding speed V_s0.
"""
from __future__ import annotations

from camtrain.metric_rows import CaseMetric, anywhere, at, one_case


def missing(deck) -> list[str]:
    if deck.roller is None:
        return ["roller (the roller's pin and solver)"]
    if deck.lubricant is None:
        return ["lubricant (the cam-roller film)"]
    if deck.cam.width is None:
        return ["cam.width (the cam-roller contact length)"]
    return []


def takes_marched_speed(deck, planned) -> bool:
    """The roller's speed is the one the elastic train marched (the dynamics effect planned,
    ``RollerSpin``, with dynamics.roller = "marched" and a turning pin): the roller effect then
    computes its film, friction and losses at that speed instead of solving its own."""
    from camtrain.assemble.roller import marches_roller

    return "RollerSpin" in planned and marches_roller(deck)


def reason(deck, planned) -> str:
    r = deck.roller
    solver = ("quasi-static (no inertia)" if r.solver == "quasi_static"
              else f"inertial, periodic march ({r.substeps} substeps per grid step)")
    if takes_marched_speed(deck, planned):
        solver = ("marched with the elastic train (dynamics.roller = \"marched\"; "
                  f"roller.solver = \"{r.solver}\" not used)")
    return (f"[roller] given: the roller turns on a {r.pin} pin, {r.traction} traction, "
            f"{r.rolling_resistance} rolling resistance, speed {solver}; film and friction "
            "at the roller's speed")


def face_mass(deck) -> float:
    """mechanism.roller.mass [kg] (a roller finger's or rocker's roller), 0 without it."""
    from camtrain.assemble.roller import face_mass as of_deck

    return of_deck(deck)


def pin_of(deck):
    """The deck's pin as physics (:func:`camtrain.assemble.roller.pin_of`)."""
    from camtrain.assemble.roller import pin_of as of_deck

    return of_deck(deck)


def settings_of(deck):
    from camtrain.roller.solve import RollerSettings

    r = deck.roller
    return RollerSettings(solver=r.solver, tolerance=r.periodic_tolerance,
                          revolutions=r.revolutions, substeps=r.substeps,
                          table_points=r.table_points, skid_slip=r.skid_slip)


def cam_force(field, v_s0):
    """Tangential force on the cam [N], positive against V_s0 (see the module docstring)."""
    import numpy as np

    s = np.sign(v_s0)
    mag_v = np.abs(v_s0)
    rolling = np.divide(field.rolling_power, mag_v, out=np.zeros(mag_v.shape), where=mag_v > 0)
    return field.traction * s + rolling


def _nan_to_zero(values):
    """``np.nan_to_num(values, nan=0.0)`` (infinities to the largest floats), with its Python
    wrapper only where a value is not finite."""
    import numpy as np

    out = np.where(values == values, values, 0.0)
    return out if np.isfinite(out).all() else np.nan_to_num(out)


def roller_metrics(theta, field, loaded) -> list:
    """The roller's metrics (:class:`camtrain.metric_rows.CaseMetric`)."""
    import numpy as np

    from camtrain.formulas.cycle import cycle_mean

    slip = np.where(loaded, np.abs(_nan_to_zero(field.slip)), 0.0)
    srr = np.where(loaded, _nan_to_zero(field.slide_roll_ratio), 0.0)
    i, j, k = int(slip.argmax()), int(srr.argmin()), int(srr.argmax())
    n = max(int(np.count_nonzero(loaded)), 1)
    parts = (field.sliding_power, field.rolling_power, field.pin_power)
    means = [float(cycle_mean(p)) for p in parts]
    return [
        CaseMetric("roller_slip_max", at(slip, i), "-", "largest slip of the loaded roller "
                   "1 - w_r r_r / (V_c - V_f)", at(theta, i)),
        CaseMetric("roller_srr_min", at(srr, j), "-", "smallest slide-roll ratio (loaded)",
                   at(theta, j)),
        CaseMetric("roller_srr_max", at(srr, k), "-", "largest slide-roll ratio (loaded)",
                   at(theta, k)),
        CaseMetric("roller_skid_fraction", np.count_nonzero(loaded & ~field.rolls) / n, "-",
                   f"share of loaded angles where the roller skids (slip > "
                   f"{field.skid_slip:g})", None, anywhere(loaded)),
        CaseMetric("roller_power_sliding", means[0], "W",
                   "cycle-mean cam-roller sliding loss |F_t u_s|"),
        CaseMetric("roller_power_rolling", means[1], "W",
                   "cycle-mean cam-roller hydrodynamic rolling loss F_R |u_e|"),
        CaseMetric("roller_power_pin", means[2], "W", "cycle-mean pin (bearing) loss T w_r"),
        CaseMetric("roller_power_total", sum(means), "W",
                   "cycle-mean roller loss: cam-roller sliding + rolling + pin"),
        CaseMetric("roller_revolutions", field.revolutions, "-",
                   "revolutions marched to the roller's periodic speed (0: quasi-static, or "
                   "marched with the elastic train)")]


def run(deck, inputs, res):
    import numpy as np

    from camtrain.components import MAIN
    from camtrain.contact.model import CamContact
    from camtrain.contact.products import ContactFilm, ContactFriction, ContactHertz, FrictionField
    from camtrain.dynamics.spin.product import RollerSpin
    from camtrain.errors import field_error
    from camtrain.loads.product import ContactLoad
    from camtrain.mechanisms.base import TrainKinematics
    from camtrain.roller.product import RollerMotion
    from camtrain.roller.traction import Traction

    kin = inputs[TrainKinematics].main
    load = np.maximum(inputs[ContactLoad].load, 0.0)
    hz = inputs[ContactHertz].main
    radius = float(np.max(kin.follower_radius))
    if not np.isfinite(radius):
        raise field_error("roller", "the mechanism's follower face is not curved",
                          deck.mechanism.type, "a cylindrical or crowned follower face (roller)")
    r = deck.roller
    contact = CamContact.from_deck(deck)
    traction = Traction(contact, kin, load, hz, r.traction, r.rolling_resistance)
    field = motion(deck, traction, radius, inputs.get(RollerSpin))
    film = traction.film(field.sliding)
    force = cam_force(field, traction.v_s0)
    used = (load > 0.0) & np.isfinite(film.for_shear) & np.isfinite(hz.pmax)
    force = np.where(used, force, 0.0)
    write_columns(res, kin, load, field, film, force, contact)
    if not hz.line:
        warn_crown_edge(res, kin.theta, hz, load > 0.0, deck.cam.width)
    res.add_metrics(one_case(roller_metrics(kin.theta, field, load > 0.0)))
    warn_zero_entrainment(res, kin.theta, field.entrainment, load > 0.0, deck)
    if field.revolutions and field.periodic_change > r.periodic_tolerance:
        res.warn(f"roller speed not periodic after {field.revolutions} revolutions (change "
                 f"{field.periodic_change:.3g} > roller.periodic_tolerance): raise "
                 "roller.revolutions")
    return (RollerMotion(((MAIN, field),)), ContactFilm(((MAIN, film),), with_load=True),
            ContactFriction(((MAIN, FrictionField(force=force, hertz=hz, film=film, used=used)),),
                            model=f"roller ({r.traction})"))


def motion(deck, traction, radius, spin):
    """The roller's motion: at the speed the elastic train marched and with the traction that
    balanced it (``spin``, a :class:`~camtrain.dynamics.spin.product.RollerSpin` with a
    speed), else its own solve (roller.solver) at the chain's load."""
    from camtrain.roller.solve import motion_of, solve_roller

    r = deck.roller
    if spin is not None and spin.marched:
        return motion_of(traction, pin_of(deck), radius, spin.inertia, spin.speed,
                         "marched with the elastic train (dynamics.roller = marched)", 0, 0.0,
                         r.skid_slip, f_t=spin.traction)
    return solve_roller(traction, pin_of(deck), radius,
                        r.moment_of_inertia(radius, face_mass(deck)), settings_of(deck))


def warn_crown_edge(res, theta, hz, loaded, width) -> None:
    """A crowned roller whose Hertz ellipse 2 a_y is longer than the contact width cam.width:
    there the crown is too flat for the load, the ellipse is cut by the roller's edges and the
    elliptical contact no longer holds (edge loading)."""
    import numpy as np

    length = np.where(loaded, 2.0 * np.nan_to_num(hz.half_length), 0.0)
    i = int(length.argmax())
    if length[i] > width:
        over = int(np.count_nonzero(length > width))
        res.warn(f"crowned roller: the Hertz ellipse (2 a_y up to {length[i] * 1e3:.3g} mm at "
                 f"{np.degrees(theta[i]):.1f} deg) is longer than cam.width "
                 f"({width * 1e3:.3g} mm) at {over} angles: the crown is too flat for the load "
                 "and the roller's edges carry load the elliptical contact does not describe; "
                 "a smaller mechanism.roller.crown_radius keeps the ellipse on the roller")


def warn_zero_entrainment(res, theta, entrainment, loaded, deck) -> None:
    """The zero-entrainment finding of the cam contact at the roller's entrainment (V_c +
    V_roll)/2, in the kinematics effect's words, on loaded angles: a locked roller's is the
    non-rotating face's."""
    import numpy as np

    from camtrain.effects.entrainment import zero_entrainment_warning
    from camtrain.roller.speeds import periodic_next

    if not deck.speed.omega > 0:
        return
    u = _nan_to_zero(entrainment)
    nxt = periodic_next(u)
    i = np.flatnonzero(loaded & periodic_next(loaded) & (u * nxt < 0.0))
    if not i.size:
        return
    step = np.diff(theta).mean()
    zeros = [float(theta[j] + step * u[j] / (u[j] - nxt[j])) for j in i]
    for angle in zeros:
        res.add_event("zero_entrainment", angle, "the roller's entrainment velocity passes "
                      "through zero: the steady EHL film vanishes")
    if zeros:
        res.warn(zero_entrainment_warning(zeros), finding="zero_entrainment")


def write_columns(res, kin, load, field, film, force, contact) -> None:
    """The film and friction columns the chain's film and friction effects write, at the
    roller's speed, and the roller's own."""
    import numpy as np

    from camtrain.formulas.friction import film_parameter

    lam = np.full(film.min.shape, np.nan)
    fin = np.isfinite(film.min)
    lam[fin] = film_parameter(film.min[fin], contact.lubricant.roughness)
    pos = load > 0.0
    mu = np.divide(force, load, out=np.zeros(load.shape), where=pos)
    rows = [("film_min", film.min, "m", f"minimum film thickness at the roller's entrainment, "
             f"{film.method} (NaN: out of contact)")]
    if film.central is not None:
        rows.append(("film_central", film.central, "m", "central film thickness at the "
                     f"roller's entrainment, {film.central_method}"))
    rows += [
        ("lambda", lam, "-", "film parameter h_min / sigma (< 1: boundary regime)"),
        ("friction_force", force, "N", "tangential force on the cam against V_c - V_f: roller "
         "traction plus rolling resistance"),
        ("friction_coefficient", mu, "-", "friction coefficient F/W (0 unloaded)"),
        ("roller_speed", field.omega_roller, "rad/s", "roller speed on its pin w_r"),
        ("roller_speed_rolling", (kin.v_cam - kin.v_follower) / field.radius, "rad/s",
         "roller speed of pure rolling (V_c - V_f) / r_r"),
        ("roller_slip", field.slip, "-", "slip 1 - w_r r_r / (V_c - V_f) (0 rolling, 1 locked)"),
        ("slide_roll_ratio", field.slide_roll_ratio, "-",
         "slide-roll ratio u_s / u_e = 2 (V_c - V_roll)/(V_c + V_roll)"),
        ("roller_sliding", field.sliding, "m/s", "cam-roller sliding speed u_s = V_c - V_roll"),
        ("roller_entrainment", field.entrainment, "m/s", "cam-roller entrainment (V_c + V_roll)/2"),
        ("roller_rolls", field.rolls.astype(float), "-",
         f"1 where the loaded roller rolls (|slip| <= {field.skid_slip:g}), 0 skids or unloaded"),
        ("roller_traction", field.traction, "N", "traction on the roller (signed as u_s)"),
        ("rolling_resistance", field.rolling_force, "N", "hydrodynamic rolling force F_R"),
        ("pin_torque", field.pin_torque, "N*m", "pin friction torque (signed as w_r)"),
        ("power_roller_sliding", field.sliding_power, "W", "cam-roller sliding loss |F_t u_s|"),
        ("power_roller_rolling", field.rolling_power, "W", "cam-roller rolling loss F_R |u_e|"),
        ("power_pin", field.pin_power, "W", "pin (bearing) loss T w_r")]
    res.add_columns(rows)
    k = kin.nose
    i = int(np.where(fin, film.min, np.inf).argmin()) if np.any(fin) else 0
    res.add_metric("film_min", float(film.min[i]), "m", "smallest minimum film over the cycle "
                   "(roller's entrainment)", float(kin.theta[i]))
    mu_b = contact.tribology.boundary_friction
    capped = pos & (np.abs(force) >= mu_b * load * (1.0 - 1e-12))
    res.add_metric("boundary_fraction", np.count_nonzero(capped) / max(np.count_nonzero(pos), 1),
                   "-", "share of loaded angles at the boundary friction limit")
    res.add_metric("film_min_at_max_lift", float(film.min[k]), "m", "minimum film at the "
                   "maximum-lift position (roller's entrainment)", float(kin.theta[k]))
