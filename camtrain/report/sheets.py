"""Plot sheets like Ball's GRAFIT pages (A4, header block, panels) and each panel on its own.

A sheet holds only the panels whose columns the run produced, so a lift-only or no-load run gets
clean, shorter sheets; a sheet with no panels at all is not written. Files: ``sheet_<name>.png``
and ``.pdf``, and ``panels/<panel>.png`` and ``.pdf``.
"""
from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from camtrain import __version__
from camtrain.report import profile
from camtrain.report.findings import Findings, find
from camtrain.report.header import header_rows, title_line
from camtrain.report.panels import PANELS, Ctx
from camtrain.report.style import A4_PORTRAIT, PANEL_SIZE, RC, pyplot
from camtrain.result import Result

#: name -> (heading, panels); "profile" is the cam drawn to scale
SHEETS = {
    "kinematics": ("Kinematics", ["lift", "velocity", "acceleration", "jerk", "eccentricity",
                                  "pressure_angle"]),
    "contact": ("Contact velocities, radii and film", ["velocities", "radii", "film_angle",
                                                       "film_position", "load", "hertz"]),
    "friction": ("Friction, torque and power", ["friction_coefficient", "friction_force",
                                                "torque", "power"]),
    "profile": ("Cam profile and film around it", ["profile"]),
}

#: progress(label, done, total) after each file set is written
Progress = Callable[[str, int, int], None]


def _ctx(result: Result) -> Ctx:
    return Ctx(np.degrees(result["cam_angle"]), find(result))


def _drawable(result: Result, ctx: Ctx, names: list[str]) -> list[str]:
    """Panels that can be drawn: try each on a scratch axes (cheap compared with saving)."""
    plt = pyplot()
    out = []
    fig = plt.figure()
    for name in names:
        ax = fig.add_subplot()
        ok = profile.can_draw(result) if name == "profile" else PANELS[name][1](ax, result, ctx)
        if ok:
            out.append(name)
        fig.delaxes(ax)
    plt.close(fig)
    return out


def _header(ax, deck, result: Result, heading: str, sha: str | None,
            title: str | None = None) -> None:
    """Title across the page; sheet name and provenance left; key inputs boxed right (Ball)."""
    ax.set_axis_off()
    ax.text(0.0, 1.0, title or title_line(deck), fontsize=11, fontweight="bold", va="top",
            transform=ax.transAxes)
    ax.text(0.0, 0.72, "CAM OPERATING CHARACTERISTICS", fontsize=7.5, color="#595959",
            va="top", transform=ax.transAxes)
    ax.text(0.0, 0.58, heading, fontsize=10, va="top", transform=ax.transAxes)
    foot = f"camtrain {__version__}" + (f"\ndeck sha256 {sha[:16]}" if sha else "")
    ax.text(0.0, 0.0, foot, fontsize=6.5, color="#7f7f7f", va="bottom", transform=ax.transAxes,
            linespacing=1.4)
    rows = header_rows(deck, result)
    if not rows:
        return
    width = max(len(label) for label, _ in rows)
    lines = [f"{label:<{width}} = {value}" for label, value in rows]
    if len(lines) > 1 and lines[-1].startswith("Frictional"):
        lines.insert(len(lines) - 1, "-" * (width + 10))
    half = (len(lines) + 1) // 2 if len(lines) > 8 else len(lines)
    cols = [lines[:half], lines[half:]] if half < len(lines) else [lines]
    x = 0.385 if len(cols) == 2 else 0.62
    for col in cols:
        ax.text(x, 0.72, "\n".join(col), family="DejaVu Sans Mono", fontsize=6.5, va="top",
                transform=ax.transAxes, linespacing=1.35,
                bbox={"boxstyle": "square,pad=0.5", "fc": "#f7f7f7", "ec": "#bfbfbf", "lw": 0.6})
        x += 0.315


#: height of the header band and the tallest row of panels on a sheet [in]
HEADER_IN = 1.45
MAX_ROW_IN = 4.3


