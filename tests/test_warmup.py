"""`camtrain warmup` compiles every family of kernels that announces a compile: each family has
a warm-up case whose deck loads, and every kernel module's announcement names a known family."""
from __future__ import annotations

import re
from pathlib import Path

from click.testing import CliRunner

from camtrain.cli import main
from camtrain.numerics.compile_notice import COMPILE_SECONDS
from camtrain.warmup import CASES

PACKAGE = Path(__file__).resolve().parent.parent / "camtrain"


def _announced() -> dict[str, str]:
    out = {}
    for path in PACKAGE.rglob("*.py"):
        for family in re.findall(r'^announce\("([^"]+)"', path.read_text(), flags=re.M):
            out[family] = path.name
    return out


def test_every_kernel_module_announces_a_known_family():
    announced = _announced()
    assert set(announced) == set(COMPILE_SECONDS), announced
    assert set(announced.values()) <= {"_orbit_march.py", "_kernel.py", "_explicit.py",
                                       "_revolution.py", "_ring_kernel.py", "_balance.py"}


def test_every_family_has_a_warm_up_case_whose_deck_loads():
    assert {case.family for case in CASES} == set(COMPILE_SECONDS)
    for case in CASES:
        assert case.available(), case.name           # a source checkout holds every deck
        assert case.load().model.title


def test_warmup_is_a_command():
    res = CliRunner().invoke(main, ["warmup", "--help"])
    assert res.exit_code == 0 and "once" in res.output
