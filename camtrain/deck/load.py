"""Read a deck (file or standard input), parse TOML, validate it into the SI model.

Every failure a user can cause becomes an :class:`InputError` listing all problems found.
"""
from __future__ import annotations

import dataclasses
import hashlib
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path

from camtrain.catalogue import DEFAULT_KIND, KINDS
from camtrain.deck.fields import SchemaPaths, build_section
from camtrain.deck.schema import Deck
from camtrain.errors import InputError, Problem
from camtrain.lazy import resolve

MAX_DECK_BYTES = 20 * 1024 * 1024


@dataclass(frozen=True)
class LoadedDeck:
    """A validated deck with where it came from."""

    model: Deck  # or a BearingDeck for kind = "journal_bearing"
    path: str
    sha256: str
    text: str


def read_text(path: str) -> tuple[str, str]:
    """Return (display name, text) of a deck path, or '-' for standard input."""
    import sys

    if path == "-":
        data = sys.stdin.buffer.read(MAX_DECK_BYTES + 1)
        name = "<stdin>"
    else:
        p = Path(path)
        if not p.exists():
            raise InputError(Problem("", f"deck file {path!r} does not exist"))
        if p.is_dir():
            raise InputError(Problem("", f"{path!r} is a directory, not a deck file"))
        try:
            with p.open("rb") as fh:
                data = fh.read(MAX_DECK_BYTES + 1)
        except OSError as exc:
            raise InputError(Problem("", f"cannot read {path!r}: {exc.strerror}")) from None
        name = path
    if len(data) > MAX_DECK_BYTES:
        raise InputError(Problem("", f"{name} is larger than {MAX_DECK_BYTES // 2**20} MiB; "
                                     "a deck is a small text file"))
    if b"\x00" in data:
        raise InputError(Problem("", f"{name} is a binary file, not a TOML deck"))
    try:
        # utf-8-sig: a byte-order mark (some Windows editors write one) is read, not parsed
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputError(Problem("", f"{name} is not UTF-8 text (byte {exc.start})")) from None
    return name, text


def parse_toml(text: str, name: str) -> dict:
    """Parse TOML text; errors carry line and column."""
    if not text.strip():
        raise InputError(Problem("", "the deck is empty"), source=name)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(Problem("", f"malformed TOML: {exc}"), source=name) from None


def validate(raw: dict, name: str = "", base_dir: Path | None = None) -> Deck:
    """Validate raw TOML data into the immutable SI model, reporting every problem at once.

    The top-level ``kind`` picks the schema among the registered deck kinds
    (:data:`camtrain.catalogue.KINDS`; ``valve_train`` is the default).
    """
    kind = raw.get("kind", DEFAULT_KIND)
    if not isinstance(kind, str) or kind not in KINDS:
        raise InputError(Problem("kind", "is not a known deck kind", kind,
                                 " or ".join(repr(k) for k in KINDS)), source=name)
    schema = resolve(KINDS[kind].schema)
    if "kind" in raw and not any(f.name == "kind" for f in dataclasses.fields(schema)):
        raw = {k: v for k, v in raw.items() if k != "kind"}  # a schema without its own kind key
    problems: list[Problem] = []
    deck = build_section(schema, raw, "", problems, SchemaPaths(schema))
    if deck is None or problems:
        raise InputError(problems or [Problem("", "invalid deck")], source=name)
    if isinstance(deck, Deck):
        deck = _resolve_lift_table(deck, base_dir or Path.cwd(), name)
    resolve_paths = getattr(deck, "resolve_paths", None)
    if resolve_paths is not None:  # a schema that names other files (an engine's valve-train decks)
        deck = resolve_paths(base_dir or Path.cwd(), name)
    return deck


def load_deck(path: str) -> LoadedDeck:
    """Read, parse and validate a deck file ('-' for standard input)."""
    name, text = read_text(path)
    raw = parse_toml(text, name)
    base = Path(path).resolve().parent if path != "-" else Path.cwd()
    model = validate(raw, name, base)
    return LoadedDeck(model, name, hashlib.sha256(text.encode()).hexdigest(), text)


def load_deck_text(text: str, name: str = "<text>", base_dir: Path | None = None) -> LoadedDeck:
    """Parse and validate deck text (for scripts and tests)."""
    raw = parse_toml(text, name)
    model = validate(raw, name, base_dir)
    return LoadedDeck(model, name, hashlib.sha256(text.encode()).hexdigest(), text)


# --------------------------------------------------------------------------- lift tables

def _resolve_lift_table(deck: Deck, base_dir: Path, name: str) -> Deck:
    """Inline table angles to radians (checked increasing); a table file path made absolute.

    The file itself is read by the lift layer, which owns the lift-table format.
    """
    table = deck.lift.table
    if table is None:
        return deck
    path = "lift.table"
    if table.file is not None:
        p = Path(table.file)
        p = p if p.is_absolute() else base_dir / p
        if not p.is_file():
            raise InputError(Problem(f"{path}.file", "file not found", table.file,
                                     "a CSV file (path relative to the deck)"), source=name)
        new_table = dataclasses.replace(table, file=str(p))
    elif table.angles is not None:
        factor = math.pi / 180.0 if table.angle_unit == "deg" else 1.0
        angles = tuple(a * factor for a in table.angles)
        for i in range(1, len(angles)):
            if not angles[i] > angles[i - 1]:
                what = "repeats" if angles[i] == angles[i - 1] else "decreases"
                raise InputError(Problem(
                    f"{path}.angles[{i}]", f"angle {what}", table.angles[i],
                    f"angles strictly increasing (previous {table.angles[i - 1]})"), source=name)
        if angles[-1] - angles[0] > 2 * math.pi + 1e-12:
            raise InputError(Problem(f"{path}.angles", "span more than one revolution", None,
                                     "a span of at most 360 deg"), source=name)
        new_table = dataclasses.replace(table, angles=angles)
    else:
        return deck
    return dataclasses.replace(deck, lift=dataclasses.replace(deck.lift, table=new_table))
