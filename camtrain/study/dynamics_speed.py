"""The highest camshaft speed at which the elastic train keeps the follower on the cam
(`camtrain dynamics-speed DECK`), beside the rigid train's closed-form bounce speed.

Plain data out (a dict), so the command line, a notebook and a test read the same thing.
"""
from __future__ import annotations

import math


def dynamics_speed(deck_path: str, *, rtol: float = 2e-3, start_rpm: float | None = None,
                   stiffness_scale: float = 1.0) -> dict:
    """Search the first separation speed of DECK's elastic train (bracket, then bisection to
    ``rtol``). Returns speeds in rpm and angles in deg."""
    from camtrain import api
    from camtrain.assemble.dynamics import separation_check
    from camtrain.assemble.lift_law import build_lift_law
    from camtrain.assemble.mechanism import kinematics
    from camtrain.dynamics.speed import first_separation_speed
    from camtrain.errors import field_error
    from camtrain.lift import angle_grid
    from camtrain.loads import bounce_speed
    from camtrain.units import rad_s_to_rpm, rpm_to_rad_s

    deck = api.load(deck_path).model
    if getattr(deck, "dynamics", None) is None:
        raise field_error("dynamics", "is required to search the separation speed", None,
                          "a [dynamics] section (see `camtrain template` and docs/dynamics.md)")
    curve = build_lift_law(deck.lift).evaluate(angle_grid(deck.solver.angle_points))
    kin = kinematics(deck, curve)[0]
    c = deck.clearance
    rigid = bounce_speed(kin, deck.tribology.boundary_friction, rate=deck.spring.rate,
                         preload_compression=deck.spring.preload_compression,
                         valve_mass=deck.masses.valve_side,
                         clearance=0.0 if (c is None or c.lash_adjuster) else c.valve_clearance)
    start = rpm_to_rad_s(start_rpm) if start_rpm else deck.speed.omega
    try:
        search = first_separation_speed(
            separation_check(deck, kin, stiffness_scale=stiffness_scale), start, rtol=rtol)
    except ValueError as exc:
        return {"deck": deck_path, "found": False, "speed_of": "camshaft", "message": str(exc),
                **_rigid(rigid, rad_s_to_rpm)}
    return {"deck": deck_path, "found": True, "speed_of": "camshaft",
            "separation_speed": rad_s_to_rpm(search.omega),
            "separating_speed": rad_s_to_rpm(search.upper),
            "separation_angle": math.degrees(search.angle) if search.angle is not None else None,
            "evaluations": [(rad_s_to_rpm(w), sep) for w, sep in search.evaluations],
            "rtol": rtol, **_rigid(rigid, rad_s_to_rpm)}


def _rigid(bounce, to_rpm) -> dict:
    if not math.isfinite(bounce.omega):
        return {"bounce_speed": None, "bounce_angle": None}
    return {"bounce_speed": to_rpm(bounce.omega), "bounce_angle": math.degrees(bounce.angle)}


def render(report: dict) -> str:
    """The search as a few readable lines. Every speed is the camshaft's (a valve-train deck's
    ``speed.camshaft``; a four-stroke crankshaft turns twice as fast), every angle a cam angle
    from maximum lift."""
    lines = [f"deck: {report['deck']}",
             "speeds are camshaft rpm (a four-stroke engine turns at twice that); angles are "
             "cam deg from maximum lift"]
    if report["bounce_speed"] is not None:
        lines.append(f"rigid train, closed-form bounce speed: {report['bounce_speed']:.1f} rpm "
                     f"camshaft (contact lost first at {report['bounce_angle']:.1f} deg cam)")
    if not report["found"]:
        lines.append(f"elastic train: {report['message']}")
        return "\n".join(lines)
    lines.append(f"elastic train keeps contact up to {report['separation_speed']:.1f} rpm "
                 f"camshaft; separates at {report['separating_speed']:.1f} rpm camshaft (first "
                 f"loss at {report['separation_angle']:.2f} deg cam); bracket "
                 f"{100 * report['rtol']:g} %")
    lines.append("camshaft speeds tried (rpm, separated): " + ", ".join(
        f"{w:.0f} {'yes' if s else 'no'}" for w, s in report["evaluations"]))
    return "\n".join(lines)
