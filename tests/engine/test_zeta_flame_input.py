"""Input errors of the piston and FLAME sections of an engine deck: each names the deck field,
the value and what was expected (exit 2, no traceback)."""
from __future__ import annotations

import subprocess
import sys

import pytest

from camtrain.errors import InputError
from tests.conftest import ROOT
from tests.engine.test_zeta_flame import ZETA, _raw, zeta


def _problem(**changes) -> str:
    with pytest.raises(InputError) as exc:
        zeta(**changes)
    return str(exc.value)


def test_one_compression_ring_is_refused():
    ring = _raw()["piston"]["rings"][0]
    assert "piston.rings" in _problem(piston__rings=[ring])


def test_groove_temperatures_need_one_value_per_speed():
    rings = [dict(r) for r in _raw()["piston"]["rings"]]
    rings[1]["groove_temperatures"] = [160.0]
    text = _problem(piston__rings=rings)
    assert "piston.rings[1].groove_temperatures" in text and "one per speed" in text


def test_separations_match_the_ring_count():
    assert "piston.gas.separations" in _problem(piston__gas__separations=[4.0, 4.0])


def test_skirt_positions_must_span_the_skirt():
    skirt = {"height": 30.0, "depth": 30.0, "positions": [0.0, 20.0], "clearances": [20.0, 20.0]}
    assert "piston.skirt.positions" in _problem(piston__skirt=skirt)


def test_vogel_law_needs_three_points():
    assert "piston.oil.temperatures" in _problem(piston__oil__law="vogel")


def test_offset_out_of_range_names_the_field():
    rings = [dict(r) for r in _raw()["piston"]["rings"]]
    rings[0]["offset"] = 1.5
    assert "piston.rings[0].offset" in _problem(piston__rings=rings)


def test_missing_valve_train_deck_names_the_include():
    vts = [{"name": "intake", "deck": "no_such_deck.toml"}]
    text = _problem(flame__valve_trains=vts)
    assert "flame.valve_trains[0].deck" in text and "file not found" in text


def test_an_included_deck_must_be_a_valve_train():
    vts = [{"name": "crank", "deck": "zeta_crank_bearings.toml"}]
    assert "is not a valve-train deck" in _problem(flame__valve_trains=vts)


def test_cli_exit_2_without_traceback(tmp_path):
    text = ZETA.read_text(encoding="utf-8").replace('deck = "zeta_intake_camshaft.toml"',
                                                    'deck = "missing.toml"')
    bad = tmp_path / "zeta_bad.toml"
    bad.write_text(text, encoding="utf-8")
    out = subprocess.run([sys.executable, "-m", "camtrain.cli", "check", str(bad)],
                         capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 2
    assert "flame.valve_trains[0].deck" in out.stderr + out.stdout
    assert "Traceback" not in out.stderr
