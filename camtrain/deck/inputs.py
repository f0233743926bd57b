"""The files a deck reads besides itself (a lift-table file, included valve-train decks and
theirs), and a digest of their contents: what a resumed sweep compares to know its finished
cases were computed from the same data."""
from __future__ import annotations

import hashlib
from pathlib import Path

#: larger files are refused where they are read (decks and lift tables: 20 MiB)
_READ_LIMIT = 20 * 1024 * 1024 + 1


def input_files(model) -> list[Path]:
    """Absolute paths of every file ``model`` (a validated deck) reads, included decks' own
    files after each included deck, in deck order, without repeats."""
    files: list[Path] = []
    table = getattr(getattr(model, "lift", None), "table", None)
    if table is not None and getattr(table, "file", None):
        files.append(Path(table.file))
    flame = getattr(model, "flame", None)
    for vt in getattr(flame, "valve_trains", None) or ():
        from camtrain.deck.load import load_deck

        files.append(Path(vt.deck))
        files += input_files(load_deck(vt.deck).model)
    return list(dict.fromkeys(files))


def input_digests(model) -> dict[str, str]:
    """{path: sha256 of its content} of :func:`input_files` ("missing" for one that went)."""
    out = {}
    for path in input_files(model):
        try:
            with path.open("rb") as fh:
                out[str(path)] = hashlib.sha256(fh.read(_READ_LIMIT)).hexdigest()
        except OSError:
            out[str(path)] = "missing"
    return out
