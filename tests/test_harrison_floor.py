"""The bare-numpy floor of the benchmarks does the same work as camtrain's Harrison chain: every
column it computes equals camtrain's to 1e-13 (relative to the column's largest value), the
out-of-contact NaNs sit at the same angles, and the cycle-mean power agrees. Without this the
benchmark ratios (docs/performance.md) would compare with less work than the chain does."""
from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import numpy as np
import pytest

from camtrain import api
from camtrain.deck.load import load_deck_text

ROOT = Path(__file__).resolve().parent.parent


def _floor():
    spec = importlib.util.spec_from_file_location("harrison_floor",
                                                  ROOT / "benchmarks" / "harrison_floor.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.harrison_floor


@pytest.mark.parametrize("points", [720, 1440, 3600])
def test_floor_matches_camtrain_columns(points):
    text = re.sub(r"(?m)^angle_points = \d+", f"angle_points = {points}",
                  (ROOT / "decks" / "harrison_flat.toml").read_text())
    result = api.run(load_deck_text(text).model)
    assert result["cam_angle"].size == points
    floor = _floor()(points)
    assert len(floor) >= 17
    for name, values in floor.items():
        if name == "power_loss_mean":
            assert float(values) == pytest.approx(result.metrics[name].value, rel=1e-13)
            continue
        mine = np.asarray(result[name], dtype=float)
        finite = np.isfinite(mine)
        np.testing.assert_array_equal(finite, np.isfinite(values), err_msg=name)
        scale = np.max(np.abs(mine[finite]))
        assert np.max(np.abs(mine[finite] - values[finite])) <= 1e-13 * scale, name
