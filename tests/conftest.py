"""Shared fixtures: paths and a minimal valid deck as TOML text."""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.tiers import TIERS, tier_of

ROOT = Path(__file__).resolve().parent.parent
DECKS = ROOT / "decks"

MINIMAL_DECK = """
title = "minimal"
[speed]
camshaft = 1500
[mechanism]
type = "flat"
[cam]
base_radius = 18
[lift]
form = "four_power"
[lift.ramps]
opening_height = 0.5
opening_length = 25
closing_height = 0.5
closing_length = 25
[lift.four_power]
half_period = 60
max_lift = 8.9
exponents = [2, 9, 78, 80]
coefficients = [-11.6918407, 2.8498942, -0.5894568, 0.5314033]
"""


@pytest.fixture
def minimal_deck() -> str:
    return MINIMAL_DECK


def pytest_configure(config):
    for tier in TIERS:
        config.addinivalue_line("markers", f"{tier}: validation tier (tests/tiers.py)")
    config.addinivalue_line("markers", "slow: out of `make test` (kept under ten minutes on two "
                            "cores); `make test-all` runs it")


def pytest_addoption(parser):
    parser.addoption("--reverse", action="store_true", default=False,
                     help="Run the collected tests in reverse order (a test that passes only "
                          "after another has run shows up; `make test-reverse`).")


def pytest_collection_modifyitems(config, items):
    """Every test gets the marker of its validation tier (tests/tiers.py); --reverse runs them
    last to first."""
    if config.getoption("--reverse"):
        items.reverse()
    for item in items:
        nodeid = item.nodeid if item.nodeid.startswith("tests/") else "tests/" + item.nodeid
        own = {m.name for m in item.iter_markers()}
        item.add_marker(getattr(pytest.mark, tier_of(nodeid, own)))
