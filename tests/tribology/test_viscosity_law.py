"""The pressure-viscosity law of the friction integral is a deck option (tribology.viscosity_law).

Barus (Ball 1988, Yang 1992) is the default; Roelands (1966), with z matched to the deck's alpha
at ambient pressure, gives a lower viscosity at Hertz pressures and so never more viscous
friction: the power loss cannot rise, and where the boundary cap is active nothing changes."""
from __future__ import annotations

import tomllib

import numpy as np
import tomli_w

from camtrain import api
from tests.conftest import DECKS


def _run(name: str, law: str):
    raw = tomllib.loads((DECKS / name).read_text())
    raw.setdefault("tribology", {})["viscosity_law"] = law
    with np.errstate(all="raise"):
        return api.run(api.loads(tomli_w.dumps(raw)))


def test_roelands_lowers_viscous_friction_line_and_point_contacts():
    for name in ("rover_2300_rocker.toml", "zeta_intake.toml"):
        barus, roel = _run(name, "barus"), _run(name, "roelands")
        fb, fr = barus["friction_force"], roel["friction_force"]
        assert np.all(np.isfinite(fr))
        assert np.all(fr <= fb * (1 + 1e-9) + 1e-12), name
        assert roel.metrics["power_loss_mean"].value < barus.metrics["power_loss_mean"].value
