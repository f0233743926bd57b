"""One bracketed camshaft-speed search and its report, for any threshold a valve train crosses
once as it speeds up: the elastic train's first separation (`camtrain dynamics-speed DECK`,
:mod:`camtrain.study.dynamics_speed`) and the hydraulic lash adjuster's pump-up
(`--pump-up`, :mod:`camtrain.study.lash_adjuster`). A :class:`SpeedFinding` says what is
searched and how the report words it; the search (:func:`search_speed`, bracket then bisection
by :func:`camtrain.dynamics.speed.first_separation_speed`) and the lines printed
(:func:`render_search`) are the same for every finding.

Plain data out (a dict), so the command line, a notebook and a test read the same thing. Speeds
are the camshaft's, in rpm.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass


@dataclass(frozen=True)
class SpeedFinding:
    """What a speed search looks for and its words.

    ``threshold`` names it in a message ("no {threshold} threshold found"); ``subject`` and
    ``crosses`` make the sentence of a search without a bracket ("{subject} {crosses} at every
    speed tried", "{subject} never {crosses} at the speeds tried"); ``who`` heads the report's
    line; ``units`` is the report's second line. ``below``, ``above`` and ``where`` are the
    report's keys of the bracket's ends (rpm) and of what the search returned at its upper end,
    ``where_of`` converts that from SI to the unit ``found`` prints it in. ``found`` is the
    sentence of a bracket (``{below}``, ``{above}`` formatted by the template) and ``found_where``
    its tail with ``{where}`` (left out when the search returned nothing there); ``tried`` says
    what "yes" means in the list of speeds tried."""

    threshold: str
    subject: str
    crosses: str
    who: str
    units: str
    below: str
    above: str
    where: str
    where_of: Callable[[float], float]
    found: str
    found_where: str
    tried: str

    def no_bracket(self, crossed_everywhere: bool) -> str:
        """The message of a search that found no bracket."""
        return (f"no {self.threshold} threshold found: " + (
            f"{self.subject} {self.crosses} at every speed tried" if crossed_everywhere else
            f"{self.subject} never {self.crosses} at the speeds tried"))


def train_kinematics(deck):
    """The follower kinematics of DECK's valve train on its own angle grid (what every speed
    search marches the train over)."""
    from camtrain.assemble.lift_law import build_lift_law
    from camtrain.assemble.mechanism import kinematics
    from camtrain.lift import angle_grid

    curve = build_lift_law(deck.lift).evaluate(angle_grid(deck.solver.angle_points))
    return kinematics(deck, curve)[0]


def search_speed(deck_path: str, deck, finding: SpeedFinding,
                 crosses: Callable[[float], tuple[bool, float | None]], *, rtol: float,
                 start_rpm: float | None) -> dict:
    """Bracket and bisect the camshaft speed where ``crosses(omega) -> (crossed, where)`` turns
    True, from ``start_rpm`` (default: the deck's speed) to a bracket ``rtol`` wide."""
    from camtrain.dynamics.speed import NoThreshold, first_separation_speed
    from camtrain.units import rad_s_to_rpm, rpm_to_rad_s

    start = rpm_to_rad_s(start_rpm) if start_rpm else deck.speed.omega
    try:
        search = first_separation_speed(crosses, start, rtol=rtol)
    except ValueError as exc:    # no bracket, or a march that cannot run at a speed tried
        return {"deck": deck_path, "found": False, "speed_of": "camshaft", "message": (
            finding.no_bracket(exc.crossed_everywhere) if isinstance(exc, NoThreshold)
            else str(exc))}
    return {"deck": deck_path, "found": True, "speed_of": "camshaft",
            finding.below: rad_s_to_rpm(search.omega),
            finding.above: rad_s_to_rpm(search.upper),
            finding.where: None if search.angle is None else finding.where_of(search.angle),
            "evaluations": [(rad_s_to_rpm(w), crossed) for w, crossed in search.evaluations],
            "rtol": rtol}


def render_search(report: dict, finding: SpeedFinding, preamble: Sequence[str] = ()) -> str:
    """The search as a few readable lines: the deck, the units, ``preamble`` (lines of the
    finding's own), the bracket found (or why none) and the speeds tried."""
    lines = [f"deck: {report['deck']}", finding.units, *preamble]
    if not report["found"]:
        lines.append(f"{finding.who}: {report['message']}")
        return "\n".join(lines)
    where = report[finding.where]
    lines.append(finding.found.format(below=report[finding.below], above=report[finding.above])
                 + ("" if where is None else finding.found_where.format(where=where))
                 + f"; bracket {100 * report['rtol']:g} %")
    lines.append(f"camshaft speeds tried (rpm, {finding.tried}): " + ", ".join(
        f"{w:.0f} {'yes' if crossed else 'no'}" for w, crossed in report["evaluations"]))
    return "\n".join(lines)


__all__ = ["SpeedFinding", "render_search", "search_speed", "train_kinematics"]
