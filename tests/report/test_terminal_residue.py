"""On a real terminal the progress bars of `camtrain run` leave nothing behind: the run is
driven through a pseudo-terminal and its output replayed on a minimal screen (carriage return,
line feed, erase line, cursor up), and the final screen holds the reports but no bar."""
from __future__ import annotations

import os
import re
import subprocess
import sys

import pytest

from tests.conftest import DECKS, ROOT

pty = pytest.importorskip("pty")

_TOKEN = re.compile(r"\x1b\[([0-9;?]*)([A-Za-z])|\r|\n|[^\x1b\r\n]+")


def screen(output: str) -> str:
    """What a terminal shows after ``output`` (the escape sequences rich's live display uses;
    styles ignored)."""
    lines, row, col = [""], 0, 0
    for m in _TOKEN.finditer(output):
        token = m.group(0)
        if m.group(2):
            arg, command = m.group(1), m.group(2)
            if command == "K":
                lines[row] = lines[row][:col] if arg in ("", "0") else ""
            elif command == "A":
                row = max(0, row - int(arg or 1))
            elif command == "G":
                col = int(arg or 1) - 1
        elif token == "\r":
            col = 0
        elif token == "\n":
            row, col = row + 1, 0
            lines += [""] * (row + 1 - len(lines))
        else:
            line = lines[row].ljust(col)
            lines[row] = line[:col] + token + line[col + len(token):]
            col += len(token)
    return "\n".join(lines)


def test_progress_leaves_no_trace_on_a_terminal(tmp_path):
    main, secondary = pty.openpty()
    env = {**os.environ, "PYTHONPATH": str(ROOT), "COLUMNS": "100", "TERM": "xterm"}
    for name in ("NO_COLOR", "FORCE_COLOR", "TTY_COMPATIBLE", "TTY_INTERACTIVE"):
        env.pop(name, None)          # the terminal library decides from the pseudo-terminal
    proc = subprocess.Popen(
        [sys.executable, "-m", "camtrain.cli", "run", str(DECKS / "harrison_flat.toml"),
         str(DECKS / "bearing_ocvirk_check.toml"), "--no-plots", "--out", str(tmp_path)],
        stdin=secondary, stdout=secondary, stderr=secondary, env=env, cwd=ROOT)
    os.close(secondary)
    chunks = []
    while True:
        try:
            data = os.read(main, 65536)
        except OSError:          # the child closed the terminal
            break
        if not data:
            break
        chunks.append(data)
    os.close(main)
    assert proc.wait(timeout=120) == 0
    raw = b"".join(chunks).decode("utf-8", "replace")
    assert "harrison_flat: " in raw, "no progress bar was drawn"   # (labels: test_terminal_summary)
    shown = screen(raw)
    assert not re.search(r"loading|running |writing|sheets?\b.*\d+/\d+", shown), shown
    assert "Cam and flat-faced follower" in shown and "Ocvirk" in shown
