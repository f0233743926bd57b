"""Dense linear algebra on one BLAS thread, where threads cost more CPU than they save.

The elastic film's Newton steps factor matrices of a few hundred to a thousand rows many times a
second. OpenBLAS spreads each factorisation over every core and spins its threads between calls;
at these sizes the spinning and the hand-over cost more CPU than the parallel work saves (steady
line contact on 1,024 points: 0.148 s of CPU on two threads, 0.078 s on one, same result), and a
sweep or a sensitivity study already keeps every core busy with its own cases. The solvers that
factor small dense matrices in a loop therefore run inside :func:`one_blas_thread`: the elastic
film's and the lift design's (its quadratic programmes, through scipy's LAPACK).

The thread pools are found and limited with threadpoolctl (the library scikit-learn and joblib use
for this; it knows OpenBLAS, MKL and BLIS), not by environment variables, which only act before
numpy is loaded. scipy carries an OpenBLAS of its own beside numpy's, and threadpoolctl limits only
the libraries loaded when its controller is made, so scipy's linear algebra is loaded first.
"""
from __future__ import annotations

from contextlib import contextmanager
from functools import lru_cache


@lru_cache(maxsize=1)
def _controller():
    import scipy.linalg  # noqa: F401  (scipy's own OpenBLAS loaded, so that it is limited too)
    from threadpoolctl import ThreadpoolController

    return ThreadpoolController()


@contextmanager
def one_blas_thread():
    """Limit every loaded BLAS library to one thread inside the block (restored after it)."""
    with _controller().limit(limits=1, user_api="blas"):
        yield


__all__ = ["one_blas_thread"]
