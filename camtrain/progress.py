"""What a long effect is doing right now (a bearing, a ring-pack pass, an included deck), for
whoever shows progress: a plain module that imports nothing of camtrain, so any layer may tell
it. A no-op unless a listener is set (the runner sets one when it is given a progress callback).
"""
from __future__ import annotations

from collections.abc import Callable
from contextlib import contextmanager
from contextvars import ContextVar

_listener: ContextVar[Callable[[str], None] | None] = ContextVar("camtrain_progress",
                                                                 default=None)


@contextmanager
def listening(callback: Callable[[str], None]):
    """Send every :func:`detail` told inside the block to ``callback``."""
    token = _listener.set(callback)
    try:
        yield
    finally:
        _listener.reset(token)


def detail(text: str) -> None:
    """Tell the listener (if any) what runs now, e.g. "main 3 of 5"."""
    callback = _listener.get()
    if callback is not None:
        callback(text)
