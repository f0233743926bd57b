"""Per-process caches keyed by the identity of an immutable object (a validated deck model).

A deck model is a frozen dataclass; hashing it walks every field (tens of µs for a full deck),
more than some of what is cached on it costs. Entries here are keyed by ``id`` and hold a weak
reference to the object, so an entry leaves with its object and a new object that happens to get
the same ``id`` never sees a stale entry.
"""
from __future__ import annotations

import functools
import weakref
from collections.abc import Callable
from typing import TypeVar

R = TypeVar("R")


def by_identity(fn: Callable[..., R]) -> Callable[..., R]:
    """Cache ``fn(obj, *args)`` per object identity and hashable ``args``; objects that cannot be
    weakly referenced are not cached."""
    entries: dict[tuple, tuple[weakref.ref, R]] = {}

    @functools.wraps(fn)
    def cached(obj, *args):
        key = (id(obj), *args)
        hit = entries.get(key)
        if hit is not None and hit[0]() is obj:
            return hit[1]
        value = fn(obj, *args)
        try:
            ref = weakref.ref(obj, lambda _, key=key: entries.pop(key, None))
        except TypeError:
            return value
        entries[key] = (ref, value)
        return value

    cached.cache_clear = entries.clear
    return cached
