"""A valve landing on its seat at the end of the lash is not a separation: on a train with lash
and no jump the run counts no separation and gives no separation warning, and reports the
landings with the valve's landing speed."""
from __future__ import annotations

import pytest

from camtrain import api
from tests.conftest import DECKS

#: Harrison's train (0.4 mm clearance taken up on 0.5 mm ramps) made elastic, at 1000 rpm: the
#: follower never leaves the cam while the valve is off its seat
_ELASTIC = """
[dynamics]
follower_mass = 0.05
contact_stiffness = 2.0e5
stem_stiffness = 2.0e4
seat_stiffness = 2.0e5
damping_ratio = 0.05
"""


@pytest.fixture(scope="module")
def lash_run():
    text = (DECKS / "harrison_flat.toml").read_text(encoding="utf-8").split("\n[limits]")[0]
    text = text.replace("camshaft = 2500.0", "camshaft = 1000.0")
    assert "valve_clearance = 0.4" in text
    return api.run(api.loads(text + _ELASTIC, "harrison_elastic_1000"))


def test_landing_at_the_end_of_the_lash_is_not_a_separation(lash_run):
    m = lash_run.metrics
    assert m["separations"].value == 0
    assert not [w for w in lash_run.warnings if "separation" in w]
    assert not lash_run.events_of("contact_loss")


def test_landings_are_reported_with_the_landing_speed(lash_run):
    m = lash_run.metrics
    assert m["landings"].value >= 1
    assert len(lash_run.events_of("landing")) == m["landings"].value
    assert m["landing_speed"].unit == "m/s"
    assert 0.0 < m["landing_speed"].value <= m["seat_impact_speed_max"].value


def test_a_jump_is_still_a_separation():
    """The same train at 2500 rpm: the follower leaves the cam with the valve in flight."""
    text = (DECKS / "harrison_flat.toml").read_text(encoding="utf-8").split("\n[limits]")[0]
    result = api.run(api.loads(text + _ELASTIC, "harrison_elastic_2500"))
    assert result.metrics["separations"].value >= 1
    assert any("while the valve is in flight" in w for w in result.warnings)
