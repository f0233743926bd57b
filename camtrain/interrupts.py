"""Ctrl-C that cannot be lost: a SIGINT during a command is remembered as well as raised.

Python drops a KeyboardInterrupt raised inside a finalizer or a callback that swallows exceptions
(matplotlib's and PIL's clean-up run such code while a plot is saved), and the command then ends
with exit 0 as if nothing happened. Under :func:`interruptible` the signal also sets a flag;
:func:`raise_if_interrupted` (called before outputs are moved into place, and when the command
ends) raises it again, so an interrupted command never leaves outputs nor exits 0.
"""
from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

_pending = threading.Event()


def _handler(signum, frame):
    _pending.set()
    raise KeyboardInterrupt


@contextmanager
def interruptible():
    """Remember SIGINT for the duration of the block (main thread only; elsewhere a no-op)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    _pending.clear()
    previous = signal.signal(signal.SIGINT, _handler)
    try:
        yield
        raise_if_interrupted()
    finally:
        signal.signal(signal.SIGINT, previous)
        _pending.clear()


def raise_if_interrupted() -> None:
    """Raise KeyboardInterrupt if a SIGINT arrived (even one that something swallowed)."""
    if _pending.is_set():
        raise KeyboardInterrupt
