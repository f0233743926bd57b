"""Plot sheets like Ball's GRAFIT pages (A4, header block, panels) and each panel on its own.

A sheet holds only the panels the effects that ran declare (EffectSpec.panels) and that have
something to draw, so a lift-only or no-load run gets clean, shorter sheets; a sheet with no
panels at all is not written. Files: ``sheet_<name>.png``
and ``.pdf``, and ``panels/<panel>.png`` and ``.pdf``.
"""
from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from camtrain.catalogue import declared_panels
from camtrain.report import profile
from camtrain.report.findings import Findings, find
from camtrain.report.header import title_line
from camtrain.report.page import Page
from camtrain.report.panels import PANELS as CYCLE_PANELS
from camtrain.report.panels import Ctx
from camtrain.report.panels_adjuster import ADJUSTER_PANELS
from camtrain.report.panels_ehl import EHL_PANELS
from camtrain.report.panels_shaft import SHAFT_PANELS
from camtrain.report.sheet_header import (
    GAP_X_IN,
    HEADER_IN,
    LEFT_IN,
    MAX_ROW_IN,
    PAGE_IN,
    RIGHT_IN,
    TITLE_IN,
    XLABEL_IN,
    _frac,
    fit_title,
    header,
)
from camtrain.report.style import A4_PORTRAIT, PANEL_SIZE, RC
from camtrain.result import Result

PANELS = {**CYCLE_PANELS, **SHAFT_PANELS, **EHL_PANELS, **ADJUSTER_PANELS}

#: name -> (heading, panels); "profile" is the cam drawn to scale
SHEETS = {
    "kinematics": ("Kinematics", ["lift", "velocity", "acceleration", "jerk", "eccentricity",
                                  "pressure_angle"]),
    "contact": ("Contact velocities, radii and film", ["velocities", "radii", "film_angle",
                                                       "film_position", "load", "hertz"]),
    "friction": ("Friction, torque and power", ["friction_coefficient", "friction_force",
                                                "torque", "power"]),
    "transient_film": ("Transient film over the cycle", ["transient_film", "film_pressures"]),
    "elastic_film": ("Elastic film over the cycle", ["elastic_films", "film_map",
                                                     "pressure_over_hertz"]),
    "profile": ("Cam profile and film around it", ["profile"]),
    "dynamics": ("Valve-train dynamics", [
        "dynamic_load", "valve_motion", "valve_acceleration", "spring_forces",
        "roller_spin"]),
    "lash_adjuster": ("Hydraulic lash adjuster", [
        "adjuster_pressure", "adjuster_extension", "adjuster_lift_loss", "check_flow",
        "check_lift"]),
    "camshaft": ("Elastic camshaft: bearing loads, orders, lobes", [
        "shaft_reactions", "shaft_orders", "lobe_loads", "lobe_motion", "lobe_twist"]),
}

#: progress(label, done, total) after each file set is written
Progress = Callable[[str, int, int], None]


def _ctx(result: Result) -> Ctx:
    return Ctx(np.degrees(result["cam_angle"]), find(result))


