"""The cam contact as a Hertz line contact (contact_model = "hertz_line"; reference notes wave2
§1.1 A-M2, the line-contact approach of Johnson 1985): the relation itself, the compiled
march's contact force against it, the stiff limit back to the rigid train, the integrators'
agreement, and the deck's checks."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from camtrain.assemble.dynamics import rigid_load
from camtrain.assemble.dynamics import setup as dynamic_setup
from camtrain.dynamics import march
from camtrain.dynamics.contact_law import (
    HertzLineLaw,
    line_contact_approach,
    line_contact_compliance,
)
from camtrain.errors import InputError
from tests.dynamics.conftest import (
    SINGLE_RATE,
    assert_integrators_agree,
    deck_of,
    kinematics_of,
    zeta_raw,
)

HERTZ = {"contact_model": "hertz_line", "contact_stiffness": None}
#: Zeta cam and follower (Yang 1992 App C): compliances (1 - nu^2)/E, cam width, dome radius
C_CAM, C_FOLLOWER = (1 - 0.28 ** 2) / 170e9, (1 - 0.29 ** 2) / 204e9


@pytest.mark.derived
def test_line_contact_approach_of_equal_bodies_and_its_derivative():
    """Two bodies of one material: delta = w/(pi E*) (ln(4R1/b) + ln(4R2/b) - 1) with
    1/E* = 2 c; the compliance is the derivative of the approach (b grows as sqrt(w))."""
    c, r1, r2, w = 4.4e-12, 0.02, 8.0, 4.5e4
    e_star = 1 / (2 * c)
    r = r1 * r2 / (r1 + r2)
    b = math.sqrt(4 * w * r / (math.pi * e_star))
    expected = w / (math.pi * e_star) * (math.log(4 * r1 / b) + math.log(4 * r2 / b) - 1)
    assert line_contact_approach(w, r1, r2, c, c) == pytest.approx(expected, rel=1e-14)
    h = w * 1e-6
    numeric = (line_contact_approach(w + h, r1, r2, c, c)
               - line_contact_approach(w - h, r1, r2, c, c)) / (2 * h)
    assert line_contact_compliance(w, r1, r2, c, c) == pytest.approx(numeric, rel=1e-8)


@pytest.mark.derived
def test_hertz_law_inverts_and_stiffens_with_the_load():
    law = HertzLineLaw(C_CAM, C_FOLLOWER, 0.011, 8.0, k_series=5e8)
    loads = np.array([1.0, 20.0, 100.0, 500.0, 1000.0])
    k = [law.stiffness(f, 0.02, 1.3) for f in loads]
    assert np.all(np.diff(k) > 0)                       # softest where it opens and closes
    for f in loads:
        assert law.force(law.deflection(f, 0.02, 1.3), 0.02, 1.3) == pytest.approx(f, rel=1e-12)
    # the Zeta contact at 500 N: 2.1e8 N/m, the order the shipped linear deck assumes (2e8)
    bare = HertzLineLaw(C_CAM, C_FOLLOWER, 0.011, 8.0)
    assert bare.stiffness(500.0, 0.02) == pytest.approx(2.09e8, rel=0.01)


@pytest.fixture(scope="module")
def zeta_hertz():
    deck = deck_of(zeta_raw({"dynamics": {**SINGLE_RATE, **HERTZ}}))
    return deck, kinematics_of(deck)


def test_compiled_contact_force_is_the_hertz_law(zeta_hertz):
    """Undamped contact: every sampled cam force of the Newmark march equals the law at the
    sampled compression, radius and load ratio (the compiled Newton against the Python one)."""
    deck, kin = zeta_hertz
    s = dynamic_setup(deck, kin, overrides={"cycles_max": 2})
    model = replace(s.model, uni_c=np.zeros(2))
    resp = march(model, s.cam, s.base, s.settings)
    law = model.cam_law
    delta = resp.cam[0] - resp.u[model.follower] + model.uni_offset[0]
    closed = resp.contact_force[0] > 0
    expected = [law.force(d, r, q) for d, r, q in zip(delta[closed], kin.cam_radius[closed],
                                                      kin.rocker_ratio[closed], strict=True)]
    np.testing.assert_allclose(resp.contact_force[0][closed], expected, rtol=1e-9)
    assert closed.sum() > 0.5 * closed.size


@pytest.mark.derived
def test_stiff_hertz_train_carries_the_rigid_load(zeta_hertz):
    """Compliances / 1e3 (and the other elements x 1e3): the rigid load within 0.5 % of its
    peak outside 2 deg of the contact edges, as the linear contact (test_dyn_limits.py)."""
    from tests.dynamics.test_dyn_limits import _edges_excluded

    deck, kin = zeta_hertz
    s = dynamic_setup(deck, kin, stiffness_scale=1e3)
    resp = march(s.model, s.cam, s.base, s.settings)
    assert resp.converged
    dyn = resp.contact_force[0] * kin.rocker_ratio
    rigid = rigid_load(deck, kin)
    keep = _edges_excluded(kin)
    assert np.max(np.abs(dyn - rigid)[keep]) / np.max(rigid) < 5e-3


@pytest.mark.derived
def test_integrators_agree_with_the_hertz_contact(zeta_hertz):
    """Newmark, central difference and LSODA on the separating Hertz train (2000 rpm): peak
    load within 0.5 %, first separation within 0.2 deg (reference notes L10), two revolutions
    from rest (the same transient for all three)."""
    deck, kin = zeta_hertz
    assert_integrators_agree(deck, kin, rpm=2000.0, cycles=2)


@pytest.mark.parametrize(("changes", "field"), [
    ({"contact_stiffness": None}, "dynamics.contact_stiffness"),             # linear needs it
    ({"contact_model": "hertz_line"}, "dynamics.contact_stiffness"),         # hertz: not used
])
def test_contact_model_input_is_checked(changes, field):
    with pytest.raises(InputError) as err:
        deck_of(zeta_raw({"dynamics": changes}))
    assert field in str(err.value) and err.value.exit_code == 2


def test_hertz_line_refused_for_a_flat_follower_and_the_coupled_camshaft():
    import tomllib

    from camtrain import api
    from tests.conftest import DECKS

    raw = zeta_raw({"dynamics": HERTZ})
    raw["mechanism"] = {"type": "flat"}
    raw["cam"].pop("taper_angle")
    with pytest.raises(InputError) as err:
        api.run(deck_of(raw))
    assert "dynamics.contact_model" in str(err.value) and "flat" in str(err.value)
    coupled = tomllib.loads((DECKS / "zeta_intake_camshaft_coupled.toml").read_text())
    coupled["dynamics"].update(contact_model="hertz_line")
    coupled["dynamics"].pop("contact_stiffness")
    with pytest.raises(InputError) as err:
        deck_of(coupled)
    assert "dynamics.contact_model" in str(err.value) and "coupled" in str(err.value)
