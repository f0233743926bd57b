"""The sheets' canvas: its PNG writer is lossless (RGB for an opaque figure, RGBA with any
transparency) and carries the resolution, and its cached
text is laid out as matplotlib lays it out."""
from __future__ import annotations

import matplotlib
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image

from camtrain.report.canvas import figure, save_png
from camtrain.report.style import RC


def _drawn(fig):
    ax = fig.add_axes([0.15, 0.2, 0.8, 0.7])
    ax.plot(np.linspace(-180, 180, 50), np.sin(np.linspace(0, 7, 50)), color="#1f4e79")
    ax.set_xlabel("cam angle [deg]")
    ax.set_ylabel("λ = h_min/σ [-]")
    ax.set_title("Film")
    return ax


@pytest.mark.parametrize(("facecolor", "mode"), [("white", "RGB"), ("none", "RGBA")])
def test_png_is_the_canvas_pixel_for_pixel_at_the_sheet_dpi(tmp_path, facecolor, mode):
    with matplotlib.rc_context(RC):
        fig = figure((3.0, 2.0))
        fig.set_facecolor(facecolor)
        _drawn(fig)
        save_png(fig, tmp_path / "f.png", software="camtrain test")
        pixels = np.asarray(fig.canvas.buffer_rgba())
    img = Image.open(tmp_path / "f.png")
    assert img.mode == mode and img.size == (pixels.shape[1], pixels.shape[0])
    assert np.array_equal(np.asarray(img.convert("RGBA")), pixels)
    assert round(img.info["dpi"][0]) == RC["savefig.dpi"] == round(fig.dpi)
    assert img.info["Software"] == "camtrain test"


def test_cached_text_has_matplotlibs_extents_and_ink():
    """Every string measures as in matplotlib's own renderer and lands within a pixel of it."""
    with matplotlib.rc_context(RC):
        ours = figure((3.0, 2.0))
        theirs = Figure(figsize=(3.0, 2.0))
        FigureCanvasAgg(theirs)
        images = []
        for fig in (ours, theirs):
            ax = _drawn(fig)
            fig.canvas.draw()
            renderer = fig.canvas.get_renderer()
            texts = [ax.title, ax.xaxis.label, ax.yaxis.label, *ax.get_xticklabels()]
            images.append((np.asarray(fig.canvas.buffer_rgba())[..., :3].astype(int),
                           [t.get_window_extent(renderer).bounds for t in texts]))
    (a, boxes_a), (b, boxes_b) = images
    assert np.allclose(boxes_a, boxes_b)
    ink_a, ink_b = (255 - a).sum(), (255 - b).sum()
    assert abs(ink_a - ink_b) < 0.01 * ink_b


def test_this_matplotlib_has_the_internals_the_text_cache_uses():
    """The fast path is the one the sheets take here (and the one the tests above check)."""
    from camtrain.report import canvas

    assert canvas.CACHED_TEXT and isinstance(figure((1.0, 1.0)).canvas, canvas.Canvas)


def test_without_those_internals_figures_use_matplotlibs_own_canvas(tmp_path, monkeypatch):
    """A matplotlib that changed its internals: the fallback draws the same pixels as
    matplotlib's FigureCanvasAgg and writes them as the PNG."""
    from camtrain.report import canvas

    with pytest.MonkeyPatch.context() as changed:      # a renderer without _prepare_font
        changed.setattr(canvas, "RendererAgg", type("RendererAgg", (), {}))
        assert not canvas._internals_present()
    monkeypatch.setattr(canvas, "CACHED_TEXT", False)
    with matplotlib.rc_context(RC):
        fig = figure((3.0, 2.0))
        assert type(fig.canvas) is FigureCanvasAgg
        _drawn(fig)
        save_png(fig, tmp_path / "f.png")
        theirs = Figure(figsize=(3.0, 2.0))
        FigureCanvasAgg(theirs)
        _drawn(theirs)
        theirs.set_dpi(fig.dpi)
        theirs.canvas.draw()
        expected = np.asarray(theirs.canvas.buffer_rgba())
    assert np.array_equal(np.asarray(Image.open(tmp_path / "f.png").convert("RGBA")), expected)
