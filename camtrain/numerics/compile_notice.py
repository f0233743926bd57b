"""Say so, once and by name, when a family of compiled kernels is about to be compiled.

numba compiles a kernel on its first call and keeps the machine code in its disk cache
(``cache=True``), so the compile is paid once per installation (``camtrain warmup`` pays it
ahead; docs/performance.md, "First run"). When a kernel module is imported (only decks that use
it import it) it calls :func:`announce` with its entry kernels: if any of them has no fresh entry
in the disk cache, the listeners (the command line prints to standard error) hear
"compiling the journal-orbit kernels, once per installation, about 15 s".

The cache is read through numba's own index of the kernel (its source stamp and numba version
must match, as numba checks them itself); a numba whose cache layout differs is not guessed at:
nothing is announced.
"""
from __future__ import annotations

from collections.abc import Callable, Iterable

#: family -> CPU seconds its compile took on the reference machine (docs/performance.md,
#: "First run": a deck's cold run less its warm run, the other families already cached)
COMPILE_SECONDS = {
    "journal-orbit": 13,
    "valve-train dynamics": 13,
    "shaft-and-trains": 30,
    "ring-film": 5,
    "roller": 4,
}

_listeners: list[Callable[[str], None]] = []
_announced: set[str] = set()


def listen(listener: Callable[[str], None] | None) -> None:
    """Hand notices to ``listener`` (replacing any other); None silences them."""
    _listeners.clear()
    if listener is not None:
        _listeners.append(listener)


def is_cached(kernel) -> bool:
    """True when numba's disk cache holds a fresh compile of ``kernel`` (or it cannot tell)."""
    try:
        return bool(kernel._cache._cache_file._load_index())
    except Exception:  # noqa: BLE001 - another numba's internals: do not claim a compile
        return True


def message(family: str) -> str:
    seconds = COMPILE_SECONDS.get(family)
    about = f", about {seconds} s" if seconds else ""
    return (f"compiling the {family} kernels, once per installation{about} "
            "(`camtrain warmup` compiles every kernel ahead)")


def announce(family: str, kernels: Iterable) -> bool:
    """Tell the listeners, once per process, that ``family`` will compile; True if it was said."""
    if family in _announced or all(is_cached(k) for k in kernels):
        return False
    _announced.add(family)
    for listener in _listeners:
        listener(message(family))
    return True
