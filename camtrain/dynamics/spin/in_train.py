"""The roller's spin in the single train's Newmark march (:mod:`camtrain.dynamics._kernel`):
the hook points the march calls, each once and guarded by the ``Spin`` record's ``on`` (the
record handed to the march beside ``Train``): the spin's step over every accepted (sub)step
(:func:`.step.spin_step`, at the end state's cam force) and :func:`sample_spin`, the spin's
rows of the march's samples."""
from __future__ import annotations

from numba import njit

from camtrain.dynamics.spin.step import spin_step

__all__ = ["spin_step", "sample_spin"]


@njit(cache=True)
def sample_spin(wr, rows, r):
    """The roller's sample ``r`` into ``rows``: speed [rad/s], sliding speed [m/s], traction
    [N] (``wr``, :data:`camtrain.dynamics.records.TrainState`)."""
    rows[0, r], rows[1, r], rows[2, r] = wr[0], wr[1], wr[2]
