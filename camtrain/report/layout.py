"""Checks of a drawn figure's text layout: nothing outside the page, no title or legend over a
plot, no legend over the data, no two figure texts on top of each other.

``layout_problems(fig)`` draws the figure and measures every visible text in pixels; the sheet
test runs it on every sheet of every shipped deck, and ``fit_text`` shortens a line to the width
it has (titles that would run off the page).
"""
from __future__ import annotations

#: pixels of slack: antialiasing and the half-pixel placement of text bitmaps
SLACK = 1.5


def _boxes_overlap(a, b, slack: float = SLACK) -> bool:
    return (a.x0 < b.x1 - slack and b.x0 < a.x1 - slack
            and a.y0 < b.y1 - slack and b.y0 < a.y1 - slack)


def _inside(inner, outer, slack: float = SLACK) -> bool:
    return (inner.x0 >= outer.x0 - slack and inner.x1 <= outer.x1 + slack
            and inner.y0 >= outer.y0 - slack and inner.y1 <= outer.y1 + slack)


def _visible(artist) -> bool:
    return artist.get_visible() and (not hasattr(artist, "get_text") or artist.get_text().strip())


def _titles(ax) -> list:
    return [t for t in (ax.title, ax._left_title, ax._right_title) if _visible(t)]


def _axes_texts(ax) -> list:
    texts = _titles(ax) + [t for t in ax.texts if _visible(t)]
    for axis in ax._axis_map.values():
        if _visible(axis.label):
            texts.append(axis.label)
        texts += _tick_labels(axis)
    legend = ax.get_legend()
    if legend is not None and legend.get_visible():
        texts += [t for t in legend.get_texts() if _visible(t)]
    return texts


def _tick_labels(axis) -> list:
    """The tick labels an axis draws (those of ticks inside its view; matplotlib keeps labels
    of ticks outside it, never drawn)."""
    out = []
    for tick in axis._update_ticks():
        out += [t for t in (tick.label1, tick.label2) if _visible(t)]
    return out


def _name(text) -> str:
    s = text.get_text().replace("\n", " ")
    return repr(s if len(s) <= 40 else s[:37] + "...")


def layout_problems(fig, draw: bool = True) -> list[str]:
    """What is wrong with the layout of ``fig`` (empty when nothing is). ``draw=False`` for a
    figure just drawn (saved): its texts are measured where that drawing put them."""
    if not hasattr(fig.canvas, "get_renderer"):     # a bare Figure: give it an Agg canvas
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        FigureCanvasAgg(fig)
        draw = True
    if draw:
        fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    page = fig.bbox
    axes = [ax for ax in fig.axes if ax.get_visible()]
    problems: list[str] = []
    figure_texts = [t for t in fig.texts if _visible(t)]
    if fig._suptitle is not None and _visible(fig._suptitle) and fig._suptitle not in fig.texts:
        figure_texts.append(fig._suptitle)
    for text in figure_texts + [t for ax in axes for t in _axes_texts(ax)]:
        box = text.get_window_extent(renderer)
        if not _inside(box, page):
            problems.append(f"text {_name(text)} runs outside the figure")
    frames = [(ax, ax.get_window_extent(renderer)) for ax in axes]
    for text in figure_texts + [t for ax in axes for t in _titles(ax)]:
        box = text.get_window_extent(renderer)
        for ax, frame in frames:
            if _boxes_overlap(box, frame):
                problems.append(f"title {_name(text)} lies over a plot ({ax.get_label() or ax})")
                break
    ticks = [t for ax in axes for axis in ax._axis_map.values() for t in _tick_labels(axis)]
    tick_boxes = [(t, t.get_window_extent(renderer)) for t in ticks]
    for text in figure_texts + [t for ax in axes for t in _titles(ax)]:
        box = text.get_window_extent(renderer)
        for tick, tick_box in tick_boxes:
            if _boxes_overlap(box, tick_box):
                problems.append(f"title {_name(text)} covers tick label {_name(tick)}")
                break
    boxes = [(t, t.get_window_extent(renderer)) for t in figure_texts]
    for i, (a, box_a) in enumerate(boxes):
        for b, box_b in boxes[i + 1:]:
            if _boxes_overlap(box_a, box_b):
                problems.append(f"figure texts {_name(a)} and {_name(b)} overlap")
    for ax in axes:
        problems += _legend_problems(ax, frames, renderer)
    return problems


def _legend_problems(ax, frames, renderer) -> list[str]:
    """A legend stays off the other plots, off its own tick labels and off its own data."""
    legend = ax.get_legend()
    if legend is None or not legend.get_visible():
        return []
    box = legend.get_window_extent(renderer)
    out = []
    for other, frame in frames:
        if other is ax or other in _twins(ax):
            continue
        if _boxes_overlap(box, other.get_tightbbox(renderer) or frame):
            out.append(f"legend of {ax.get_title()!r} lies over another plot")
    for axis in ax._axis_map.values():
        for tick in _tick_labels(axis):
            if _boxes_overlap(box, tick.get_window_extent(renderer)):
                out.append(f"legend of {ax.get_title()!r} covers tick label {_name(tick)}")
                break
    if _covers_data(ax, box):
        out.append(f"legend of {ax.get_title()!r} lies over its data")
    return out


def _twins(ax) -> list:
    return [o for o in ax.get_shared_x_axes().get_siblings(ax) if o is not ax] + \
        list(ax.child_axes)


def _covers_data(ax, box) -> bool:
    """Whether any drawn point of a curve of ``ax`` (or of its twins) falls inside ``box``."""
    import numpy as np

    for owner in [ax, *_twins(ax)]:
        for line in owner.get_lines():
            if not line.get_visible() or line.get_label().startswith("_minor"):
                continue
            xy = np.column_stack(line.get_data()).astype(float)
            xy = xy[np.all(np.isfinite(xy), axis=1)]
            if len(xy) == 0:
                continue
            px = line.get_transform().transform(xy)
            inside = ((px[:, 0] > box.x0 + SLACK) & (px[:, 0] < box.x1 - SLACK)
                      & (px[:, 1] > box.y0 + SLACK) & (px[:, 1] < box.y1 - SLACK))
            if inside.any():
                return True
    return False


def fit_text(text: str, width_px: float, measure) -> str:
    """``text`` shortened at a word boundary (with an ellipsis) until ``measure(text)`` [px]
    fits ``width_px``; unchanged when it fits."""
    if measure(text) <= width_px:
        return text
    words = text.split(" ")
    while len(words) > 1:
        words.pop()
        candidate = " ".join(words).rstrip(",;:—-– ") + " …"
        if measure(candidate) <= width_px:
            return candidate
    return text
