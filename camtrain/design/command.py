"""`camtrain design`: the deck's [design] events -> a spline lift law -> a deck that runs.

:func:`design_deck` reads a valve-train deck with a ``[design]`` section, builds the lift
(:mod:`camtrain.design.construct`), measures every event and limit on it
(:mod:`camtrain.design.check`) and writes the deck again with ``[lift]`` replaced by the
``spline`` form (the other sections as they were, ``[design]`` kept so the events travel with
the cam). Nothing is written when the events cannot be met (exit code 3).
"""
from __future__ import annotations

import copy
from dataclasses import dataclass, field
from pathlib import Path

from camtrain.design.check import HEADER, Item, continuity, measure
from camtrain.design.construct import DesignInfeasible, Events, Flank
from camtrain.errors import CamtrainError, InputError, Problem


class InfeasibleDesign(CamtrainError):
    """The events and limits admit no lift law (a physically impossible request)."""

    exit_code = 3


@dataclass
class DesignOutcome:
    """The designed law, its deck (raw TOML dictionary), every event and limit measured."""

    law: object
    raw: dict
    items: list[Item]
    jumps: dict[str, float]
    events: Events
    written: list[Path] = field(default_factory=list)

    @property
    def all_met(self) -> bool:
        return all(i.met for i in self.items)


def events_of(model) -> tuple[Events, float, float]:
    """The [design] section (SI in the model) as Events in mm and cam deg, with the lift and
    angle tolerances [mm, deg]."""
    from camtrain.units import from_si

    d = model.design
    if d is None:
        raise InputError(Problem("design", "is missing", None,
                                 "a [design] section with the valve events and limits"))
    k = 2.0 if d.angle_basis == "crank" else 1.0      # crank deg per cam deg

    def deg(v):
        return None if v is None else from_si(v, "deg") / k

    def per(v, unit, order):
        return None if v is None else from_si(v, unit) * k ** order

    heights = tuple(from_si(h, "mm") for h in d.checking_heights)
    opening = Flank(heights, tuple(deg(a) for a in d.opening_angles),
                    from_si(d.ramp_height, "mm"), per(d.ramp_velocity, "mm/deg", 1),
                    deg(d.ramp_length))
    closing_angles = d.closing_angles or d.opening_angles
    pick = [(getattr(d, f"closing_{f}") if getattr(d, f"closing_{f}") is not None
             else getattr(d, f)) for f in ("ramp_height", "ramp_velocity", "ramp_length")]
    closing = Flank(heights, tuple(deg(a) for a in closing_angles), from_si(pick[0], "mm"),
                    per(pick[1], "mm/deg", 1), deg(pick[2]))
    ev = Events(from_si(d.max_lift, "mm"), opening, closing,
                per(d.max_acceleration, "mm/deg²", 2), per(d.max_deceleration, "mm/deg²", 2),
                per(d.max_jerk, "mm/deg³", 3), d.symmetric, int(d.spans))
    return ev, from_si(d.lift_tolerance, "mm"), from_si(d.angle_tolerance, "deg") / k


def design_deck(deck: str | Path) -> DesignOutcome:
    """Design the lift of ``deck``'s [design] section; InfeasibleDesign if none exists."""
    from camtrain.deck.load import load_deck, parse_toml

    loaded = load_deck(str(deck))
    base = Path(deck).resolve().parent if str(deck) != "-" else Path.cwd()
    return design_raw(parse_toml(loaded.text, loaded.path), loaded.path, base, loaded.model)


def design_raw(raw: dict, name: str, base_dir: str | Path, model=None) -> DesignOutcome:
    """:func:`design_deck` on a raw deck dictionary (``model``: its validated model, if known).

    The outcome's ``raw`` is a copy of ``raw`` with the spline [lift]."""
    from camtrain.deck.load import validate
    from camtrain.design.construct import design_lift
    from camtrain.lift.base import DEG, MM
    from camtrain.lift.spline import SplineLift

    if model is None:
        model = validate(raw, name, Path(base_dir))
    ev, lift_tol, angle_tol = events_of(model)
    try:
        made = design_lift(ev)
    except DesignInfeasible as exc:
        raise InfeasibleDesign(f"design: {exc}") from None
    law = SplineLift(made.knots * DEG, made.coefficients * MM, made.degree)
    raw = copy.deepcopy(raw)
    lift = raw.get("lift", {})
    raw["lift"] = {"form": "spline", "measured_at": lift.get("measured_at", "valve")}
    if "inspection_radius" in lift:
        raw["lift"]["inspection_radius"] = lift["inspection_radius"]
    raw["lift"]["spline"] = law.in_deck_units()
    validate(raw, name, Path(base_dir))       # the written deck must load as it is
    items = measure(ev, law, lift_tol, angle_tol)
    return DesignOutcome(law, raw, items, continuity(law), ev)


