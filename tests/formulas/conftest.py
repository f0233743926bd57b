"""Helpers for the formula-layer tests.

Tolerance policy: a published or hand-computed number printed to d decimals is matched to half a
unit of its last printed digit (``printed`` fixture); closed-form identities are matched to
1e-10 or tighter.
"""
from __future__ import annotations

from decimal import Decimal

import numpy as np
import pytest


def _assert_printed(value, printed: str, scale: float = 1.0) -> None:
    """Assert that value * scale rounds to the printed string (half a unit of its last digit)."""
    exponent = Decimal(printed).as_tuple().exponent
    half_ulp = 0.5 * 10.0 ** exponent
    got = float(value) * scale
    # 1e-9 relative slack only absorbs binary rounding of values sitting exactly on a half unit
    assert abs(got - float(printed)) <= half_ulp * (1 + 1e-9), (
        f"{got!r} does not round to the printed {printed} (tolerance {half_ulp})")


@pytest.fixture
def printed():
    return _assert_printed


@pytest.fixture
def raise_all():
    """Turn every floating-point warning (overflow, underflow, 0/0, x/0) into an exception."""
    with np.errstate(all="raise"):
        yield
