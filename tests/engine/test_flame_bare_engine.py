"""FLAME on a bare engine deck (no [[cylinders]]; correlations.cylinders counts them) with a
valve train included: the total is the valve train's plus accessories, and the fmep divides
it by the swept volume of the cylinders the correlations count (no division by zero)."""
from __future__ import annotations

import math
import shutil

from click.testing import CliRunner

from camtrain import api
from camtrain.cli import main
from tests.conftest import DECKS

VALVE_TRAIN = ('\n[[flame.valve_trains]]\nname = "intake camshaft"\n'
               'deck = "zeta_intake_camshaft.toml"\n')


def _bare_with_valve_train(tmp_path):
    shutil.copy(DECKS / "zeta_intake_camshaft.toml", tmp_path)
    deck = tmp_path / "bare_flame.toml"
    deck.write_text((DECKS / "zeta_bare_engine.toml").read_text() + VALVE_TRAIN)
    return deck


def test_the_fmep_of_a_bare_engine_uses_the_cylinders_the_correlations_count(tmp_path):
    r = api.run(api.load(_bare_with_valve_train(tmp_path)))
    total = r.metrics["flame_total"].value
    assert total > 0.0 and r.metrics["flame_valve_train"].value > 0.0
    # hand: 4 cylinders x pi/4 x bore 80.6 mm^2 x stroke 88.0 mm; 3000 rpm, 4-stroke
    swept = 4 * math.pi / 4.0 * 0.0806 ** 2 * 0.088
    fmep = total * 2.0 / (swept * 3000.0 / 60.0)
    assert math.isclose(r.metrics["fmep"].value, fmep, rel_tol=1e-12)


def test_the_cli_runs_it_without_a_traceback(tmp_path):
    res = CliRunner().invoke(main, ["run", str(_bare_with_valve_train(tmp_path)), "--out",
                                    str(tmp_path / "out"), "--plots", "none"])
    assert res.exit_code == 0, res.output
    assert "Traceback" not in res.output and "internal error" not in res.output
    assert "fmep" in res.output
