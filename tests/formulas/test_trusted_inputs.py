"""The formula layer's checks: always on for a direct call (the public entry), skipped only
inside ``trusted_inputs`` (the analysis chain, whose inputs were validated at the deck)."""
from __future__ import annotations

import threading

import numpy as np
import pytest

from camtrain.errors import InputError
from camtrain.formulas import hertz_line
from camtrain.formulas._util import trusted_inputs


def test_direct_call_is_checked_and_names_the_argument():
    with pytest.raises(InputError, match="R"):
        hertz_line(1000.0, -0.01, 2.3e11, L=0.01)


def test_trusted_block_skips_the_checks_and_restores_them():
    checked = hertz_line(1000.0, 0.01, 2.3e11, L=0.01)
    with trusted_inputs(), np.errstate(invalid="ignore"):
        assert hertz_line(1000.0, 0.01, 2.3e11, L=0.01) == checked   # same numbers
        assert np.isnan(hertz_line(-1000.0, 0.01, 2.3e11, L=0.01).half_width)  # not checked
    with pytest.raises(InputError):
        hertz_line(-1000.0, 0.01, 2.3e11, L=0.01)


def test_trust_does_not_leak_into_other_threads():
    errors = []

    def other():
        try:
            hertz_line(1000.0, -0.01, 2.3e11, L=0.01)
        except InputError as exc:
            errors.append(exc)

    with trusted_inputs():
        t = threading.Thread(target=other)
        t.start()
        t.join()
    assert len(errors) == 1
