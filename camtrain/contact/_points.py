"""Selecting a contact parameter at the angles a formula runs on.

A contact parameter (viscosity, modulus, cam width, boundary coefficient) is one number per run;
a sweep that runs many cases as one batch gives it one value per case, shaped to broadcast
against the (cases, angles) arrays. The laws evaluate formulas only on the angles that carry
load (``x[use]``), so such a parameter is selected at the same points; a plain number passes
through unchanged.
"""
from __future__ import annotations

import numpy as np


def at(value, use):
    """``value`` at the points ``use`` (a boolean mask over the field's shape) when it is an
    array of parameters, else ``value`` itself."""
    if type(value) is float or np.ndim(value) == 0:   # a plain number: the single run's case
        return value
    return np.broadcast_to(value, np.shape(use))[use]
