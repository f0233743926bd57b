"""The header band of every A4 sheet (Ball's GRAFIT pages): the title across the page, the deck
kind's heading, the sheet's name, camtrain's version and the deck's hash, and the key inputs
boxed on the right; and the page's fixed margins. Titles are fitted to the page."""
from __future__ import annotations

from camtrain import __version__
from camtrain.report.header import header_rows, report_heading, title_line
from camtrain.result import Result

#: height of the header band and the tallest row of panels on a sheet [in]
HEADER_IN = 1.45
MAX_ROW_IN = 4.3
#: fixed margins of a sheet [in]: page edges, room for titles above and tick labels and axis
#: labels around each panel (a twin axis on the right of a panel needs the gap between columns)
PAGE_IN = 0.1
LEFT_IN, RIGHT_IN = 0.62, 0.45
GAP_X_IN = 0.95
TITLE_IN, XLABEL_IN = 0.28, 0.42


def _frac(x0: float, y0: float, w: float, h: float, size) -> list[float]:
    """A rectangle in inches from the bottom left as figure fractions."""
    return [x0 / size[0], y0 / size[1], w / size[0], h / size[1]]


def header(fig, rect, deck, result: Result, heading: str, sha: str | None,
           title: str | None = None) -> None:
    """Title across the page; the deck kind's heading, sheet name and provenance left; key
    inputs boxed right (Ball). Figure text placed in the header band ``rect`` (figure
    fractions), not an axes. A title too long for the page is set smaller, then shortened; a
    sheet name too long for the room left of the boxes is wrapped."""
    from matplotlib.transforms import Bbox, BboxTransformTo, TransformedBbox

    band = BboxTransformTo(TransformedBbox(Bbox.from_bounds(*rect), fig.transFigure))

    def text(x, y, s, **kw):
        return fig.text(x, y, s, transform=band, **kw)

    rows = header_rows(deck, result)
    width = max((len(label) for label, _ in rows), default=0)
    lines = [f"{label:<{width}} = {value}" for label, value in rows]
    columns = 2 if len(lines) > 8 else 1
    boxes_x = 0.385 if columns == 2 else 0.62
    band_px = rect[2] * fig.bbox.width
    fit_title(text(0.0, 1.0, title or title_line(deck), fontsize=11, fontweight="bold",
                   va="top"), band_px, deck if title is None else None)
    text(0.0, 0.72, report_heading(deck), fontsize=7.5, color="#595959", va="top")
    wrap_text(text(0.0, 0.58, heading, fontsize=10, va="top"), (boxes_x - 0.02) * band_px)
    foot = f"camtrain {__version__}" + (f"\ndeck sha256 {sha[:16]}" if sha else "")
    text(0.0, 0.0, foot, fontsize=6.5, color="#7f7f7f", va="bottom", linespacing=1.4)
    if not rows:
        return
    if len(lines) > 1 and lines[-1].startswith("Frictional"):
        lines.insert(len(lines) - 1, "-" * (width + 10))
    half = (len(lines) + 1) // 2 if columns == 2 else len(lines)
    cols = [lines[:half], lines[half:]] if half < len(lines) else [lines]
    x = boxes_x
    for k, col in enumerate(cols):
        room = ((1.0 if k == len(cols) - 1 else x + 0.3) - x) * band_px - 6.0
        box = text(x, 0.72, "\n".join(col), family="DejaVu Sans Mono", fontsize=6.5, va="top",
                   linespacing=1.35,
                   bbox={"boxstyle": "square,pad=0.5", "fc": "#f7f7f7", "ec": "#bfbfbf",
                         "lw": 0.6})
        _fit_box(box, col, room)
        x += 0.315


def _fit_box(box, lines: list[str], room_px: float) -> None:
    """A box of input rows within ``room_px``: a smaller font first, then the longest rows cut
    with an ellipsis (report.txt holds them whole)."""
    for size in (6.5, 6.0, 5.5):
        box.set_fontsize(size)
        if _width(box) <= room_px:
            return
    per_char = _width(box) / max(len(line) for line in lines)
    keep = max(int(room_px / per_char) - 1, 10)
    box.set_text("\n".join(line if len(line) <= keep else line[:keep - 1] + "…"
                           for line in lines))


def _width(text) -> float:
    return text.get_window_extent(text.figure.canvas.get_renderer()).width


def fit_title(text, width_px: float, deck=None, sizes=(11, 10, 9)) -> None:
    """Fit a title line into ``width_px``: a smaller font first (``sizes`` [pt]), then the
    deck's title shortened at a word (the speed after it is kept)."""
    from camtrain.report.layout import fit_text

    for size in sizes:
        text.set_fontsize(size)
        if _width(text) <= width_px:
            return
    full = text.get_text()
    suffix = full[len(deck.title):] if deck is not None and full.startswith(deck.title) else ""
    head = full[:len(full) - len(suffix)] if suffix else full

    def measure(candidate: str) -> float:
        text.set_text(candidate + suffix)
        return _width(text)

    text.set_text(fit_text(head, width_px, measure) + suffix)


def wrap_text(text, width_px: float, max_lines: int = 2) -> None:
    """Break ``text`` at words into at most ``max_lines`` lines no wider than ``width_px``."""
    words, lines = text.get_text().split(), []
    while words:
        line = words.pop(0)
        while words:
            text.set_text(f"{line} {words[0]}")
            if _width(text) > width_px:
                break
            line = f"{line} {words.pop(0)}"
        lines.append(line)
        if len(lines) == max_lines - 1 and words:
            lines.append(" ".join(words))
            break
    text.set_text("\n".join(lines))


