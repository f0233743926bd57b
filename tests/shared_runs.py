"""One run per deck file and set of ``--set`` changes for the whole test session.

Several test files run the same shipped deck unchanged (the golden files, the outputs of every
deck, the generated documentation pages, the Zeta engine's speed table); each such run is made
once here and handed to every test that asks for it. What a test receives is what it would have
computed itself:

- a deep copy of the result, so that no test sees another test's changes to it;
- every Python warning the run raised, issued again in the asking test (under that test's
  warning filters, with the module that raised it), so that a test that turns warnings into
  errors still fails on a run that warns, whichever test ran it first.

A run that raises is not kept: every test that asks for it runs it again and sees the error.

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
    """(LoadedDeck, Result) of ``api.run(api.load(path, sets))``, run once per session."""
    loaded, result, caught = _run_once(str(Path(path).resolve()), tuple(sets))
    _warn_again(caught)
    return loaded, copy.deepcopy(result)


@functools.cache
def _run_once(path: str, sets: tuple[str, ...]):
    from camtrain import api

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")   # keep every warning; the asking test's filters decide
        loaded = api.load(path, sets)
        result = api.run(loaded)
    return loaded, result, tuple(caught)


def _warn_again(caught) -> None:
    if not caught:
        return
    module_of = {getattr(m, "__file__", None): name for name, m in list(sys.modules.items())}
    for w in caught:
        module = module_of.get(w.filename) or Path(w.filename).stem
        warnings.warn_explicit(w.message, w.category, w.filename, w.lineno, module=module)
