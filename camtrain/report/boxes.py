"""The terminal report as plain text, for output that is not a terminal (a pipe, a file, a log).

There the terminal library prints no colours or styles, only characters: its rule, its
heavy-headed box tables with one space of padding, and its word wrapping of cells (words longer
than a column folded). This module draws the same characters, cell for cell, without importing
that library (a sixth of a short run's process). `tests/report/test_boxes.py` compares the two
at many widths. Text it could lay out differently (characters that are not one cell wide, a
backslash the markup escaping would touch, an encoding that is not UTF-8, Windows consoles) is
left to the library: :func:`plain_ok` says which.
"""
from __future__ import annotations

import os
import re
import sys

#: characters one terminal cell wide as the terminal library measures them: its own single-cell
#: ranges, and the few symbols camtrain's messages use (all one cell in Unicode's width tables)
_ONE_CELL = frozenset(
    [chr(c) for lo, hi in ((0x20, 0x7E), (0xA0, 0xAC), (0xAE, 0x2FF), (0x370, 0x482),
                           (0x2500, 0x25FC)) for c in range(lo, hi + 1)]
    + list("…−–—‘’“”•′″→←↑↓≤≥≈≠±∞√∑∫∂∆∇∈∉≡√"))

_WORD = re.compile(r"\s*\S+\s*")


def plain_ok(*texts: str) -> bool:
    """True when every text can be drawn here exactly as the terminal library would."""
    return all(_ONE_CELL.issuperset(t) and "\\" not in t for t in texts)


def is_plain_stream(stream, environ=None) -> bool:
    """True when the terminal library would write ``stream`` as plain text (no terminal): not
    a tty, UTF-8 output, not on Windows (whose consoles the library treats apart). Where the
    environment overrides the library's choice (FORCE_COLOR, TTY_COMPATIBLE) the library
    decides: its versions read those variables differently (13.0 takes an empty FORCE_COLOR
    as set and knows no TTY_COMPATIBLE), so only the case every version agrees on is drawn
    here."""
    env = os.environ if environ is None else environ
    if os.name == "nt" or "JPY_PARENT_PID" in env or "ipykernel" in sys.modules:
        return False
    encoding = (getattr(stream, "encoding", None) or "utf-8").lower()
    if not encoding.startswith("utf"):
        return False
    if "FORCE_COLOR" in env or "TTY_COMPATIBLE" in env:
        return False
    isatty = getattr(stream, "isatty", None)
    try:
        return isatty is not None and not isatty()
    except ValueError:
        return True


def plain_width(environ=None) -> int:
    """Width the terminal library gives a non-terminal: a terminal's on standard input, output
    or error if any, else 80; COLUMNS overrides."""
    env = os.environ if environ is None else environ
    width = None
    for fd in (0, 1, 2):
        try:
            width = os.get_terminal_size(fd).columns
        except (AttributeError, ValueError, OSError):
            continue
        break
    columns = env.get("COLUMNS")
    if columns is not None and columns.isdigit():
        width = int(columns)
    return width or 80


def rule(title: str, width: int) -> str:
    """A horizontal rule with ``title`` centred (cut with an ellipsis when too long)."""
    if width - 4 <= 0 or not title:
        return "─" * width
    title = title.replace("\n", " ")
    title = _cut(title, width - 4)
    side = (width - len(title)) // 2
    left = "─" * max(side - 1, 0)
    right = "─" * (width - len(left) - len(title))
    return _fit(left + " " + title + " " + right, width)


def _cut(text: str, width: int) -> str:
    return text if len(text) <= width else text[:width - 1] + "…"


def _fit(text: str, width: int) -> str:
    return text[:width] if len(text) > width else text + " " * (width - len(text))


def table(title: str | None, columns: list[tuple[str, str]], rows: list[list[str]],
          width: int) -> list[str]:
    """The lines of a heavy-headed box table: ``columns`` are (header, "left" | "right"), every
    cell padded by a space either side and word-wrapped (long words folded) to fit ``width``."""
    cells = [[h for h, _ in columns], *rows]
    widths = _column_widths(cells, width - len(columns) - 1)
    lines = []
    if title:                            # rich does not wrap a title on a soft-wrapping console
        lines.append(title)
    lines.append("┏" + "┳".join("━" * w for w in widths) + "┓")
    for index, row in enumerate(cells):
        wrapped = [_wrap(text, w - 2, just) if w > 2 else [""]
                   for text, w, (_, just) in zip(row, widths, columns, strict=True)]
        height = max(len(c) for c in wrapped)
        for i, c in enumerate(wrapped):
            blank = [" " * max(widths[i] - 2, 0)] * (height - len(c))
            wrapped[i] = blank + c if index == 0 else c + blank   # headers sit at the bottom
        bar = "┃" if index == 0 else "│"
        for n in range(height):
            lines.append(bar + bar.join(_pad(c[n], w) for c, w in zip(wrapped, widths, strict=True))
                         + bar)
        if index == 0:
            lines.append("┡" + "╇".join("━" * w for w in widths) + "┩")
    lines.append("└" + "┴".join("─" * w for w in widths) + "┘")
    return lines