def _panel_rects(count: int, size=A4_PORTRAIT) -> list[list[float]]:
    """Axes rectangles of ``count`` panels under the header band: two columns for five or
    more, one column of wide panels for three or four (so they fill the page rather than
    leave its bottom third empty), rows of at most MAX_ROW_IN."""
    columns = 2 if count > 4 or count < 3 else 1
    rows = max(-(-count // columns), 1)
    top = size[1] - PAGE_IN - HEADER_IN
    row_in = min((top - PAGE_IN) / rows, MAX_ROW_IN)
    width = (size[0] - 2 * PAGE_IN - LEFT_IN - RIGHT_IN - (columns - 1) * GAP_X_IN) / columns
    rects = []
    for i in range(count):
        r, c = divmod(i, columns)
        x0 = PAGE_IN + LEFT_IN + c * (width + GAP_X_IN)
        y0 = top - (r + 1) * row_in + XLABEL_IN
        rects.append(_frac(x0, y0, width, row_in - XLABEL_IN - TITLE_IN, size))
    return rects


def _sheet(page: Page, result: Result, deck, name: str, ctx: Ctx, sha: str | None,
           title: str | None = None) -> int:
    """Draw sheet ``name`` on the A4 ``page``; the number of panels drawn.

    Each panel is drawn into the page's next panel axes and given back if it has nothing to
    show; the survivors are then placed on a fixed grid (no layout solver: the page is always
    the same A4 frame)."""
    page.new_sheet()
    heading = SHEETS[name][0]
    size = page.size
    header(page.fig, _frac(PAGE_IN, size[1] - PAGE_IN - HEADER_IN, size[0] - 2 * PAGE_IN,
                            HEADER_IN - 0.1, size), deck, result, heading, sha, title)
    declared = declared_panels(result.plan)   # the panels the effects that ran feed
    if name == "profile":
        if "profile" not in declared:
            return 0
        side = size[0] - 2 * PAGE_IN - LEFT_IN - RIGHT_IN
        ax = page.panel()
        ax.set_position(_frac(PAGE_IN + LEFT_IN, size[1] - PAGE_IN - HEADER_IN - TITLE_IN - side,
                              side, side, size))
        profile.draw(ax, result, ctx.findings, deck.cam.base_radius if deck else None)
        ax.set_title("Cam profile to scale, film thickness laid around it")
        return 1
    drawn = []
    for pname in (p for p in SHEETS[name][1] if p in declared):
        ax = page.panel()
        panel_title, func = PANELS[pname]
        if func(ax, result, ctx):
            ax.set_title(panel_title)
            drawn.append(ax)
        else:   # nothing to show: the axes (and any twin the panel made) go back
            page.give_back()
    for ax, rect in zip(drawn, _panel_rects(len(drawn), size), strict=True):
        ax.set_position(rect)   # twin axes follow their host
    return len(drawn)


def _panel(fig, result: Result, deck, pname: str, ctx: Ctx) -> bool:
    """One panel alone on ``fig`` (PANEL_SIZE, or square for the profile)."""
    square = pname == "profile"
    w, h = fig.get_size_inches()
    bottom = 1.1 if square else 0.55      # the profile's legend goes under its drawing
    ax = fig.add_axes(_frac(0.8, bottom, w - 1.5, h - bottom - 0.5, (w, h)))
    if square:
        ok = profile.draw(ax, result, ctx.findings, deck.cam.base_radius if deck else None)
        title = "Cam profile and film"
    else:
        title = PANELS[pname][0]
        ok = PANELS[pname][1](ax, result, ctx)
    ax.set_title(title)
    head = fig.suptitle(title_line(deck), fontsize=7.5, color="#595959", y=0.995)
    fit_title(head, 0.96 * fig.bbox.width, deck, sizes=(7.5, 7.0, 6.5))
    return bool(ok)


def _figure(size):
    """A bare Agg figure (no pyplot figure manager: nothing to close, nothing kept)."""
    from camtrain.report.canvas import figure

    return figure(size)


def _orbits(result: Result, out_dir: Path, *, deck=None, sha: str | None = None,
            formats=("png",)) -> list[Path]:
    """Journal orbits: one A4 sheet of them all, and one plot per bearing (none without
    orbits: a Petroff-only run)."""
    from camtrain.report.bearing_plots import orbit_series, orbit_sheets, write_orbit_plots

    if not orbit_series(result):
        return []
    written = orbit_sheets(result, out_dir, deck=deck, sha=sha, formats=formats)
    title = getattr(deck, "title", "") if deck is not None else ""
    for ext in formats:
        written += write_orbit_plots(result, out_dir, title=title, fmt=ext, sha=sha, deck=deck)
    return written


#: the sheets that are not cycle panels: name an effect declares (EffectSpec.sheets) ->
#: "module:function" drawing it, ``draw(result, out_dir, deck=, sha=, formats=) -> [Path]``
#: (empty when the run has nothing for it)
OTHER_SHEETS = {
    "orbits": "camtrain.report.sheets:_orbits",
    "lobes": "camtrain.report.panels_shaft:lobe_sheet",
    "engine_loads": "camtrain.report.engine_plots:load_sheet",
    "piston": "camtrain.report.piston_plots:piston_sheet",
    "correlations": "camtrain.report.correlation_plots:correlation_sheet",
    "roller": "camtrain.report.roller_plots:roller_sheet",
}


def declared_sheets(result: Result) -> list[str]:
    """The sheets the effects that ran declare, in plan order (EffectSpec.sheets)."""
    from camtrain.catalogue import declared_effects

    names = dict.fromkeys(n for spec in declared_effects(result.plan) for n in spec.sheets)
    if result.plan is None:   # a lift-only run: the cycle sheets, none that needs an effect's product
        return [n for n in names if n not in OTHER_SHEETS]
    return list(names)


def _other_sheets(result: Result, wanted: list[str], out_dir: Path, formats, sha: str | None,
                  deck, progress: Progress | None) -> list[Path]:
    """The declared sheets that are not cycle panels, each in the house style: journal orbits,
    the lobes of a long camshaft, an engine's load diagrams, its piston and FLAME sheet."""
    import importlib

    written: list[Path] = []
    for name in wanted:
        if name not in OTHER_SHEETS:   # a cycle sheet (SHEETS)
            continue
        module, _, func = OTHER_SHEETS[name].partition(":")
        files = getattr(importlib.import_module(module), func)(
            result, out_dir, deck=deck, sha=sha, formats=formats)
        if files and progress:
            progress(f"sheet {name}", 1, 1)
        written += files
    return written


#: --plots: which files a run draws (sheet formats, and whether every panel also goes alone)
PLOT_CHOICES = {"sheets": (("png",), False), "pdf": (("png", "pdf"), False),
                "all": (("png", "pdf"), True), "none": ((), False)}


def write_plots(result: Result, deck, out_dir: Path, *, single_panels: bool = True,
                formats=("png", "pdf"), sha: str | None = None,
                progress: Progress | None = None, dpi: int | None = None) -> list[Path]:
    """Draw every sheet (and every panel alone) that the result supports into ``out_dir``,
    and a polar orbit plot per journal bearing when the run has bearings.

    The sheets are those the effects that ran declare (EffectSpec.sheets). One A4 figure is
    drawn on, saved and cleared for every sheet in turn."""
    wanted = declared_sheets(result)
    orbits = _other_sheets(result, wanted, out_dir, formats, sha, deck, progress)
    cycle = [name for name in SHEETS if name in wanted]
    if not cycle or not result.axes:   # an empty result (no plan, no grid) has no cycle
        return orbits
    import matplotlib

    from camtrain.report.canvas import wipe

    out_dir.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    with matplotlib.rc_context({**RC, **({"savefig.dpi": dpi} if dpi else {})}):
        ctx = _ctx(result)
        declared = declared_panels(result.plan)
        page = Page(A4_PORTRAIT)
        panels = [(sheet, p) for sheet in cycle for p in SHEETS[sheet][1]]
        total = len(cycle) + (len(panels) if single_panels else 0)
        done, drawn = 0, set()
        for name in cycle:
            if _sheet(page, result, deck, name, ctx, sha):
                written += _save(page.fig, out_dir / f"sheet_{name}", formats)
                drawn.add(name)
            done += 1
            if progress:   # name only a sheet that was drawn (a deck without a shaft has none)
                progress(f"sheet {name}" if name in drawn else "sheets", done, total)
        if single_panels:
            (out_dir / "panels").mkdir(exist_ok=True)
            panel_fig, square_fig = _figure(PANEL_SIZE), _figure((6.4, 6.4))
            for sheet, pname in panels:
                f = square_fig if pname == "profile" else panel_fig
                wipe(f)
                if sheet in drawn and pname in declared and _panel(f, result, deck, pname, ctx):
                    written += _save(f, out_dir / "panels" / pname, formats)
                done += 1
                if progress:
                    progress(f"panel {pname}" if sheet in drawn else "panels", done, total)
    return written + orbits


def kinematics_sheet(result: Result, deck, title: str, stem: Path,
                     formats=("png", "pdf")) -> list[Path]:
    """The kinematics sheet alone, under a given title and file stem (``camtrain lift``)."""
    import matplotlib

    with matplotlib.rc_context(RC):
        page = Page(A4_PORTRAIT)
        _sheet(page, result, deck, "kinematics", _ctx(result), None, title)
        stem.parent.mkdir(parents=True, exist_ok=True)
        return _save(page.fig, stem, formats)


def _save(fig, stem: Path, formats) -> list[Path]:
    from camtrain.report.canvas import save_sheet

    return save_sheet(fig, stem, formats)


def findings_of(result: Result) -> Findings:
    return find(result)
