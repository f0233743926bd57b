"""Decks written back as TOML (tomli-w): api.save_deck / api.to_toml round-trip every shipped
deck and template of every kind, in deck units; a sweep writes each case's deck on request."""
from __future__ import annotations

import dataclasses
import tomllib

import pytest
from click.testing import CliRunner

from camtrain import api
from camtrain.cli import MECHANISM_CHOICES
from camtrain.cli_sweep import sweep as sweep_command
from camtrain.deck.load import validate
from camtrain.deck.templates import render_template
from tests.conftest import DECKS

SHIPPED = sorted(p.name for p in DECKS.glob("*.toml"))


@pytest.mark.parametrize("name", SHIPPED + [f"template:{m}" for m in MECHANISM_CHOICES])
def test_round_trip_gives_an_equal_deck(name, tmp_path):
    if name.startswith("template:"):
        loaded = api.loads(render_template(name.split(":")[1]), name)
    else:
        loaded = api.load(DECKS / name)
    path = api.save_deck(loaded, tmp_path / "again.toml")
    again = api.load(path)
    assert again.model == loaded.model


def test_written_in_deck_units_and_a_python_change_survives(tmp_path):
    loaded = api.load(DECKS / "harrison_flat.toml")
    deck = loaded.model
    deck = dataclasses.replace(deck, cam=dataclasses.replace(deck.cam, base_radius=0.0195))
    raw = tomllib.loads(api.to_toml(deck))
    assert raw["cam"]["base_radius"] == 19.5            # mm, as the deck writes it
    assert raw["speed"]["camshaft"] == 2500.0           # rpm, not rad/s
    assert raw["lubricant"]["pressure_viscosity"] == 22.0   # 1/GPa, not 2.2e-08
    assert api.load(api.save_deck(deck, tmp_path / "d.toml")).model == deck


def test_inline_table_angles_go_back_in_their_unit():
    text = (DECKS / "harrison_flat.toml").read_text(encoding="utf-8")
    raw = tomllib.loads(text)
    angles = [-60.0, -45.0, -30.0, -15.0, 0.0, 15.0, 30.0, 45.0, 60.0]
    raw["lift"] = {"form": "table", "table": {
        "angles": angles, "lifts": [0.0, 1.0, 4.0, 8.0, 9.0, 8.0, 4.0, 1.0, 0.0]}}
    model = validate(raw, "t")
    again = tomllib.loads(api.to_toml(model))
    assert again["lift"]["table"]["angles"] == angles
    assert validate(again, "t") == model


def test_sweep_writes_each_case_deck(tmp_path):
    deck = tmp_path / "flat.toml"
    deck.write_text((DECKS / "harrison_flat.toml").read_text(encoding="utf-8")
                    .replace("angle_points = 720", "angle_points = 120"), encoding="utf-8")
    res = CliRunner().invoke(sweep_command, [str(deck), "-p", "base_radius", "--values", "17,19",
                                             "--out", str(tmp_path / "o"), "-q", "--no-plots",
                                             "-j", "1", "--write-decks"])
    assert res.exit_code == 0, res.output
    written = sorted((tmp_path / "o" / "decks").glob("case_*.toml"))
    assert [p.name for p in written] == ["case_00000.toml", "case_00001.toml"]
    second = api.load(written[1])
    assert second.model.cam.base_radius == pytest.approx(0.019, rel=1e-12)
    assert "base_radius = 19 mm" in written[1].read_text(encoding="utf-8").splitlines()[0]
