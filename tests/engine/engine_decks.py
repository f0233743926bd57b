"""The shipped engine decks as validated models, with fields changed (for the engine tests)."""
from __future__ import annotations

import copy
import tomllib
from functools import cache

from camtrain.deck.load import validate
from tests.conftest import DECKS

RUSTON = DECKS / "ruston_6veb.toml"
ZETA = DECKS / "zeta_crank_bearings.toml"


@cache
def _raw(path) -> dict:
    return tomllib.loads(path.read_text(encoding="utf-8"))


def deck(path=RUSTON, **changes):
    """The deck at ``path`` with ``section__field=value`` changes (``bearings__big_end__length``
    for nested sections), validated into its SI model."""
    raw = copy.deepcopy(_raw(path))
    for key, value in changes.items():
        *sections, name = key.split("__")
        node = raw
        for s in sections:
            node = node.setdefault(s, {})
        node[name] = value
    return validate(raw, path.name, DECKS)
