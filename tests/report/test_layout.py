"""The layout check finds what it is for: text off the page, a legend over the data or over
another plot, a title over a plot; a clean figure passes. Titles are fitted to the page."""
from __future__ import annotations

import numpy as np

from camtrain.report.canvas import figure
from camtrain.report.layout import fit_text, layout_problems


def _plot(fig, rect):
    ax = fig.add_axes(rect)
    x = np.linspace(0.0, 1.0, 50)
    ax.plot(x, x, label="rising")
    return ax


def test_a_clean_figure_passes():
    fig = figure((6.0, 4.0))
    ax = _plot(fig, [0.15, 0.15, 0.6, 0.7])
    ax.set_title("a title")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0))
    assert layout_problems(fig) == []


def test_text_off_the_page_is_found():
    fig = figure((6.0, 4.0))
    _plot(fig, [0.15, 0.15, 0.7, 0.7])
    fig.text(0.6, 0.95, "a title far too long for the right half of this page, running off it")
    assert any("outside the figure" in p for p in layout_problems(fig))


def test_a_legend_over_the_data_is_found():
    fig = figure((6.0, 4.0))
    ax = _plot(fig, [0.15, 0.15, 0.7, 0.7])
    ax.legend(loc="center")
    assert any("over its data" in p for p in layout_problems(fig))


def test_a_title_over_another_plot_is_found():
    fig = figure((6.0, 4.0))
    _plot(fig, [0.15, 0.1, 0.7, 0.4])
    upper = _plot(fig, [0.15, 0.52, 0.7, 0.4])
    upper.set_title("upper", y=-0.3)
    assert any("lies over a plot" in p for p in layout_problems(fig))


def test_a_long_title_is_shortened_at_a_word():
    assert fit_text("short", 100.0, len) == "short"
    fitted = fit_text("one two three four five", 14.0, len)
    assert fitted == "one two …" and len(fitted) <= 14


def test_a_sheet_with_a_very_long_title_keeps_it_on_the_page():
    import matplotlib

    from camtrain.report.page import Page
    from camtrain.report.sheets import _ctx, _sheet
    from camtrain.report.style import A4_PORTRAIT, RC
    from tests.report.conftest import synthetic

    title = "A valve train with a title " + "that goes on and on " * 8 + "— 2500 rpm camshaft"
    with matplotlib.rc_context(RC):
        page = Page(A4_PORTRAIT)
        result = synthetic(120)
        assert _sheet(page, result, None, "kinematics", _ctx(result), "ab" * 32, title)
        assert layout_problems(page.fig) == []
    shown = [t.get_text() for t in page.fig.texts if "title" in t.get_text()]
    assert shown and shown[0].endswith("…")
