"""Import only what a deck uses: the flagship deck's whole run loads none of scipy's heavy
subpackages (optimisers, splines, special functions, integrators) nor numba; a lift-table deck
loads the splines it needs."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
HEAVY = ("scipy.optimize", "scipy.special", "scipy.interpolate", "scipy.integrate", "numba",
         "matplotlib", "numpy.ma")
CODE = ("import sys; from camtrain import api; api.run(api.load(sys.argv[1])); "
        f"print(' '.join(m for m in {HEAVY!r} if m in sys.modules))")


def _loaded(deck: str) -> set[str]:
    out = subprocess.run([sys.executable, "-c", CODE, str(ROOT / "decks" / deck)], cwd=ROOT,
                         capture_output=True, text=True, check=True).stdout
    return set(out.split())


def test_harrison_run_imports_no_heavy_package():
    assert _loaded("harrison_flat.toml") == set()


def test_table_deck_imports_the_splines_it_needs():
    assert "scipy.interpolate" in _loaded("zeta_intake.toml")


def test_quiet_run_command_imports_no_terminal_plotting_or_compiler(tmp_path):
    """`camtrain run --no-plots --quiet`: nothing is printed or drawn and nothing marches, so
    the whole command loads neither rich, matplotlib, numba nor scipy's heavy subpackages."""
    code = ("import sys, runpy; sys.argv = ['camtrain', 'run', sys.argv[1], '--no-plots', "
            "'--quiet', '--out', sys.argv[2]]\n"
            "try:\n    runpy.run_module('camtrain.cli', run_name='__main__')\n"
            "except SystemExit as exc:\n    assert not exc.code, exc.code\n"
            f"print(' '.join(m for m in {HEAVY + ('rich',)!r} if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code, str(ROOT / "decks" / "harrison_flat.toml"),
                          str(tmp_path / "out")], cwd=ROOT, capture_output=True, text=True,
                         check=True).stdout
    assert set(out.split()) == set()
    assert (tmp_path / "out" / "summary.json").is_file()


def test_run_report_into_a_pipe_imports_no_terminal_library(tmp_path):
    """`camtrain run --no-plots` writing its report into a pipe: the same tables as rich would
    print there (tests/report/test_boxes.py), drawn without importing rich."""
    code = ("import sys, runpy; sys.argv = ['camtrain', 'run', sys.argv[1], '--no-plots', "
            "'--out', sys.argv[2]]\n"
            "try:\n    runpy.run_module('camtrain.cli', run_name='__main__')\n"
            "except SystemExit as exc:\n    assert not exc.code, exc.code\n"
            "print('rich' in sys.modules, file=sys.stderr)")
    env = {k: v for k, v in os.environ.items() if k not in ("FORCE_COLOR", "TTY_COMPATIBLE")}
    res = subprocess.run([sys.executable, "-c", code, str(ROOT / "decks" / "harrison_flat.toml"),
                          str(tmp_path / "out")], cwd=ROOT, capture_output=True, text=True,
                         check=True, env=env)
    assert "key results" in res.stdout and "┏" in res.stdout
    assert res.stderr.strip().splitlines()[-1] == "False"
