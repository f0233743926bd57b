"""Ctrl-C and SIGTERM that cannot be lost: a signal during a command is remembered as well as
raised.

Python drops a KeyboardInterrupt raised inside a finalizer or a callback that swallows exceptions
(matplotlib's and PIL's clean-up run such code while a plot is saved), and the command then ends
with exit 0 as if nothing happened. Under :func:`interruptible` the signal also sets a flag;
:func:`raise_if_interrupted` (called before outputs are moved into place, and when the command
ends) raises it again, so an interrupted command never leaves outputs nor exits 0.

SIGTERM (what CI cancellation and `timeout` send) is handled as Ctrl-C: it raises
:class:`Terminated`, so every ``finally`` runs (staging directories and temporary files are
removed, locks released) instead of the process dying where it stands; the CLI exits 143.
"""
from __future__ import annotations

import os
import signal
import threading
from contextlib import contextmanager

_pending = threading.Event()
_pending_terminate = threading.Event()


class Terminated(KeyboardInterrupt):
    """SIGTERM received: handled as Ctrl-C (the command cleans up), exit 143."""


def _raise_for(signum: int):
    if signum == signal.SIGTERM:
        raise Terminated
    raise KeyboardInterrupt


_owner = os.getpid()


def _handler(signum, frame):
    if os.getpid() != _owner:   # a forked child that has not yet reset the handler
        os._exit(128 + signum)
    _pending.set()
    if signum == signal.SIGTERM:
        _pending_terminate.set()
    _raise_for(signum)


@contextmanager
def interruptible():
    """Remember SIGINT and SIGTERM for the duration of the block (main thread only; elsewhere a
    no-op)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    global _owner
    _owner = os.getpid()
    _pending.clear()
    _pending_terminate.clear()
    previous = signal.signal(signal.SIGINT, _handler)
    previous_term = signal.signal(signal.SIGTERM, _handler)
    try:
        yield
        raise_if_interrupted()
    finally:
        signal.signal(signal.SIGINT, previous)
        signal.signal(signal.SIGTERM, previous_term)
        _pending.clear()
        _pending_terminate.clear()


def raise_if_interrupted() -> None:
    """Raise KeyboardInterrupt (:class:`Terminated` after a SIGTERM) if a signal arrived (even one
    that something swallowed)."""
    if _pending.is_set():
        _raise_for(signal.SIGTERM if _pending_terminate.is_set() else signal.SIGINT)


@contextmanager
def terminable():
    """SIGTERM raises :class:`Terminated` in this process for the duration of the block (main
    thread only). A forked child that has not yet reset the handler exits at once instead."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    pid = os.getpid()

    def terminate(signum, frame):
        if os.getpid() != pid:
            os._exit(128 + signum)
        raise Terminated

    previous = signal.signal(signal.SIGTERM, terminate)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)
