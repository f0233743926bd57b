"""The Agg canvas every camtrain figure is drawn on: no pyplot, and each string rasterised once.

A sheet repeats the same strings many times (the angle axis "−180 … 180" and its label under
every panel, units, legend entries). matplotlib from 3.11 on lays out and renders text glyph by
glyph in Python on every draw, a third of a sheet's drawing time. Here each distinct string
(text, font, dpi, antialiasing) is rendered by FreeType into a bitmap once per process and
blitted where it is drawn, placed to the whole pixel as matplotlib up to 3.10 placed its text
bitmaps. Mathematical text and anything unusual go through matplotlib's own path.

The cache leans on matplotlib internals (``RendererAgg._prepare_font`` and its
``_renderer.draw_text_image``, ``FigureCanvasAgg._lastKey``,
``fontManager._find_fonts_by_props``). :data:`CACHED_TEXT` checks once that they exist; on a
matplotlib without them every figure is drawn on matplotlib's own ``FigureCanvasAgg``: the
same sheets, only slower text (tests/report/test_canvas.py draws a sheet both ways).
"""
from __future__ import annotations

import math

from matplotlib.backends.backend_agg import FigureCanvasAgg, RendererAgg, get_hinting_flag
from matplotlib.figure import Figure

#: (string, font properties, dpi, antialiased) -> bitmap, its offsets and the string's extent
_STRINGS: dict[tuple, tuple] = {}
_MAX_STRINGS = 4096


#: (font properties, dpi) -> (ascent, descent, line gap) [px] of the font Text lays lines out by
_HEIGHTS: dict[tuple, tuple] = {}


class _Renderer(RendererAgg):
    def _get_font_height_metrics(self, prop):
        """matplotlib >= 3.11 asks the renderer for a font's line metrics before it reads the
        font's OS/2 or hhea table itself, on every layout of every Text: read them once."""
        key = (prop, self.dpi)
        hit = _HEIGHTS.get(key)
        if hit is None:
            from matplotlib.font_manager import fontManager, get_font

            font = get_font(fontManager._find_fonts_by_props(prop))
            hit = (None, None, None)
            for table_name, gap, ascent, descent in (
                    ("OS/2", "sTypoLineGap", "sTypoAscender", "sTypoDescender"),
                    ("hhea", "lineGap", "ascent", "descent")):
                table = font.get_sfnt_table(table_name)
                if table is not None:
                    scale = (prop.get_size_in_points() * self.dpi / 72
                             / font.get_sfnt_table("head")["unitsPerEm"])
                    hit = (table[ascent] * scale, -table[descent] * scale, table[gap] * scale)
                    break
            _HEIGHTS[(prop.copy(), self.dpi)] = hit
        return hit

    def get_text_width_height_descent(self, s, prop, ismath):
        if ismath:
            return super().get_text_width_height_descent(s, prop, ismath)
        return self._string(s, prop, True)[4]

    def draw_text(self, gc, x, y, s, prop, angle, ismath=False, mtext=None):
        if ismath or (mtext is not None and _shaped(mtext)):
            return super().draw_text(gc, x, y, s, prop, angle, ismath, mtext)
        image, xo, yo, descent, _ = self._string(s, prop, bool(gc.get_antialiased()))
        rad = math.radians(angle)
        # (x, y) is the baseline's start, y downwards; the bitmap's bottom goes a descent below
        xi = round(x + xo + descent * math.sin(rad))
        yi = round(y + yo + descent * math.cos(rad))
        self._renderer.draw_text_image(image, xi, yi + 1, angle, gc)

    def _string(self, s, prop, antialiased: bool) -> tuple:
        """(bitmap, x offset, y offset, descent, (width, height, descent)) of a string, laid
        out and rendered once: the layout that measures it also draws it."""
        key = (s, prop, self.dpi, antialiased)
        hit = _STRINGS.get(key)
        if hit is None:
            font = self._prepare_font(prop)
            font.set_text(s, 0.0, flags=get_hinting_flag())
            w, h = font.get_width_height()
            descent = font.get_descent() / 64.0
            font.draw_glyphs_to_bitmap(antialiased=antialiased)
            xo, yo = font.get_bitmap_offset()
            hit = (font.get_image().copy(), xo / 64.0, yo / 64.0, descent,
                   (w / 64.0, h / 64.0, descent))
            if len(_STRINGS) >= _MAX_STRINGS:
                _STRINGS.clear()
            _STRINGS[(s, prop.copy(), self.dpi, antialiased)] = hit   # a key nobody mutates
        return hit


