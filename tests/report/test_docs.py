"""Generated docs stay in step with the code: mechanism pages and the examples page."""
from __future__ import annotations

import re

import pytest

from camtrain.deck.schema import MECHANISMS
from camtrain.report.docs_pages import mechanism_page
from tests.conftest import DECKS, ROOT


@pytest.mark.parametrize("mechanism", MECHANISMS)
def test_mechanism_page_is_up_to_date(mechanism):
    """Regenerate with `python docs/make_examples.py --pages`."""
    page = ROOT / "docs" / f"mechanism_{mechanism}.md"
    assert page.read_text(encoding="utf-8") == mechanism_page(mechanism)


def test_mechanism_page_holds_a_valid_template():
    from camtrain import api

    page = mechanism_page("finger")
    toml = page.split("```toml\n", 1)[1].split("\n```", 1)[0]
    assert api.loads(toml, "finger.toml").model.mechanism.type == "finger"


def test_examples_cover_every_deck_and_link_existing_images():
    text = (ROOT / "docs" / "examples.md").read_text(encoding="utf-8")
    for deck in DECKS.glob("*.toml"):
        assert f"decks/{deck.name}" in text, f"{deck.name}: rerun python docs/make_examples.py"
    images = re.findall(r"\]\((img/[^)]+)\)", text)
    assert images
    for image in images:
        assert (ROOT / "docs" / image).exists(), image


def test_docs_name_no_machine_paths():
    """Generated pages use repository-relative paths only."""
    for page in list((ROOT / "docs").glob("mechanism_*.md")) + [ROOT / "docs" / "examples.md"]:
        assert str(ROOT) not in page.read_text(encoding="utf-8"), page.name


def test_every_large_residual_in_the_examples_is_explained():
    """A published comparison more than 10 % off carries its explanation, or 'unexplained' and
    what was tried (docs/make_examples.py refuses to write it otherwise)."""
    text = (ROOT / "docs" / "examples.md").read_text(encoding="utf-8")
    rows = [r for r in text.splitlines() if r.startswith("| ") and r.count("|") == 7]
    checked = 0
    for row in rows:
        cells = [c.strip() for c in row.strip("|").split("|")]
        m = re.fullmatch(r"([+-]?\d+\.\d) (%|points)", cells[4])
        if m and abs(float(m.group(1))) > 10.0:
            checked += 1
            assert len(cells[5]) > 20, row
    assert checked >= 3     # the Pinto and desmodromic rows at least
