"""A one-line notice when camtrain compiles its numerical kernels in this process.

The numba kernels (journal orbits, the elastic valve train, the coupled camshaft) are compiled
on first use and cached on disk (``cache=True``); a run that finds the cache is fast (the
coupled camshaft deck: about 6 s of CPU), one that does not first spends 30-70 s of CPU
compiling: after an install, an upgrade, or any change of a kernel's source file. Without a word
that looks like a hang, so :func:`watch` prints once, when numba actually compiles (a kernel
loaded from the cache says nothing).

numba is imported only by decks that use a kernel, so the listener is installed when numba is
first imported (an import hook), never by importing numba here.
"""
from __future__ import annotations

import sys
from collections.abc import Callable
from importlib.abc import MetaPathFinder
from importlib.machinery import PathFinder

NOTICE = ("note: compiling camtrain's numerical kernels (first use after an install or an "
          "upgrade: up to about a minute, once; later runs load them from the cache)")

class _State:
    """One listener per process, saying the notice once to whoever asked last."""

    say: Callable[[str], None] | None = None
    said = False
    listening = False


def _on_compile() -> None:
    if not _State.said and _State.say is not None:
        _State.said = True
        _State.say(NOTICE)


def _listen() -> None:
    if _State.listening:
        return
    from numba.core import event

    class _Compiling(event.Listener):
        def on_start(self, ev):
            _on_compile()

        def on_end(self, ev):
            pass

    event.register("numba:compile", _Compiling())
    _State.listening = True


class _OnNumbaImport(MetaPathFinder):
    """Finds nothing itself; wraps numba's loader so the listener is installed once numba is."""

    used = False

    def find_spec(self, name, path=None, target=None):
        if name != "numba" or self.used:
            return None
        self.used = True      # (it leaves sys.meta_path later: the import is iterating it now)
        spec = PathFinder.find_spec(name, path)
        if spec is None or spec.loader is None:
            return spec
        run_module, finder = spec.loader.exec_module, self

        def exec_module(module):
            if finder in sys.meta_path:
                sys.meta_path.remove(finder)
            run_module(module)
            _listen()

        spec.loader.exec_module = exec_module
        return spec


def watch(say: Callable[[str], None]) -> None:
    """Call ``say(NOTICE)`` the first time numba compiles a kernel in this process (the last
    ``say`` given is the one called)."""
    _State.say = say
    if _State.said or _State.listening:
        return
    if "numba" in sys.modules:
        _listen()
    elif not any(isinstance(f, _OnNumbaImport) for f in sys.meta_path):
        sys.meta_path.insert(0, _OnNumbaImport())
