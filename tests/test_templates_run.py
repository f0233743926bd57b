"""Every template runs clean: `camtrain template KIND` then `camtrain run` gives no warning about
the template's own data (a lift law of another engine, a concave flank, a discontinuous cut-off,
a pressure table of doubtful reference), only the physical findings the published engine it
comes from gives as a shipped deck."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from camtrain import api
from camtrain.cli import MECHANISM_CHOICES
from camtrain.deck.templates import render_template
from camtrain.report.findings import find

DECKS = Path(__file__).resolve().parent.parent / "decks"

#: the shipped deck of the engine (or the data) each template is taken from
SOURCE_DECK = {
    "flat": "harrison_flat", "domed": "harrison_flat", "pushrod": "harrison_flat",
    "finger": "pinto_finger", "rocker": "rover_2300_rocker", "desmodromic": "desmo_rig",
    "roller_finger": "roller_finger", "roller_rocker": "roller_finger",
    "roller_tappet": "roller_finger", "pushrod_roller": "roller_finger",
    "journal_bearing": "bearing_ocvirk_check", "engine": "ruston_6veb",
}


def _kind_of(warning: str) -> str:
    """What a warning is about: its words before the first number or angle."""
    return re.split(r"[-+]?\d", warning, maxsplit=1)[0].strip()


def _all_warnings(loaded) -> list[str]:
    """What `camtrain run` prints as warnings: check's advice, the size checks, the run's own
    warnings and the findings on its cycle (a concave flank, bounce, boundary lubrication)."""
    advice = list(getattr(loaded.model, "advisories", list)())
    result = api.run(loaded)
    findings = find(result).messages(result.warnings)
    return advice + list(api.implausible(loaded)) + list(result.warnings) + findings


def test_every_template_has_a_source_deck():
    assert set(SOURCE_DECK) == set(MECHANISM_CHOICES)


@pytest.mark.parametrize("kind", MECHANISM_CHOICES)
def test_template_runs_without_a_warning_about_its_own_data(kind):
    loaded = api.loads(render_template(kind), f"template {kind}")
    template = _all_warnings(loaded)
    source = {_kind_of(w) for w in _all_warnings(api.load(DECKS / f"{SOURCE_DECK[kind]}.toml"))}
    own = [w for w in template if _kind_of(w) not in source]
    assert not own, f"template {kind} warns about its own data: {own}"


@pytest.mark.parametrize("kind", MECHANISM_CHOICES)
def test_template_draws_no_advice_from_check(kind):
    """`check`'s advice on a valid but suspicious deck (the engine's pressure reference, its
    moment unit, a short film beyond its land) has nothing to say about a template."""
    loaded = api.loads(render_template(kind), f"template {kind}")
    assert list(getattr(loaded.model, "advisories", list)()) == []
    assert list(api.implausible(loaded)) == []
