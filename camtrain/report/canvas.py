"""The Agg canvas every camtrain figure is drawn on: no pyplot, and each string rasterised once.

A sheet repeats the same strings many times (the angle axis "−180 … 180" and its label under
every panel, units, legend entries). matplotlib from 3.11 on lays out and renders text glyph by
glyph in Python on every draw, a third of a sheet's drawing time. Here each distinct string
(text, font, dpi, antialiasing) is rendered by FreeType into a bitmap once per process and
blitted where it is drawn, placed to the whole pixel as matplotlib up to 3.10 placed its text
bitmaps. Mathematical text and anything unusual go through matplotlib's own path.
"""
from __future__ import annotations

import math

from matplotlib.backends.backend_agg import FigureCanvasAgg, RendererAgg, get_hinting_flag
from matplotlib.figure import Figure

#: (string, font properties, dpi, antialiased) -> (alpha bitmap, x offset, y offset, descent)
_STRINGS: dict[tuple, tuple] = {}
_MAX_STRINGS = 4096


class _Renderer(RendererAgg):
    def draw_text(self, gc, x, y, s, prop, angle, ismath=False, mtext=None):
        if ismath or (mtext is not None and _shaped(mtext)):
            return super().draw_text(gc, x, y, s, prop, angle, ismath, mtext)
        antialiased = bool(gc.get_antialiased())
        key = (s, prop, self.dpi, antialiased)
        hit = _STRINGS.get(key)
        if hit is None:
            font = self._prepare_font(prop)
            font.set_text(s, 0.0, flags=get_hinting_flag())
            font.draw_glyphs_to_bitmap(antialiased=antialiased)
            xo, yo = font.get_bitmap_offset()
            hit = (font.get_image().copy(), xo / 64.0, yo / 64.0, font.get_descent() / 64.0)
            if len(_STRINGS) >= _MAX_STRINGS:
                _STRINGS.clear()
            _STRINGS[(s, prop.copy(), self.dpi, antialiased)] = hit    # a key nobody mutates
        image, xo, yo, descent = hit
        rad = math.radians(angle)
        # (x, y) is the baseline's start, y downwards; the bitmap's bottom goes a descent below
        xi = round(x + xo + descent * math.sin(rad))
        yi = round(y + yo + descent * math.cos(rad))
        self._renderer.draw_text_image(image, xi, yi + 1, angle, gc)


def _shaped(mtext) -> bool:
    """Text that asks for font features or a language needs matplotlib's shaping path."""
    features = getattr(mtext, "get_fontfeatures", None)
    language = getattr(mtext, "get_language", None)
    return bool((features and features()) or (language and language()))


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
    Canvas(fig)
    return fig
