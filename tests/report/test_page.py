"""A sheet drawn on a page that already carried other sheets is the sheet drawn on a fresh page:
the reused panel axes keep nothing of the panels drawn on them before."""
from __future__ import annotations

import matplotlib
import numpy as np
import pytest

from camtrain.report.page import Page
from camtrain.report.sheets import SHEETS, _ctx, _sheet
from camtrain.report.style import A4_PORTRAIT, RC
from tests.report.conftest import synthetic


def _pixels(page: Page, result, name: str) -> np.ndarray:
    _sheet(page, result, None, name, _ctx(result), "0" * 64)
    page.fig.canvas.draw()
    return np.asarray(page.fig.canvas.buffer_rgba()).copy()


@pytest.mark.parametrize("name", ["kinematics", "contact", "friction", "profile"])
def test_sheet_on_a_used_page_equals_the_sheet_on_a_fresh_page(name):
    result = synthetic(240)
    with matplotlib.rc_context(RC):
        fresh = _pixels(Page(A4_PORTRAIT), result, name)
        used = Page(A4_PORTRAIT)
        for other in SHEETS:        # every other sheet first, the profile and twins included
            if other != name:
                _pixels(used, result, other)
        again = _pixels(used, result, name)
    assert np.array_equal(fresh, again)
