"""The sealed incompressible chamber of the single train (camtrain.dynamics.hla.sealed): its
pressure is the constraint's reaction, restarted consistently at every contact change."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from tests.dynamics.conftest import deck_of, kinematics_of


@pytest.fixture(scope="module")
def zeta_hla():
    """The Zeta train of decks/zeta_intake_hla.toml on the 360-point grid of the coupled
    camshaft's deck."""
    import tomllib

    from camtrain.assemble.dynamics import setup
    from tests.integration_camshaft.test_camshaft_coupled import DECKS

    raw = tomllib.loads((DECKS / "zeta_intake_hla.toml").read_text("utf-8"))
    raw.setdefault("solver", {})["angle_points"] = 360
    deck = deck_of(raw)
    return setup(deck, kinematics_of(deck))


@pytest.mark.derived
def test_sealed_chamber_stays_the_rigid_adjuster_over_many_revolutions(zeta_hla):
    """Incompressible oil, no air, no clearance, a shut check valve: over eight revolutions
    (the followers touch and leave the cam on the base circle, each closing a jump of the
    contact's damper force) the train is the constant-load adjuster's to the integrator's
    tolerance (measured 1e-9 of the peak load), its chamber's pressure does not alternate
    down to the vapour pressure and the plunger never moves. Restarted with the chamber's
    last pressure instead, the pressure's step-to-step alternation grew with every closing,
    reached the vapour pressure in the fourth revolution and the plunger ratcheted out
    (73 % of the peak load by the sixth)."""
    from camtrain.dynamics import march
    from camtrain.dynamics.hla import rigid_adjuster, with_element

    s = zeta_hla
    adj = replace(s.model.series.adjuster, bulk_modulus=math.inf, air_fraction=0.0, radial_clearance=0.0,
                  cracking_pressure=1e9)
    settings = replace(s.settings, cycles_min=8, cycles_max=8)
    sealed = march(with_element(s.model, adj), s.cam, s.base, settings)
    rigid = march(rigid_adjuster(s.model), s.cam, s.base, settings)
    peak = float(np.max(rigid.contact_force))
    assert np.max(np.abs(sealed.contact_force - rigid.contact_force)) < 1e-8 * peak
    assert np.ptp(sealed.hydraulic[3]) < 1e-12
    assert np.min(sealed.hydraulic[0]) > adj.vapour_pressure - 101_325.0
    steps = np.diff(sealed.hydraulic[0])
    assert np.sum(steps[1:] * steps[:-1] < 0.0) < 0.5 * steps.size   # no sample-to-sample sawtooth
