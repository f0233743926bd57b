"""Shared helpers of the dynamics tests: the shipped Zeta dynamics deck with fields changed, and
its kinematics."""
from __future__ import annotations

import copy
import tomllib

import pytest

from tests.conftest import DECKS

ZETA_DYNAMICS = DECKS / "zeta_intake_dynamics.toml"


def zeta_raw(changes: dict | None = None) -> dict:
    """The Zeta dynamics deck as a TOML dictionary, ``changes`` = {section: {field: value}}
    (a value None removes the field)."""
    raw = tomllib.loads(ZETA_DYNAMICS.read_text())
    raw = copy.deepcopy(raw)
    for section, fields in (changes or {}).items():
        target = raw.setdefault(section, {})
        for key, value in fields.items():
            if value is None:
                target.pop(key, None)
            else:
                target[key] = value
    return raw


def deck_of(raw: dict):
    from camtrain.deck.load import validate

    return validate(raw, "zeta_intake_dynamics")


def kinematics_of(deck):
    from camtrain.assemble.lift_law import build_lift_law
    from camtrain.assemble.mechanism import kinematics
    from camtrain.lift import angle_grid

    curve = build_lift_law(deck.lift).evaluate(angle_grid(deck.solver.angle_points))
    return kinematics(deck, curve)[0]


def assert_integrators_agree(deck, kin, rpm: float, cycles: int) -> None:
    """Newmark, central difference (at half the step) and LSODA march the same train ``cycles``
    revolutions from rest at ``rpm``: peak cam load within 0.5 %, first separation within 0.2 deg
    of LSODA's (reference notes wave2 §1.5 L10)."""
    import math
    from dataclasses import replace

    import numpy as np

    # imported under another name: a module-level function called setup is a nose-style setup
    # hook to pytest < 8 (the declared minimum is 7.4)
    from camtrain.assemble.dynamics import setup as dynamic_setup
    from camtrain.dynamics import march
    from camtrain.dynamics.findings import findings

    out = {}
    for name, refine in (("newmark", 1), ("central_difference", 2), ("lsoda", 1)):
        s = dynamic_setup(deck, kin, omega=rpm * math.pi / 30,
                          overrides={"integrator": name, "cycles_min": cycles,
                                     "cycles_max": cycles})
        resp = march(s.model, s.cam, s.base,
                     replace(s.settings, substeps=s.settings.substeps * refine))
        flights = [x for x in findings(resp).separations if x.in_flight]
        out[name] = (float(np.max(resp.contact_force[0])), flights[0].loss)
    peak, angle = out["lsoda"]
    for name in ("newmark", "central_difference"):
        assert out[name][0] == pytest.approx(peak, rel=5e-3)
        assert abs(math.degrees(out[name][1] - angle)) < 0.2


#: the stiff-limit train: single-rate spring without damping (the rigid train has neither
#: surge nor spring damping), every other element as the deck
SINGLE_RATE = {"spring_elements": 0, "spring_mass": None, "spring_damping_ratio": 0.0}


@pytest.fixture(scope="session")
def zeta_single_rate():
    deck = deck_of(zeta_raw({"dynamics": SINGLE_RATE}))
    return deck, kinematics_of(deck)