def _sheet(result: Result, deck, name: str, ctx: Ctx, panels: list[str], sha: str | None,
           title: str | None = None):
    plt = pyplot()
    heading = SHEETS[name][0]
    fig = plt.figure(figsize=A4_PORTRAIT, layout="constrained")
    if name == "profile":
        gs = fig.add_gridspec(2, 1, height_ratios=[HEADER_IN, A4_PORTRAIT[1] - HEADER_IN])
        _header(fig.add_subplot(gs[0]), deck, result, heading, sha)
        ax = fig.add_subplot(gs[1])
        profile.draw(ax, result, ctx.findings, deck.cam.base_radius if deck else None)
        ax.set_title("Cam profile to scale, film thickness laid around it")
        return fig
    rows = (len(panels) + 1) // 2
    # ratios in inches: the header keeps its size and a short sheet keeps panels in proportion,
    # leaving the bottom of the page empty rather than stretching one row over it
    row_in = min((A4_PORTRAIT[1] - HEADER_IN) / rows, MAX_ROW_IN)
    spare = A4_PORTRAIT[1] - HEADER_IN - rows * row_in
    heights = [HEADER_IN] + [row_in] * rows + ([spare] if spare > 0.1 else [])
    gs = fig.add_gridspec(len(heights), 2, height_ratios=heights)
    _header(fig.add_subplot(gs[0, :]), deck, result, heading, sha, title)
    for i, pname in enumerate(panels):
        ax = fig.add_subplot(gs[1 + i // 2, i % 2])
        title, func = PANELS[pname]
        func(ax, result, ctx)
        ax.set_title(title)
    return fig


def _panel(result: Result, deck, pname: str, ctx: Ctx):
    plt = pyplot()
    square = pname == "profile"
    fig = plt.figure(figsize=(6.4, 6.4) if square else PANEL_SIZE, layout="constrained")
    ax = fig.add_subplot()
    if square:
        profile.draw(ax, result, ctx.findings, deck.cam.base_radius if deck else None)
        title = "Cam profile and film"
    else:
        title = PANELS[pname][0]
        PANELS[pname][1](ax, result, ctx)
    ax.set_title(title)
    fig.suptitle(title_line(deck), fontsize=7.5, color="#595959")
    return fig


def write_plots(result: Result, deck, out_dir: Path, *, single_panels: bool = True,
                formats=("png", "pdf"), sha: str | None = None,
                progress: Progress | None = None, dpi: int | None = None) -> list[Path]:
    """Draw every sheet (and every panel alone) that the result supports into ``out_dir``,
    and a polar orbit plot per journal bearing when the run has bearings."""
    from camtrain.report.bearing_plots import orbit_series, write_orbit_plots

    orbits: list[Path] = []
    if orbit_series(result):
        title = getattr(deck, "title", "") if deck is not None else ""
        for ext in formats:
            orbits += write_orbit_plots(result, out_dir, title=title, fmt=ext)
    if "cam_angle" not in result.columns:
        return orbits
    import matplotlib

    plt = pyplot()
    out_dir.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    with matplotlib.rc_context({**RC, **({"savefig.dpi": dpi} if dpi else {})}):
        ctx = _ctx(result)
        plan = {name: _drawable(result, ctx, panels) for name, (_, panels) in SHEETS.items()}
        jobs = [("sheet", name) for name, panels in plan.items() if panels]
        if single_panels:
            (out_dir / "panels").mkdir(exist_ok=True)
            jobs += [("panel", p) for panels in plan.values() for p in panels]
        for done, (kind, name) in enumerate(jobs, 1):
            if kind == "sheet":
                fig = _sheet(result, deck, name, ctx, plan[name], sha)
                written += _save(plt, fig, out_dir / f"sheet_{name}", formats)
            else:
                fig = _panel(result, deck, name, ctx)
                written += _save(plt, fig, out_dir / "panels" / name, formats)
            if progress:
                progress(f"{kind} {name}", done, len(jobs))
    return written + orbits


def kinematics_sheet(result: Result, deck, title: str, stem: Path,
                     formats=("png", "pdf")) -> list[Path]:
    """The kinematics sheet alone, under a given title and file stem (``camtrain lift``)."""
    import matplotlib

    plt = pyplot()
    with matplotlib.rc_context(RC):
        ctx = _ctx(result)
        panels = _drawable(result, ctx, SHEETS["kinematics"][1])
        fig = _sheet(result, deck, "kinematics", ctx, panels, None, title)
        stem.parent.mkdir(parents=True, exist_ok=True)
        return _save(plt, fig, stem, formats)


def _save(plt, fig, stem: Path, formats) -> list[Path]:
    engine = fig.get_layout_engine()
    if engine is not None:      # lay out once, not once per file format (it is the slow part)
        engine.execute(fig)
        fig.set_layout_engine("none")
    paths = []
    for ext in formats:
        path = stem.with_suffix(f".{ext}")
        fig.savefig(path, metadata={"Creator": f"camtrain {__version__}"} if ext == "pdf" else None)
        paths.append(path)
    plt.close(fig)
    return paths


def findings_of(result: Result) -> Findings:
    return find(result)
