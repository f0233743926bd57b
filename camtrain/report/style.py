"""One look for every plot camtrain draws: fonts, colours, line weights, page size.

Sheets are A4 portrait so they print like Ball's GRAFIT pages; single panels are a quarter page.
matplotlib is imported lazily (Agg backend) so the command line starts fast.
"""
from __future__ import annotations

A4_PORTRAIT = (8.27, 11.69)    # inches
PANEL_SIZE = (6.4, 3.6)
DPI = 150

#: colour per role, so V_c is the same blue on every sheet of every deck
COLORS = {
    "main": "#1f4e79", "second": "#c0504d", "third": "#4f8a3c", "fourth": "#8064a2",
    "grey": "#7f7f7f", "boundary": "#f4c7a1", "no_contact": "#e6b8b7", "clearance": "#ececec",
    "film": "#5b9bd5",
    "zero": "#c00000", "mean": "#404040",
}

RC = {
    "font.family": "DejaVu Sans",
    "font.size": 8.5,
    "axes.titlesize": 9.5,
    "axes.titleweight": "bold",
    # titles at the top edge: no panel has labels above it, and the automatic placement
    # measures every axes' tight box on each draw (an eighth of a sheet's drawing time)
    "axes.titley": 1.0,
    "axes.labelsize": 8.5,
    "axes.linewidth": 0.8,
    "axes.grid": True,
    "axes.axisbelow": True,
    "grid.color": "#d9d9d9",
    "grid.linewidth": 0.5,
    # ticks inward on all four sides, as they are born (setting them on every panel re-makes
    # the marks of every existing tick); a panel with a second y scale drops its right ones
    "xtick.direction": "in",
    "ytick.direction": "in",
    "xtick.top": True,
    "ytick.right": True,
    "xtick.labelsize": 7.5,
    "ytick.labelsize": 7.5,
    "legend.fontsize": 7.0,
    "legend.frameon": True,
    "legend.framealpha": 0.85,
    "legend.edgecolor": "#bfbfbf",
    "lines.linewidth": 1.2,
    # every curve names its colour; a one-entry cycle is rebuilt cheaply on each new axes
    "axes.prop_cycle": "cycler('color', ['1f4e79'])",
    "figure.dpi": DPI,
    "savefig.dpi": DPI,
    "pdf.fonttype": 3,           # subset Type 3 fonts: much faster to write than Type 42
    "svg.fonttype": "none",
    "axes.formatter.useoffset": False,
    "axes.formatter.limits": (-4, 5),
}

ANGLE_LABEL = "cam angle from maximum lift [deg]"


def pyplot():
    """matplotlib.pyplot with the non-interactive backend (safe on servers and in CI)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


#: the cam-angle axis: labelled ticks every 60 deg, unlabelled ones every 15 deg between them
ANGLE_MAJOR = tuple(range(-180, 181, 60))
ANGLE_MINOR = tuple(a for a in range(-165, 180, 15) if a % 60)


def angle_axis(ax) -> None:
    """The cam-angle axis every cycle plot shares: −180…180 deg, nose at 0."""
    from matplotlib.ticker import FixedLocator

    ax.set_xlim(-180.0, 180.0)
    ax.xaxis.set_major_locator(FixedLocator(ANGLE_MAJOR))
    minor_ticks(ax, ANGLE_MINOR)
    ax.set_xlabel(ANGLE_LABEL)


def minor_ticks(ax, positions) -> None:
    """Unlabelled x ticks at ``positions``, inward at the bottom and the top, drawn as two
    marker lines (the marks matplotlib's own ticks are made of): a Tick object per position
    costs five artists each, and these are a third of all the ticks on a sheet."""
    import matplotlib as mpl
    from matplotlib.lines import TICKDOWN, TICKUP, Line2D

    x = list(positions)
    style = {"ls": "none", "ms": mpl.rcParams["xtick.minor.size"],
             "mew": mpl.rcParams["xtick.minor.width"], "color": mpl.rcParams["xtick.color"],
             "transform": ax.get_xaxis_transform(), "clip_on": False, "zorder": 2.5,
             "label": "_minor ticks"}
    for y, marker in ((0.0, TICKUP), (1.0, TICKDOWN)):   # add_line: none of plot()'s parsing
        ax.add_line(Line2D(x, [y] * len(x), marker=marker, **style))


def finish_axes(ax, legend: bool = False, handles=None) -> None:
    if _has_twin(ax):
        ax.tick_params(which="both", right=False)
    handles = handles or ax.get_legend_handles_labels()
    if legend and handles[0]:
        # two columns only when two labels fit side by side within the panel
        ncol = 2 if len(handles[0]) > 2 and max(map(len, handles[1])) <= 24 else 1
        rows = -(-len(handles[0]) // ncol)
        headroom(ax, 0.32 if rows <= 2 else 0.14 * rows)
        ax.legend(*handles, loc="upper center", ncol=ncol, columnspacing=1.0, handlelength=1.8)


def headroom(ax, fraction: float = 0.32) -> None:
    """Room above the curves for a legend, so it never hides data (measured on the axis's
    own scale, so a log or symlog axis gets the same share of the panel)."""
    lo, hi = ax.get_ylim()
    t = ax.yaxis.get_transform()
    a, b = t.transform([lo, hi])
    ax.set_ylim(lo, float(t.inverted().transform([b + fraction * (b - a)])[0]))


def _has_twin(ax) -> bool:
    """A second y scale on the right (a twin sharing x, or a secondary axis): the host's own
    right-hand ticks would stand among its ticks."""
    return bool(ax.child_axes) or len(ax.get_shared_x_axes().get_siblings(ax)) > 1
