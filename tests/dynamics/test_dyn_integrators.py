"""The integrators against each other and against the energy balance (reference notes wave2
§1.5 L6, L10): Newmark (default), Teodorescu's central difference and scipy's LSODA agree on a
separating Zeta train; the undamped train's cam work over a revolution equals the change of its
stored energy (to 1e-4 of the peak, falling with the step), the damped cycle absorbs work; the
explicit scheme refuses a step above its limit, naming the element."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

# imported under another name: a module-level function called setup is a nose-style setup
# hook to pytest < 8 (the declared minimum is 7.4)
from camtrain.build.dynamics import setup as dynamic_setup
from camtrain.dynamics import march
from camtrain.dynamics.findings import findings
from camtrain.dynamics.integrators import _start_index
from tests.dynamics.conftest import SINGLE_RATE, deck_of, kinematics_of, zeta_raw

#: just above the first separation of the elastic single-rate Zeta train (1864 rpm)
SEPARATING_RPM = 2000.0


def _run(deck, kin, integrator, refine=1, **overrides):
    omega = SEPARATING_RPM * math.pi / 30 if overrides.pop("separating", True) else None
    s = dynamic_setup(deck, kin, omega=omega,
                      overrides={"integrator": integrator, "cycles_min": 3, "cycles_max": 3,
                                 **overrides})
    return march(s.model, s.cam, s.base, replace(s.settings,
                                                  substeps=s.settings.substeps * refine)), s


@pytest.mark.derived
def test_integrators_agree_on_peak_load_and_separation(zeta_single_rate):
    deck, kin = zeta_single_rate
    out = {}
    for name, refine in (("newmark", 1), ("central_difference", 2), ("lsoda", 1)):
        resp, _ = _run(deck, kin, name, refine)
        flights = [x for x in findings(resp).separations if x.in_flight]
        out[name] = (float(np.max(resp.contact_force[0])), flights[0].loss)
    peak, angle = out["lsoda"]
    for name in ("newmark", "central_difference"):
        assert out[name][0] == pytest.approx(peak, rel=5e-3)
        assert abs(math.degrees(out[name][1] - angle)) < 0.2


def _energy(model, u, v, b):
    """Stored energy [J] of the undamped train: kinetic + springs - preload work + contacts."""
    e = 0.5 * np.sum(model.mass[:, None] * v * v, axis=0)
    e += 0.5 * np.einsum("is,ij,js->s", u, model.stiffness, u) - model.preload @ u
    for j, inp in ((0, b), (1, 0.0 * b)):
        delta = inp - u[model.uni_node[j]] + model.uni_offset[j]
        e += 0.5 * model.uni_k[j] * np.maximum(delta, 0.0) ** 2
    return e


@pytest.mark.derived
def test_undamped_cam_work_equals_the_change_of_stored_energy():
    raw = zeta_raw({"dynamics": {**SINGLE_RATE, "damping_ratio": 0.0, "seat_damping_ratio": 0.0}})
    deck = deck_of(raw)
    kin = kinematics_of(deck)
    errors = []
    for refine in (1, 2):
        resp, s = _run(deck, kin, "newmark", refine, separating=False, cycles_min=1,
                       cycles_max=1)
        model = s.model
        energy = _energy(model, resp.u, resp.v, resp.cam[0])
        start = _energy(model, np.zeros((model.size, 1)), np.zeros((model.size, 1)),
                        np.zeros(1))[0]
        end = energy[_start_index(s.cam.lift)]     # the last sample closes the revolution
        peak = np.max(energy) - start
        errors.append(abs(resp.cam_work - (end - start)) / peak)
    assert errors[0] < 1e-4
    assert errors[1] < errors[0]


@pytest.mark.derived
def test_damped_periodic_cycle_absorbs_cam_work(zeta_single_rate):
    deck, kin = zeta_single_rate
    s = dynamic_setup(deck, kin)
    resp = march(s.model, s.cam, s.base, s.settings)
    assert resp.converged and resp.cam_work > 0.0


def test_central_difference_refuses_a_step_above_its_limit():
    from camtrain import api
    from camtrain.errors import InputError

    raw = zeta_raw({"dynamics": {"integrator": "central_difference", "steps_per_degree": 2.0}})
    with pytest.raises(InputError) as err:
        api.run(deck_of(raw))
    text = str(err.value)
    assert "dynamics.steps_per_degree" in text and "stability limit" in text
    assert "cam contact" in text
