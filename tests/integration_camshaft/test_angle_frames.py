"""The camshaft's cycle.csv states its two angle frames: the train's columns at its own lobe's
cam angle, the camshaft's (torque, bearings, shaft) at the shaft angle, on which each lobe's nose
sits at its max_lift_angle; a shaft_angle column opens the camshaft's columns."""
from __future__ import annotations

import json

import numpy as np
from click.testing import CliRunner

from camtrain.cli import main
from tests.conftest import DECKS


def test_camshaft_table_states_its_angle_frames(tmp_path):
    out = tmp_path / "out"
    res = CliRunner().invoke(main, ["run", str(DECKS / "zeta_intake_camshaft.toml"), "--out",
                                    str(out), "--no-plots", "-q"], catch_exceptions=False)
    assert res.exit_code == 0, res.output
    header = (out / "cycle.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    names = [h.split("[")[0] for h in header]
    shaft = names.index("shaft_angle")
    assert header[shaft] == "shaft_angle[deg]"
    assert names.index("load") < shaft < names.index("camshaft_torque")
    assert shaft < min(i for i, n in enumerate(names) if n.startswith("bearing_"))
    columns = json.loads((out / "summary.json").read_text(encoding="utf-8"))["columns"]
    assert "max_lift_angle" in columns["shaft_angle"]["description"]
    assert "own lobe's cam_angle" in columns["shaft_angle"]["description"]
    assert "shaft_angle" in columns["camshaft_torque"]["description"]
    table = np.loadtxt(out / "cycle.csv", delimiter=",", skiprows=1, usecols=(0, shaft))
    np.testing.assert_array_equal(table[:, 0], table[:, 1])   # one grid, two frames
