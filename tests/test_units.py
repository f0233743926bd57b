"""Units at the boundary: every deck unit converts to SI by the right factor."""
from __future__ import annotations

import math
import tomllib

import pytest
import tomli_w

from camtrain import api
from camtrain.units import UNITS, from_si, to_si
from tests.conftest import DECKS

EXPECTED = {
    "mm": 1e-3, "µm": 1e-6, "deg": math.pi / 180, "rpm": 2 * math.pi / 60, "N/mm": 1e3,
    "N/mm²": 1e6, "N/mm³": 1e9, "GPa": 1e9, "MPa": 1e6, "1/GPa": 1e-9, "Pa·s": 1.0,
    "kg·m²": 1.0, "mm/deg": 1e-3 / (math.pi / 180), "mm/deg²": 1e-3 / (math.pi / 180) ** 2,
}


@pytest.mark.parametrize("unit,factor", sorted(EXPECTED.items()))
def test_unit_factor(unit, factor):
    assert to_si(1.0, unit) == pytest.approx(factor, rel=1e-15)
    assert from_si(to_si(3.7, unit), unit) == pytest.approx(3.7, rel=1e-15)


def test_every_unit_has_a_positive_factor():
    assert all(f > 0 for f, _ in UNITS.values())


def test_progressive_spring_term_through_the_deck():
    """c2 = 0.5 N/mm² adds c2 x² to the valve force: at the angle of the largest load of the
    Harrison deck, x = l_v + delta; the load rises by exactly that (flat follower, W = F_v)."""
    raw = tomllib.loads((DECKS / "harrison_flat.toml").read_text())
    raw["effects"] = ["loads"]
    base = api.run(api.loads(tomli_w.dumps(raw)))
    raw["spring"]["progressive_quadratic"] = 0.5
    stiff = api.run(api.loads(tomli_w.dumps(raw)))
    x = base["valve_lift"] + 6.4e-3
    extra = 0.5e6 * x**2
    in_contact = base["load"] > 0
    assert stiff["load"][in_contact] == pytest.approx((base["load"] + extra)[in_contact],
                                                      rel=1e-9)
