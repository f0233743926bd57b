"""An A4 page in the house style for the sheets that are not cycle panels (engine load polars,
journal orbits, the piston and FLAME sheet): the same header band as the valve-train sheets
(title, deck kind, sheet name, version, deck hash, key inputs) and a grid of plots below it."""
from __future__ import annotations

from contextlib import contextmanager

from camtrain.report.sheet_header import HEADER_IN, PAGE_IN, _frac, header
from camtrain.report.style import A4_PORTRAIT, RC

#: room [in] around the grid below the header: tick labels and axis labels left and below,
#: titles above
GRID_LEFT_IN, GRID_RIGHT_IN, GRID_TOP_IN, GRID_BOTTOM_IN = 0.75, 0.3, 0.35, 0.5


@contextmanager
def house_page(deck, result, heading: str, sha: str | None, size=A4_PORTRAIT):
    """Yield an A4 figure with the header band drawn, inside the house style's rc settings."""
    import matplotlib

    from camtrain.report.canvas import figure

    with matplotlib.rc_context(RC):
        fig = figure(size)
        header(fig, _frac(PAGE_IN, size[1] - PAGE_IN - HEADER_IN, size[0] - 2 * PAGE_IN,
                          HEADER_IN - 0.1, size), deck, result, heading, sha)
        yield fig


def grid(fig, rows: int, columns: int, *, bottom_in: float = 0.0, left_in: float = GRID_LEFT_IN,
         right_in: float = GRID_RIGHT_IN, **kw):
    """A GridSpec filling the page below the header (and above ``bottom_in`` inches kept free
    for a note at the foot of the page; ``right_in`` for legends beside the plots)."""
    w, h = fig.get_size_inches()
    top = h - PAGE_IN - HEADER_IN - GRID_TOP_IN
    return fig.add_gridspec(rows, columns, left=left_in / w, right=1 - right_in / w,
                            top=top / h, bottom=(PAGE_IN + GRID_BOTTOM_IN + bottom_in) / h, **kw)


#: room [in] right of the plots for a legend beside them
LEGEND_RIGHT_IN = 1.75


def legend_beside(ax, **kw) -> None:
    """The legend right of the plot (in the page's LEGEND_RIGHT_IN), off the data."""
    handles, labels = ax.get_legend_handles_labels()
    if handles:
        ax.legend(handles, labels, loc="upper left", bbox_to_anchor=(1.02, 1.0),
                  borderaxespad=0.0, frameon=False, **kw)


def legend_above(ax, ncol: int = 4, **kw) -> None:
    """The legend in a band above the plot, off the data and off the ticks."""
    handles, labels = ax.get_legend_handles_labels()
    if handles:
        ax.legend(handles, labels, loc="lower left", bbox_to_anchor=(0.0, 1.01, 1.0, 0.1),
                  ncol=min(ncol, len(handles)), mode="expand", borderaxespad=0.0,
                  frameon=False, **kw)


def foot_note(fig, text: str) -> None:
    """A note at the foot of the page (the frame and conventions of its plots)."""
    w, _ = fig.get_size_inches()
    fig.text(PAGE_IN / w + 0.01, 0.012, text, fontsize=6.5, color="#404040", va="bottom",
             wrap=False)
