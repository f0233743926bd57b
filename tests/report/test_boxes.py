"""The plain-text report (camtrain.report.boxes) is, character for character, what rich prints
on a stream that is not a terminal: the same tables, rule and lines at every width, for the
report of a real run and for cells made to stress the wrapping."""
from __future__ import annotations

import io
import random

import pytest
from rich.console import Console

from camtrain import api
from camtrain.report import boxes
from camtrain.report.console import PlainOut, RichOut, Table, print_checks, print_plan, print_run
from camtrain.report.outputs import check_limits
from tests.conftest import DECKS

WIDTHS = (20, 33, 47, 60, 80, 101, 160)


def _both(width: int, draw) -> tuple[str, str]:
    rich_file, plain_file = io.StringIO(), io.StringIO()
    draw(RichOut(console=Console(file=rich_file, width=width, highlight=False, soft_wrap=True,
                                 emoji=False)))
    draw(PlainOut(plain_file, width=width))
    return rich_file.getvalue(), plain_file.getvalue()


@pytest.fixture(scope="module")
def harrison():
    text = (DECKS / "harrison_flat.toml").read_text().replace("angle_points = 1440",
                                                              "angle_points = 240")
    loaded = api.loads(text)
    result = api.run(loaded)
    return loaded, result, check_limits(result, loaded)


@pytest.mark.parametrize("width", WIDTHS)
def test_run_report_as_rich_prints_it(harrison, width):
    loaded, result, checks = harrison

    def draw(out):
        out.rule((loaded.model.title, "bold"), "  (decks/harrison_flat.toml)")
        print_plan(out, result.plan, result.timings)
        print_run(out, result, [], checks, None)
        print_checks(out, checks)

    expected, got = _both(width, draw)
    assert "key results" in got and "┏" in got
    assert got == expected


_WORDS = ["a", "ok", "film", "Hertz", "[camshaft]", "(lobes)", "µm", "λ", "−39.5°", "…",
          "extraordinarily_long_identifier_without_breaks", "mm/deg²", "≤", "N·m", "", "  "]


def _phrase(rng: random.Random) -> str:
    return " ".join(rng.choice(_WORDS) for _ in range(rng.randint(0, 9))).strip(" ") \
        if rng.random() < 0.9 else rng.choice(_WORDS) * rng.randint(1, 4)


@pytest.mark.parametrize("seed", range(30))
def test_random_tables_as_rich_prints_them(seed):
    rng = random.Random(seed)
    ncols = rng.randint(1, 5)
    table = Table(_phrase(rng) or "title", [(_phrase(rng), rng.choice(("left", "right")),
                                             rng.choice((None, "dim"))) for _ in range(ncols)])
    for _ in range(rng.randint(0, 6)):
        table.add_row(*(_phrase(rng) for _ in range(ncols)))
    for width in (rng.randint(12, 40), rng.randint(41, 200)):
        expected, got = _both(width, lambda out, t=table: out.table(t))
        assert got == expected, (width, table.texts())


@pytest.mark.parametrize("width", WIDTHS)
def test_rules_and_lines_as_rich_prints_them(width):
    def draw(out):
        for title in ("x", "Cam and flat-faced follower (Harrison data, Ball 1988)", "a" * 300):
            out.rule((title, "bold"), "  (deck.toml)")
        out.line(("warning:", "yellow"), " film [µm] passes " + "z" * 200)

    expected, got = _both(width, draw)
    assert got == expected


def test_text_it_cannot_draw_alike_goes_to_rich():
    """A backslash (markup escaping), a wide character or a newline: printed by rich."""
    for text in ("C:\\decks\\x.toml", "カム", "two\nlines", "tab\there"):
        assert not boxes.plain_ok(text)
        expected, got = _both(40, lambda out, t=text: out.table(Table(t, [(t, "left", None)])))
        assert got == expected


def test_stream_kind_as_rich_decides_it():
    """A stream is drawn here only where rich would write plain text too (with every rich
    version camtrain supports: where the environment overrides rich's choice, rich decides);
    a pipe with no override is drawn here."""
    class Pipe(io.StringIO):
        encoding = "utf-8"

    class Tty(Pipe):
        def isatty(self):
            return True

    for stream, env in ((Pipe(), {}), (Tty(), {}), (Pipe(), {"FORCE_COLOR": "1"}),
                        (Pipe(), {"FORCE_COLOR": ""}), (Tty(), {"TTY_COMPATIBLE": "0"}),
                        (Pipe(), {"TTY_COMPATIBLE": "1"})):
        rich_terminal = Console(file=stream, _environ=env).is_terminal
        if boxes.is_plain_stream(stream, env):
            assert not rich_terminal, env
    assert boxes.is_plain_stream(Pipe(), {})
    assert not boxes.is_plain_stream(Tty(), {})