def report_text(outcome: DesignOutcome, name: str) -> str:
    """The design report (Markdown): every event and limit, the continuity, the law."""
    rows = [HEADER] + [i.row() for i in outcome.items]
    widths = [max(len(str(r[c])) for r in rows) for c in range(len(HEADER))]
    lines = ["| " + " | ".join(str(v).ljust(w) for v, w in zip(r, widths, strict=True)) + " |"
             for r in rows]
    lines.insert(1, "|" + "|".join("-" * (w + 2) for w in widths) + "|")
    met = sum(i.met for i in outcome.items)
    j = outcome.jumps
    law = outcome.law
    return "\n".join([
        f"# Lift design: {name}", "",
        f"{met} of {len(outcome.items)} events and limits met. The lift is a degree-"
        f"{law.degree} B-spline on {len(law.knots)} knots from {law.opening_angle / DEG_:.3f} to "
        f"{law.closing_angle / DEG_:.3f} cam deg (the nose at 0).", "", *lines, "",
        "Largest jump over every knot and both base-circle joints: "
        f"lift {j['lift']:.2e} mm, velocity {j['velocity']:.2e} mm/deg, acceleration "
        f"{j['acceleration']:.2e} mm/deg², jerk {j['jerk']:.2e} mm/deg³ "
        "(continuous to the jerk; a B-spline of degree 5 is C4 across its simple knots).", ""])


DEG_ = 3.141592653589793 / 180.0


def write_design(outcome: DesignOutcome, out_dir: Path, name: str, plots: bool = True) -> list[Path]:
    """designed.toml, design.md, design.csv and (unless ``plots`` is False) design.png."""
    import csv
    import io

    import tomli_w

    from camtrain.report.tables import atomic_write

    out_dir.mkdir(parents=True, exist_ok=True)
    head = (f"# Lift designed by camtrain design from the [design] events of {Path(name).name}"
            "\n# (docs/design.md); run it, sweep it or optimise it like any deck.\n\n")
    written = [out_dir / "designed.toml", out_dir / "design.md", out_dir / "design.csv"]
    atomic_write(written[0], head + tomli_w.dumps(outcome.raw))
    atomic_write(written[1], report_text(outcome, name))
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(HEADER)
    for item in outcome.items:
        w.writerow(item.row())
    atomic_write(written[2], buf.getvalue())
    if plots:
        written.append(_plot(outcome, out_dir / "design.png", name))
    outcome.written = written
    return written


def _plot(outcome: DesignOutcome, path: Path, name: str) -> Path:
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from camtrain.lift.base import DEG, MM

    law = outcome.law
    theta = np.linspace(law.opening_angle - 5 * DEG, law.closing_angle + 5 * DEG, 2001)
    c = law.evaluate(theta)
    fig = Figure(figsize=(7.0, 8.0), constrained_layout=True)
    FigureCanvasAgg(fig)
    axes = fig.subplots(4, 1, sharex=True)
    deg = theta / DEG
    ev = outcome.events
    rows = ((c.lift / MM, "lift [mm]", None), (c.d1 / MM * DEG, "velocity [mm/deg]", None),
            (c.d2 / MM * DEG ** 2, "acceleration [mm/deg²]",
             (ev.max_acceleration, -ev.max_deceleration if ev.max_deceleration else None)),
            (c.d3 / MM * DEG ** 3, "jerk [mm/deg³]",
             (ev.max_jerk, -ev.max_jerk if ev.max_jerk else None)))
    for ax, (y, label, limits) in zip(axes, rows, strict=True):
        ax.plot(deg, y, lw=1.2)
        ax.set_ylabel(label)
        for lim in limits or ():
            if lim is not None:
                ax.axhline(lim, color="0.4", ls="--", lw=0.8)
    for flank, side in ((ev.opening, -1), (ev.closing, 1)):
        axes[0].plot([side * a for a in flank.angles], flank.heights, "o", ms=4, color="C3")
    axes[0].set_title(f"{Path(name).name}: designed lift (events as dots, limits dashed)")
    axes[-1].set_xlabel("cam angle from the nose [deg]")
    fig.savefig(path, dpi=110)
    return path
