"""A deck's hydraulic lash adjuster off the engine: the workshop leak-down test
(`camtrain leakdown DECK`) and the camshaft speed where it first pumps up
(`camtrain dynamics-speed DECK --pump-up`). Plain data out (dicts), as `dynamics_speed`."""
from __future__ import annotations


def _deck_with_adjuster(deck_path: str, what: str):
    from camtrain import api
    from camtrain.errors import field_error

    deck = api.load(deck_path).model
    d = getattr(deck, "dynamics", None)
    if d is None or d.lash_adjuster is None:
        raise field_error("dynamics.lash_adjuster", f"is required {what}", None,
                          "a [dynamics.lash_adjuster] section (docs/lash_adjusters.md)")
    return deck


def leakdown(deck_path: str, *, load: float = 222.0, travel: float = 1.0e-3,
             start: float = 0.1e-3) -> dict:
    """The leak-down test of DECK's adjuster: ``load`` [N] on the plunger from full extension,
    time [s] between ``start`` and ``start + travel`` [m] of collapse, marched and in closed
    form, with the tester's oil at the deck's viscosity and atmospheric pressure."""
    from camtrain.assemble.dynamics import lash_adjuster
    from camtrain.dynamics.hla import leakdown_test, leakdown_time
    from camtrain.errors import field_error

    deck = _deck_with_adjuster(deck_path, "for the leak-down test")
    adj = lash_adjuster(deck)
    if start + travel >= adj.stroke:
        raise field_error("dynamics.lash_adjuster.stroke", "is shorter than the leak-down "
                          "travel", f"{adj.stroke * 1e3:g} mm",
                          f"more than start + travel = {(start + travel) * 1e3:g} mm")
    try:
        closed = leakdown_time(adj, load, travel, start)
        marched, begun, pressure = leakdown_test(adj, load, travel, start)
    except ValueError as exc:
        raise field_error("dynamics.lash_adjuster", str(exc), f"{load:g} N",
                          "a load above the plunger spring's force") from None
    return {"deck": deck_path, "load": load, "travel_mm": travel * 1e3,
            "start_mm": start * 1e3, "time": marched, "time_closed_form": closed,
            "start_time": begun, "pressure_bar": pressure / 1e5,
            "viscosity": adj.viscosity, "eccentricity": adj.eccentricity}


def render_leakdown(r: dict) -> str:
    return "\n".join([
        f"deck: {r['deck']}",
        f"leak-down test: {r['load']:g} N on the plunger, {r['travel_mm']:g} mm of travel "
        f"from {r['start_mm']:g} mm below full extension (oil {r['viscosity']:g} Pa·s, "
        f"eccentricity {r['eccentricity']:g})",
        f"time: {r['time']:.4g} s marched, {r['time_closed_form']:.4g} s laminar annulus "
        f"closed form (start mark reached after {r['start_time']:.3g} s; chamber "
        f"{r['pressure_bar']:.4g} bar)"])


def pump_up_speed(deck_path: str, *, rtol: float = 2e-3, start_rpm: float | None = None) -> dict:
    """The lowest camshaft speed at which DECK's adjuster pumps up (the valve held off its seat
    on the base circle), bracketed and bisected as the separation speed. Speeds in rpm."""
    from camtrain.assemble.dynamics import setup
    from camtrain.assemble.lift_law import build_lift_law
    from camtrain.assemble.mechanism import kinematics
    from camtrain.dynamics import march
    from camtrain.dynamics.hla import rigid_adjuster
    from camtrain.dynamics.hla.findings import adjuster_findings
    from camtrain.dynamics.speed import first_separation_speed
    from camtrain.lift import angle_grid
    from camtrain.units import rad_s_to_rpm, rpm_to_rad_s

    deck = _deck_with_adjuster(deck_path, "to search the pump-up speed")
    curve = build_lift_law(deck.lift).evaluate(angle_grid(deck.solver.angle_points))
    kin = kinematics(deck, curve)[0]
    height = deck.dynamics.lash_adjuster.checking_height

    def pumps(omega):
        s = setup(deck, kin, omega=omega, spin=False)   # the roller does not act on the train
        resp = march(s.model, s.cam, s.base, s.settings)
        rigid = march(rigid_adjuster(s.model), s.cam, s.base, s.settings)
        found = adjuster_findings(resp, rigid, s.model, height)
        return found.pumped_up, found.held_open

    start = rpm_to_rad_s(start_rpm) if start_rpm else deck.speed.omega
    try:
        search = first_separation_speed(pumps, start, rtol=rtol)
    except ValueError as exc:
        return {"deck": deck_path, "found": False, "message": str(exc).replace(
            "separation threshold", "pump-up threshold").replace("separates", "pumps up")
            .replace("never separates", "never pumps up")}
    return {"deck": deck_path, "found": True, "speed_of": "camshaft",
            "pump_up_free_speed": rad_s_to_rpm(search.omega),
            "pump_up_speed": rad_s_to_rpm(search.upper),
            "held_open_mm": None if search.angle is None else search.angle * 1e3,
            "evaluations": [(rad_s_to_rpm(w), p) for w, p in search.evaluations], "rtol": rtol}


def render_pump_up(r: dict) -> str:
    lines = [f"deck: {r['deck']}", "speeds are camshaft rpm (a four-stroke engine turns at "
             "twice that)"]
    if not r["found"]:
        lines.append(f"lash adjuster: {r['message']}")
        return "\n".join(lines)
    lines.append(f"lash adjuster holds the valve shut on the base circle up to "
                 f"{r['pump_up_free_speed']:.1f} rpm camshaft; pumps up at "
                 f"{r['pump_up_speed']:.1f} rpm (valve held {r['held_open_mm']:.3g} mm open); "
                 f"bracket {100 * r['rtol']:g} %")
    lines.append("camshaft speeds tried (rpm, pumped up): " + ", ".join(
        f"{w:.0f} {'yes' if p else 'no'}" for w, p in r["evaluations"]))
    return "\n".join(lines)


__all__ = ["leakdown", "render_leakdown", "pump_up_speed", "render_pump_up"]
