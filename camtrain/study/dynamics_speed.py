"""The highest camshaft speed at which the elastic train keeps the follower on the cam
(`camtrain dynamics-speed DECK`), beside the rigid train's closed-form bounce speed: the
separation finding of the shared speed search (:mod:`camtrain.study.speed_search`).

Plain data out (a dict), so the command line, a notebook and a test read the same thing.
"""
from __future__ import annotations

import math

from camtrain.study.speed_search import SpeedFinding, render_search

#: The first separation of the elastic train while the valve is off its seat; where: the cam
#: angle [deg] from maximum lift of the first loss at the bracket's upper end.
SEPARATION = SpeedFinding(
    threshold="separation", subject="the train", crosses="separates", who="elastic train",
    units="speeds are camshaft rpm (a four-stroke engine turns at twice that); angles are cam "
          "deg from maximum lift",
    below="separation_speed", above="separating_speed", where="separation_angle",
    where_of=math.degrees,
    found="elastic train keeps contact up to {below:.1f} rpm camshaft; separates at {above:.1f} "
          "rpm camshaft",
    found_where=" (first loss at {where:.2f} deg cam)", tried="separated")


def dynamics_speed(deck_path: str, *, rtol: float = 2e-3, start_rpm: float | None = None,
                   stiffness_scale: float = 1.0) -> dict:
    """Search the first separation speed of DECK's elastic train (bracket, then bisection to
    ``rtol``). Returns speeds in rpm and angles in deg."""
    from camtrain import api
    from camtrain.assemble.dynamics import separation_check
    from camtrain.errors import field_error
    from camtrain.loads import bounce_speed
    from camtrain.study.speed_search import search_speed, train_kinematics

    deck = api.load(deck_path).model
    if getattr(deck, "dynamics", None) is None:
        raise field_error("dynamics", "is required to search the separation speed", None,
                          "a [dynamics] section (see `camtrain template` and docs/dynamics.md)")
    kin = train_kinematics(deck)
    c = deck.clearance
    rigid = bounce_speed(kin, deck.tribology.boundary_friction, rate=deck.spring.rate,
                         preload_compression=deck.spring.preload_compression,
                         valve_mass=deck.masses.valve_side,
                         clearance=0.0 if (c is None or c.lash_adjuster) else c.valve_clearance)
    report = search_speed(deck_path, deck, SEPARATION,
                          separation_check(deck, kin, stiffness_scale=stiffness_scale),
                          rtol=rtol, start_rpm=start_rpm)
    return {**report, **_rigid(rigid)}


def _rigid(bounce) -> dict:
    from camtrain.units import rad_s_to_rpm

    if not math.isfinite(bounce.omega):
        return {"bounce_speed": None, "bounce_angle": None}
    return {"bounce_speed": rad_s_to_rpm(bounce.omega), "bounce_angle": math.degrees(bounce.angle)}


def render(report: dict) -> str:
    """The search as a few readable lines. Every speed is the camshaft's (a valve-train deck's
    ``speed.camshaft``; a four-stroke crankshaft turns twice as fast), every angle a cam angle
    from maximum lift."""
    rigid = [] if report["bounce_speed"] is None else [
        f"rigid train, closed-form bounce speed: {report['bounce_speed']:.1f} rpm camshaft "
        f"(contact lost first at {report['bounce_angle']:.1f} deg cam)"]
    return render_search(report, SEPARATION, rigid)
