"""One A4 page whose panel axes are kept from sheet to sheet.

Building an axes builds its two axis objects and their ticks (five artists per tick); on a page
of six panels that was a third of drawing a sheet. The page keeps a pool of panel axes: the
next sheet takes them back emptied of its curves, shading, legend, labels and scales, and keeps
their axis and tick objects. The header is figure text, not an axes.
"""
from __future__ import annotations


class Page:
    def __init__(self, size):
        from camtrain.report.canvas import figure

        self.size = size
        self.fig = figure(size)
        self._pool: list = []
        self._used = 0

    def new_sheet(self) -> None:
        """Empty and hide the panels of the previous sheet and drop its figure text."""
        for ax in self._pool[:self._used]:
            _empty(ax)
            ax.set_visible(False)
        for text in tuple(self.fig.texts):
            text.remove()
        self._used = 0

    def panel(self):
        """The next empty, visible panel axes (positioned later with set_position)."""
        if self._used == len(self._pool):
            self._pool.append(self.fig.add_axes([0.0, 0.0, 0.1, 0.1]))
        ax = self._pool[self._used]
        ax.set_visible(True)
        self._used += 1
        return ax

    def give_back(self) -> None:
        """Return the last panel taken (its panel had nothing to show)."""
        self._used -= 1
        ax = self._pool[self._used]
        _empty(ax)
        ax.set_visible(False)


def _empty(ax) -> None:
    """What a fresh axes would be for a panel: no artists, twins, legend, labels; linear
    scales with their default ticks; autoscaling on; free aspect; ticks on all four sides
    (style.RC)."""
    fig = ax.figure
    twins = [other for other in ax._twinned_axes.get_siblings(ax) if other is not ax]
    if twins or ax.child_axes:                  # a second y scale took the right-hand side
        for child in tuple(ax.child_axes):
            child.remove()
        for other in twins:
            fig.delaxes(other)
        ax.tick_params(which="both", right=True)
    for container in tuple(ax.containers):      # bars: their patches and the legend entry
        container.remove()
    for artist in (*ax.lines, *ax.patches, *ax.collections, *ax.texts, *ax.images,
                   *ax.artists, *ax.tables):
        artist.remove()
    if ax.legend_ is not None:
        ax.legend_.remove()
    ax.set_title("")
    ax.set_xlabel("")
    ax.set_ylabel("")
    ax.set_xscale("linear")                     # default locators and formatters again
    ax.set_yscale("linear")
    ax.set_aspect("auto")
    ax.set_adjustable("box")
    ax.ignore_existing_data_limits = True
    ax.relim()
    ax.autoscale(True)
