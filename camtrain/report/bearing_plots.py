"""Polar journal-orbit plots, and the report header of a stand-alone bearing deck.

An orbit is drawn as the journal-centre path in the bush frame: radius = eccentricity ratio
(the clearance circle is radius 1), polar angle = direction of the line of centres, which is
the direction of the minimum film (Booker 1965; the polar orbit diagrams of Yang 1992 ch 4 and
Ball 1988 ch 6). Markers show the load-diagram angles 0, 90, 180 and 270 deg and the point of
largest eccentricity. Matplotlib is imported lazily with the Agg backend, so importing this
module costs nothing and needs no display.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from camtrain.catalogue import components_of, declared_effects
from camtrain.result import Result
from camtrain.units import from_si

_MARKS = (0.0, 90.0, 180.0, 270.0)


@dataclass(frozen=True)
class OrbitSeries:
    """One orbit taken from a Result: label, load-diagram angle [rad], eps [-], direction [rad],
    the minimum film over the cycle [m] (None when the run has no film column) and the frame
    the directions are measured in."""

    label: str
    angle: np.ndarray
    eccentricity: np.ndarray
    position: np.ndarray
    film: np.ndarray | None = None
    frame: str = "bush frame"


def _frame(name: str | None) -> str:
    """The frame of a bearing's directions: a big-end's are in rod axes, a main's in block
    axes, a camshaft or stand-alone bearing's in its bush."""
    if name is not None and name.startswith("big_end"):
        return "rod axes"
    if name is not None and name.startswith("main"):
        return "block axes"
    return "bush frame"


def _bearings(result: Result) -> list[str | None]:
    """The parts of a run that are bearings: those the effects of its plan that make orbits
    declare (EffectSpec.components: the camshaft's ``bearing_{k}``, an engine's ``big_end_{k}``
    and ``main_{k}``), or the result itself when such an effect declares none (a stand-alone
    bearing deck)."""
    makers = [spec for spec in declared_effects(result.plan)
              if {"BearingOrbits", "EngineBearings"} & set(spec.produces)]
    alone = [None] if any(not spec.components for spec in makers) else []
    return alone + [c for product in ("BearingOrbits", "EngineBearings")
                    for c in components_of(result.plan, product, result.components)]


def orbit_series(result: Result) -> list[OrbitSeries]:
    """Every orbit in a run: each bearing's (the bearings of a camshaft or an engine run), or
    the orbit of the result itself (a stand-alone bearing deck)."""
    out = []
    for name in _bearings(result):
        part = result.component(name)
        # a partially grooved crank bearing has both extremes (suffixes), each its own orbit;
        # a camshaft bearing whose orbit did not converge (warned) or of method petroff has none
        for sfx in ("", "_ungrooved", "_grooved"):
            ecc, pos = f"eccentricity{sfx}", f"min_film_position{sfx}"
            if ecc not in part.columns:
                continue
            col = part.columns[ecc]
            label = ("bearing" if name is None else name.replace("_", " ")) + sfx.replace("_",
                                                                                          " ")
            out.append(OrbitSeries(label.replace("big end", "big-end"), result[col.axis],
                                   part[ecc], part[pos], part[f"min_film{sfx}"], _frame(name)))
    return out


def _nearest(angle: np.ndarray, target_deg: float) -> int:
    d = np.angle(np.exp(1j * (angle - math.radians(target_deg))))  # wrapped difference
    return int(np.argmin(np.abs(d)))


def _thinnest(series: OrbitSeries) -> int:
    """Where on the cycle the film is thinnest (the largest eccentricity without a film)."""
    if series.film is not None and np.isfinite(series.film).any():
        return int(np.nanargmin(series.film))
    return int(np.argmax(series.eccentricity))


def thinnest_text(series: OrbitSeries) -> str:
    """'h_min 0.638 µm at 107°' (or the largest eccentricity ratio without a film column)."""
    i = _thinnest(series)
    at = f"at {math.degrees(series.angle[i]):.0f}°"
    if series.film is None:
        return f"ε_max {series.eccentricity[i]:.3f} {at}"
    return f"h_min {series.film[i] * 1e6:.3g} µm {at}"