def _pad(line: str, width: int) -> str:
    return _fit(" " + line + " ", width) if width >= 2 else _fit(line, width)


def _measure(text: str) -> tuple[int, int]:
    longest_line = max((len(line) for line in text.splitlines()), default=0)
    longest_word = max((len(word) for word in text.split()), default=longest_line)
    return longest_word, longest_line


def _column_widths(cells: list[list[str]], room: int) -> list[int]:
    """Column widths with padding: each column's longest line, shrunk to ``room`` the way the
    terminal library shrinks them (the widest columns first, then all evenly)."""
    def maximum(col: int, limit: int) -> int:
        if limit < 1:
            return 0
        widest = 0
        for row in cells:
            if limit - 2 < 1:
                longest = limit
            else:
                longest = min(_measure(row[col])[1] + 2, limit)
            widest = max(widest, min(longest, limit))
        return widest

    n = len(cells[0])
    widths = [maximum(c, room) or 1 for c in range(n)]
    if sum(widths) > room:
        widths = _collapse(widths, room)
        if sum(widths) > room:
            widths = _reduce(sum(widths) - room, [1] * n, widths, widths)
        widths = [maximum(c, w) or 0 for c, w in enumerate(widths)]
    return widths


def _collapse(widths: list[int], room: int) -> list[int]:
    total = sum(widths)
    excess = total - room
    while total and excess > 0:
        widest = max(widths)
        second = max((w for w in widths if w != widest), default=0)
        if not widest - second:
            break
        ratios = [1 if w == widest else 0 for w in widths]
        widths = _reduce(excess, ratios, [min(excess, widest - second)] * len(widths), widths)
        total = sum(widths)
        excess = total - room
    return widths


def _reduce(total: int, ratios: list[int], maximums: list[int], values: list[int]) -> list[int]:
    ratios = [r if m else 0 for r, m in zip(ratios, maximums, strict=True)]
    total_ratio = sum(ratios)
    if not total_ratio:
        return values[:]
    out = []
    for ratio, most, value in zip(ratios, maximums, values, strict=True):
        if ratio and total_ratio > 0:
            cut = min(most, round(ratio * total / total_ratio))
            out.append(value - cut)
            total -= cut
            total_ratio -= ratio
        else:
            out.append(value)
    return out


def _wrap(text: str, width: int, justify: str) -> list[str]:
    """``text`` word-wrapped to ``width`` (long words folded), each line justified."""
    out = []
    for paragraph in text.split("\n"):
        breaks = _breaks(paragraph, width)
        for a, b in zip([0, *breaks], [*breaks, len(paragraph)], strict=True):
            line = paragraph[a:b]
            excess = len(line) - width
            if excess > 0:                             # blanks past the width are dropped
                blanks = len(line) - len(line.rstrip())
                line = line[:len(line) - min(blanks, excess)]
            if justify == "right":
                line = line.rstrip()[:width]
                line = " " * (width - len(line)) + line
            else:
                line = _fit(line, width)
            out.append(line)
    return out


def _breaks(text: str, width: int) -> list[int]:
    """Offsets to break ``text`` at so that each line fits ``width`` cells."""
    breaks, offset = [], 0
    for match in _WORD.finditer(text):
        start, word = match.start(), match.group(0)
        length = len(word.rstrip())
        if width - offset >= length:
            offset += len(word)
        elif length > width:                           # fold a word wider than a line
            chunks = [word[i:i + width] for i in range(0, len(word), width)] or [word]
            for i, chunk in enumerate(chunks):
                if start:
                    breaks.append(start)
                if i == len(chunks) - 1:
                    offset = len(chunk)
                else:
                    start += len(chunk)
        elif offset and start:
            breaks.append(start)
            offset = len(word)
    return breaks
