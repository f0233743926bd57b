"""A deck's hydraulic lash adjuster off the engine: the workshop leak-down test
(`camtrain leakdown DECK`) and the camshaft speed where it first pumps up
(`camtrain dynamics-speed DECK --pump-up`). Plain data out (dicts), as `dynamics_speed`."""
from __future__ import annotations

from camtrain.study.speed_search import SpeedFinding, render_search


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


#: The adjuster's pump-up: the valve held off its seat on the base circle; where: how far
#: open [mm] at the bracket's upper end.
PUMP_UP = SpeedFinding(
    threshold="pump-up", subject="the adjuster", crosses="pumps up", who="lash adjuster",
    units="speeds are camshaft rpm (a four-stroke engine turns at twice that)",
    below="pump_up_free_speed", above="pump_up_speed", where="held_open_mm",
    where_of=lambda metres: metres * 1e3,
    found="lash adjuster holds the valve shut on the base circle up to {below:.1f} rpm "
          "camshaft; pumps up at {above:.1f} rpm",
    found_where=" (valve held {where:.3g} mm open)", tried="pumped up")


def pump_up_speed(deck_path: str, *, rtol: float = 2e-3, start_rpm: float | None = None) -> dict:
    """The lowest camshaft speed at which DECK's adjuster pumps up (the valve held off its seat
    on the base circle), bracketed and bisected as the separation speed. Speeds in rpm."""
    from camtrain.assemble.dynamics import setup
    from camtrain.dynamics import march
    from camtrain.dynamics.hla import rigid_adjuster
    from camtrain.dynamics.hla.findings import adjuster_findings
    from camtrain.study.speed_search import search_speed, train_kinematics

    deck = _deck_with_adjuster(deck_path, "to search the pump-up speed")
    kin = train_kinematics(deck)
    height = deck.dynamics.lash_adjuster.checking_height

    def pumps(omega):
        s = setup(deck, kin, omega=omega, spin=False)   # the roller does not act on the train
        resp = march(s.model, s.cam, s.base, s.settings)
        rigid = march(rigid_adjuster(s.model), s.cam, s.base, s.settings)
        found = adjuster_findings(resp, rigid, s.model, height)
        return found.pumped_up, found.held_open

    return search_speed(deck_path, deck, PUMP_UP, pumps, rtol=rtol, start_rpm=start_rpm)


def render_pump_up(r: dict) -> str:
    return render_search(r, PUMP_UP)


__all__ = ["PUMP_UP", "leakdown", "render_leakdown", "pump_up_speed", "render_pump_up"]