def orbit_axes(ax, series: OrbitSeries, *, markers: bool = True, small: bool = False) -> None:
    """Draw one polar orbit on a matplotlib polar axes: the journal-centre path (arrows: the
    way it travels as the cycle goes on), the clearance circle, the load-diagram angles 0, 90,
    180 and 270 deg and the thinnest film (star)."""
    pos = np.append(series.position, series.position[0])  # the orbit is closed
    eps = np.append(series.eccentricity, series.eccentricity[0])
    ax.plot(pos, eps, lw=1.0 if small else 1.2, color="#1f4e79", label="journal centre")
    n = len(series.position)
    for k in (n // 8, 5 * n // 8):          # the sense of travel along the orbit
        j = min(k + max(n // 60, 1), n - 1)
        ax.annotate("", xy=(series.position[j], series.eccentricity[j]),
                    xytext=(series.position[k], series.eccentricity[k]),
                    arrowprops={"arrowstyle": "-|>", "color": "#1f4e79", "lw": 0.8,
                                "mutation_scale": 7 if small else 10})
    circle = np.linspace(0.0, 2.0 * math.pi, 181)
    ax.plot(circle, np.ones_like(circle), lw=0.8, color="0.4", ls="--", label="clearance")
    if markers:
        colors = ("#c0504d", "#4f8a3c", "#8064a2", "#d08c00")
        for j, deg in enumerate(_MARKS):
            i = _nearest(series.angle, deg)
            ax.plot(series.position[i], series.eccentricity[i], "o", ms=3.5 if small else 5,
                    color=colors[j], label=f"cycle angle {deg:g}°")
    i = _thinnest(series)
    ax.plot(series.position[i], series.eccentricity[i], "*", ms=8 if small else 11, color="k",
            label=thinnest_text(series))
    ax.set_ylim(0.0, 1.0)
    ax.set_yticks([0.25, 0.5, 0.75, 1.0])
    ax.set_rlabel_position(112.5)
    if small:
        ax.tick_params(labelsize=6, pad=0)
        ax.set_yticklabels([])


#: what every orbit plot shows, written under it
ORBIT_NOTE = ("Journal-centre path: radius = eccentricity ratio (dashed: the clearance circle), "
              "angle = direction of the line of centres, where the film is thinnest, counter-"
              "clockwise positive in the frame named; arrows: the way the centre travels as "
              "the cycle goes on; star: the thinnest film.")


def rotation_note(deck) -> str:
    """The sense in which the journal turns in its frame, from the deck: an engine's crank turns
    counter-clockwise (camtrain.engine.crank), a camshaft as its ``camshaft.rotation`` says, a
    stand-alone journal as the sign of its speed relative to the bush."""
    if deck is None:
        return ""
    if hasattr(deck, "engine"):
        return "The crank turns counter-clockwise in these frames."
    shaft = getattr(deck, "camshaft", None)
    if shaft is not None:
        sense = "counter-clockwise" if shaft.rotation == "anticlockwise" else "clockwise"
        return f"The camshaft turns {sense} (camshaft.rotation)."
    speed = getattr(deck, "speed", None)
    if speed is not None and hasattr(speed, "journal"):
        relative = speed.journal - speed.bearing
        sense = "counter-clockwise" if relative >= 0 else "clockwise"
        return f"The journal turns {sense} relative to the bush (speed.journal, speed.bearing)."
    return ""


def orbit_figure(series: OrbitSeries, title: str = "", sha: str | None = None,
                 rotation: str = ""):
    """A matplotlib Figure with one polar orbit, its legend beside it and the convention and
    provenance under it."""
    import matplotlib

    from camtrain import __version__
    from camtrain.report.canvas import figure
    from camtrain.report.layout import fit_text
    from camtrain.report.style import RC

    with matplotlib.rc_context(RC):
        fig = figure((6.4, 4.8))
        ax = fig.add_axes([0.08, 0.22, 0.5, 0.62], projection="polar")
        orbit_axes(ax, series)
        ax.set_title(f"{series.label} ({series.frame}): {thinnest_text(series)}", pad=20,
                     fontsize=9.5)
        ax.legend(loc="upper left", bbox_to_anchor=(1.12, 1.0), fontsize=7, frameon=False)
        if title:
            head = fig.text(0.02, 0.975, title, fontsize=10, fontweight="bold", va="top")
            renderer = fig.canvas.get_renderer()

            def measure(text: str) -> float:
                head.set_text(text)
                return head.get_window_extent(renderer).width

            head.set_text(fit_text(title, 0.96 * fig.bbox.width, measure))
        foot = f"camtrain {__version__}" + (f", deck sha256 {sha[:16]}" if sha else "")
        note = ORBIT_NOTE + (f" {rotation}" if rotation else "")
        fig.text(0.02, 0.015, _wrapped(note, 110) + "\n" + foot, fontsize=6,
                 color="#404040", va="bottom")
    return fig


def _wrapped(text: str, width: int) -> str:
    import textwrap

    return "\n".join(textwrap.wrap(text, width))


def write_orbit_plots(result: Result, out_dir: Path, *, title: str = "",
                      fmt: str = "png", sha: str | None = None, deck=None) -> list[Path]:
    """One polar orbit plot per bearing, ``orbit_<bearing>.<fmt>``; returns the files.
    ``deck`` (when given) says which way the journal turns."""
    from camtrain.report.canvas import save_sheet

    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    written = []
    for s in orbit_series(result):
        stem = out_dir / ("orbit_" + s.label.replace(" ", "_").replace("-", "_"))
        written += save_sheet(orbit_figure(s, title, sha, rotation_note(deck)), stem, (fmt,))
    return written


#: orbits on one A4 sheet (three to a row)
ORBITS_PER_SHEET = 15


def orbit_sheets(result: Result, out_dir: Path, *, deck=None, sha: str | None = None,
                 formats=("png",)) -> list[Path]:
    """``sheet_orbits.<fmt>`` (and ``sheet_orbits_2`` ... past fifteen bearings): every
    journal orbit of the run as small multiples on an A4 page in the house style, each titled
    with its thinnest film in µm and where, the frame and conventions at the foot."""
    from camtrain.report.canvas import save_sheet
    from camtrain.report.house import foot_note, grid, house_page

    series = orbit_series(result)
    written: list[Path] = []
    for page, start in enumerate(range(0, len(series), ORBITS_PER_SHEET)):
        chunk = series[start:start + ORBITS_PER_SHEET]
        rows = max(-(-len(chunk) // 3), 3)
        with house_page(deck, result, "Journal orbits (minimum film, frame, travel)",
                        sha) as fig:
            spec = grid(fig, rows, 3, bottom_in=0.35, hspace=0.5, wspace=0.35)
            for k, s in enumerate(chunk):
                ax = fig.add_subplot(spec[k // 3, k % 3], projection="polar")
                orbit_axes(ax, s, markers=False, small=True)
                ax.set_title(f"{s.label} ({s.frame})\n{thinnest_text(s)}", fontsize=7.5,
                             pad=17)
            foot_note(fig, _wrapped(f"{ORBIT_NOTE} {rotation_note(deck)} Rings at "
                                    "eccentricity ratio 0.25, 0.5, 0.75.", 150))
            stem = Path(out_dir) / ("sheet_orbits" if page == 0 else f"sheet_orbits_{page + 1}")
            Path(out_dir).mkdir(parents=True, exist_ok=True)
            written += save_sheet(fig, stem, formats)
    return written


def _film_model_text(deck) -> str:
    """The film model the run uses (short or finite, and how it was chosen)."""
    from camtrain.bearings import JournalBearing
    from camtrain.bearings.models import choose_model

    sol, g = deck.solver, deck.bearing
    if sol.method == "petroff":
        return "none (Petroff)"
    used, _ = choose_model(JournalBearing(g.diameter, g.length, g.clearance, g.viscosity,
                                          g.groove_width), sol.model)
    text = "short (Ocvirk)" if used == "short" else \
        f"finite ({sol.cavitation}, {sol.n_theta} x {sol.n_z})"
    return text + (" by auto" if sol.model == "auto" else "")


def bearing_header_rows(deck, result: Result | None) -> list[tuple[str, str]]:
    """Header rows (label with unit, value) of a ``kind = "journal_bearing"`` deck, the
    counterpart of the valve-train header for report.txt and the sheets."""
    g, s = deck.bearing, deck.speed
    rows = [("Diameter (mm)", f"{from_si(g.diameter, 'mm'):g}"),
            ("Length (mm)", f"{from_si(g.length, 'mm'):g}"),
            ("Radial clearance (mm)", f"{from_si(g.clearance, 'mm'):g}"),
            ("Groove width (mm)", f"{from_si(g.groove_width, 'mm'):g}"),
            ("Viscosity (Pa·s)", f"{g.viscosity:g}"),
            ("Journal / bush speed (rpm)",
             f"{from_si(s.journal, 'rpm'):g} / {from_si(s.bearing, 'rpm'):g}"),
            ("Method / film", f"{deck.solver.method} / {deck.solver.film}"),
            ("Film model", _film_model_text(deck))]
    if result is not None:
        for key, label, unit, scale in (("max_eccentricity", "Max eccentricity ratio", "", 1.0),
                                        ("min_film", "Min film (µm)", "", 1e6),
                                        ("power_mean", "Mean power (W)", "", 1.0)):
            m = result.metrics.get(key)
            rows.append((label, "not computed" if m is None else f"{m.value * scale:.4g}{unit}"))
    return rows
