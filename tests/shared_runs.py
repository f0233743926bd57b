"""One run per deck model for the whole test session.

Several test files run the same deck (the golden files, the outputs of every deck, the generated
documentation pages, the Zeta engine's speed table); each such run is made once here and handed
to every test that asks for it. A run is keyed by its validated deck model (a frozen dataclass:
equal models are the same run however they were written, e.g. a deck file with
``speed.engine=3000`` set and the same deck built in Python). What a test receives is what it
would have computed itself:

- a deep copy of the result, so that no test sees another test's changes to it;
- every Python warning the run raised, issued again in the asking test (under that test's
  warning filters, with the module that raised it), so that a test that turns warnings into
  errors still fails on a run that warns, whichever test ran it first.

A run that raises is not kept: every test that asks for it runs it again and sees the error.
Loading a deck is not shared (it is cheap, and its warnings and errors belong to the asker).

Import it as ``tests.shared_runs`` everywhere: a module imported under two names would keep two
caches.
"""
from __future__ import annotations

import copy
import functools
import sys
import warnings
from pathlib import Path


def run_deck(path: str | Path, sets: tuple[str, ...] = ()):
    """(LoadedDeck, Result) of ``api.run(api.load(path, sets))``; the run shared."""
    from camtrain import api

    loaded = api.load(path, tuple(sets))
    return loaded, run_model(loaded.model)


def run_model(model):
    """``api.run(model)`` for a validated deck model, run once per session."""
    try:
        hash(model)
    except TypeError:     # not a frozen model: nothing to key the run by
        from camtrain import api

        return api.run(model)
    result, caught = _run_once(model)
    _warn_again(caught)
    return copy.deepcopy(result)


@functools.cache
def _run_once(model):
    from camtrain import api

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")   # keep every warning; the asking test's filters decide
        result = api.run(model)
    return result, tuple(caught)


def _warn_again(caught) -> None:
    if not caught:
        return
    module_of = {getattr(m, "__file__", None): name for name, m in list(sys.modules.items())}
    for w in caught:
        module = module_of.get(w.filename) or Path(w.filename).stem
        warnings.warn_explicit(w.message, w.category, w.filename, w.lineno, module=module)
