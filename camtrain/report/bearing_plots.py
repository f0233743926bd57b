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

from camtrain.result import Result
from camtrain.units import from_si

_MARKS = (0.0, 90.0, 180.0, 270.0)


@dataclass(frozen=True)
class OrbitSeries:
    """One orbit taken from a Result: label, load-diagram angle [rad], eps [-], direction [rad]."""

    label: str
    angle: np.ndarray
    eccentricity: np.ndarray
    position: np.ndarray


def orbit_series(result: Result) -> list[OrbitSeries]:
    """Every orbit in a run: each result component with an orbit (the bearings of a camshaft
    run), or the orbit of the result itself (a stand-alone bearing deck)."""
    out = []
    for name in [None, *result.components]:
        part = result.component(name)
        # a partially grooved crank bearing has both extremes (suffixes), each its own orbit
        for sfx in ("", "_ungrooved", "_grooved"):
            ecc, pos = f"eccentricity{sfx}", f"min_film_position{sfx}"
            if ecc not in part.columns or pos not in part.columns:
                continue
            col = part.columns[ecc]
            if not col.axis or col.axis not in result.columns:
                continue
            label = ("bearing" if name is None else name.replace("_", " ")) + sfx.replace("_",
                                                                                          " ")
            out.append(OrbitSeries(label, result[col.axis], part[ecc], part[pos]))
    return out


def _nearest(angle: np.ndarray, target_deg: float) -> int:
    d = np.angle(np.exp(1j * (angle - math.radians(target_deg))))  # wrapped difference
    return int(np.argmin(np.abs(d)))


def orbit_axes(ax, series: OrbitSeries) -> None:
    """Draw one polar orbit on a matplotlib polar axes."""
    pos = np.append(series.position, series.position[0])  # the orbit is closed
    eps = np.append(series.eccentricity, series.eccentricity[0])
    ax.plot(pos, eps, lw=1.2, color="C0")
    circle = np.linspace(0.0, 2.0 * math.pi, 181)
    ax.plot(circle, np.ones_like(circle), lw=0.8, color="0.4", ls="--")
    for j, deg in enumerate(_MARKS):
        i = _nearest(series.angle, deg)
        ax.plot(series.position[i], series.eccentricity[i], "o", ms=5, color=f"C{j + 1}",
                label=f"{deg:g} deg")
    i = int(np.argmax(series.eccentricity))
    ax.plot(series.position[i], series.eccentricity[i], "*", ms=11, color="k",
            label=f"max eps {series.eccentricity[i]:.3f} at "
                  f"{math.degrees(series.angle[i]):.0f} deg")
    ax.set_ylim(0.0, 1.0)
    ax.set_title(series.label, fontsize=10)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=7, frameon=False)


def orbit_figure(series: OrbitSeries, title: str = ""):
    """A matplotlib Figure with one polar orbit."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6.0, 4.5))
    ax = fig.add_subplot(projection="polar")
    orbit_axes(ax, series)
    if title:
        fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    return fig


def write_orbit_plots(result: Result, out_dir: Path, *, title: str = "",
                      fmt: str = "png") -> list[Path]:
    """One polar orbit plot per bearing, ``orbit_bearing_<i>.<fmt>``; returns the files."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    written = []
    for s in orbit_series(result):
        name = "orbit_" + s.label.replace(" ", "_") + f".{fmt}"
        fig = orbit_figure(s, title)
        fig.savefig(out_dir / name, dpi=110)
        written.append(out_dir / name)
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