def _shaped(mtext) -> bool:
    """Text that asks for font features or a language needs matplotlib's shaping path."""
    features = getattr(mtext, "get_fontfeatures", None)
    language = getattr(mtext, "get_language", None)
    return bool((features and features()) or (language and language()))


def _internals_present() -> bool:
    """True when the matplotlib internals the string cache uses exist."""
    try:
        from matplotlib.font_manager import fontManager

        return (callable(getattr(RendererAgg, "_prepare_font", None))
                and callable(getattr(fontManager, "_find_fonts_by_props", None))
                and hasattr(RendererAgg(1, 1, 72)._renderer, "draw_text_image")
                and hasattr(FigureCanvasAgg(Figure()), "_lastKey"))
    except Exception:  # noqa: BLE001 - any change of those internals means: do not use them
        return False


#: draw text through the string cache (False: matplotlib's own canvas, see the module doc)
CACHED_TEXT = _internals_present()


class Canvas(FigureCanvasAgg):
    """FigureCanvasAgg drawing with the string-caching renderer."""

    def get_renderer(self):
        w, h = self.get_width_height(physical=True)
        key = w, h, self.figure.dpi
        if self._lastKey != key:
            self.renderer = _Renderer(w, h, self.figure.dpi)
            self._lastKey = key
        return self.renderer


def figure(size) -> Figure:
    """A bare figure on the canvas (no pyplot figure manager: nothing to close, nothing kept)."""
    fig = Figure(figsize=size)
    (Canvas if CACHED_TEXT else FigureCanvasAgg)(fig)
    return fig


def wipe(fig: Figure) -> None:
    """Empty ``fig`` for the next sheet. Figure.clear() first clears every axes it is about to
    drop (building fresh axis and tick objects for each: a fifth of drawing a sheet)."""
    for ax in tuple(fig.axes):
        fig.delaxes(ax)
    fig.clear()


def save_png(fig: Figure, path, software: str = "") -> None:
    """Draw ``fig`` at rcParams["savefig.dpi"] and write it as a PNG with Pillow (which
    matplotlib itself writes PNGs with) at zlib's fastest level: lossless, ~10 % larger than
    Pillow's default level 6 and written in well under half its time (an A4 sheet at 150 dpi).
    A sheet without transparency (every sheet on its white page) is written as RGB: the same
    pixels, a quarter fewer bytes for Pillow to filter and compress (~50 against ~58 ms and
    ~200 against ~230 KiB a sheet)."""
    import matplotlib as mpl
    import numpy as np
    from PIL import Image, PngImagePlugin

    dpi = mpl.rcParams["savefig.dpi"]
    if dpi != "figure" and dpi != fig.dpi:
        fig.set_dpi(dpi)
    fig.canvas.draw()
    info = PngImagePlugin.PngInfo()
    if software:
        info.add_text("Software", software)
    rgba = np.asarray(fig.canvas.buffer_rgba())
    image = Image.frombuffer("RGBA", (rgba.shape[1], rgba.shape[0]), rgba, "raw", "RGBA", 0, 1)
    if rgba[..., 3].min() == 255:
        image = image.convert("RGB")
    image.save(path, format="png", compress_level=1, dpi=(fig.dpi, fig.dpi), pnginfo=info)


def save_sheet(fig: Figure, stem, formats) -> list:
    """Write ``fig`` as ``stem.<ext>`` for every format (PNG through :func:`save_png`, PDF with
    camtrain as its creator); the paths written."""
    from pathlib import Path

    from camtrain import __version__

    paths = []
    for ext in formats:
        path = Path(stem).with_suffix(f".{ext}")
        if ext == "png":
            save_png(fig, path, software=f"camtrain {__version__}")
        else:
            fig.savefig(path, metadata={"Creator": f"camtrain {__version__}"} if ext == "pdf"
                        else None)
        paths.append(path)
    return paths
