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
from camtrain.assemble.dynamics import setup as dynamic_setup
from camtrain.dynamics import march
from camtrain.dynamics.integrators import _start_index
from tests.dynamics.conftest import (
    SINGLE_RATE,
    assert_integrators_agree,
    deck_of,
    kinematics_of,
    zeta_raw,
)

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
    assert_integrators_agree(deck, kin, rpm=SEPARATING_RPM, cycles=3)


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


THETA0 = 1.0
PER_PERIOD = (5, 10, 20, 40, 80, 160)


def _harmonic_cam(lift, grid=360):
    """Cam input of the lift b = lift/2 (1 - cos theta) on a grid (exact derivatives)."""
    from camtrain.dynamics import CamInput

    th = np.arange(grid) * 2 * math.pi / grid
    return CamInput(th, 0.5 * lift * (1 - np.cos(th)), 0.5 * lift * np.sin(th),
                    0.5 * lift * np.cos(th))


@pytest.mark.derived
def test_undamped_periodic_cycle_cam_work_vanishes_and_falls_with_the_step():
    """Reference notes L6 on a faithful periodic cycle. An undamped train never settles, so the
    march starts from the exact periodic state of the linear single-mass train under the cam
    b = h/2 (1 - cos w t), in closed form: u = U0 + U1 cos w t, U1 = -k_c h/2 / (K - m w^2),
    K = k_c + k_s (contact and stem in series, plus the spring). The cam contact stays closed and
    the seat open, so the train is linear and no free vibration is excited. Over one revolution
    the cam work is zero exactly; Newmark's is below 1e-4 of the peak stored energy (6e-8
    at 5 steps per period of the train's mode) and falls with the step (order 1.8)."""
    from camtrain.dynamics import CAM, TimeBase, assemble_train
    from camtrain.dynamics.integrators import revolution_from

    m, k_s, f0, lift = 0.1, 4e4, 200.0, 8e-3
    model = assemble_train(valve_mass=m, contact_stiffness=2e8, links={"stem": 5e7},
                           seat_stiffness=1e8, spring_rate=k_s, spring_preload=f0,
                           damping_ratio=0.0, spring_damping_ratio=0.0)
    model = replace(model, uni_offset=np.array([model.uni_offset[CAM], -1.0]))  # seat far away
    k_c, off = model.uni_k[CAM], model.uni_offset[CAM]
    big_k = k_c + k_s
    base = TimeBase(1500.0 * math.pi / 30)
    w = base.omega
    u0 = (k_c * (0.5 * lift + off) - f0) / big_k
    u1 = -k_c * 0.5 * lift / (big_k - m * w * w)
    cam = _harmonic_cam(lift)
    t_n = 2 * math.pi / math.sqrt(big_k / m)
    ratios = []
    for per_period in PER_PERIOD:
        sub = math.ceil(base.period / (t_n / per_period) / cam.theta.size)
        # started off the symmetry axis of the cam (the trapezoid is time-reversible: from
        # theta = 0 its error would cancel by symmetry)
        u, v, a, f, events, work = revolution_from(
            model, cam, base, sub, [u0 + u1 * math.cos(THETA0)], [-u1 * w * math.sin(THETA0)],
            [True, False], theta0=THETA0)
        assert not events and np.all(f[CAM] > 0)
        b = cam.evaluate(THETA0 + w * (np.arange(1, cam.theta.size + 1) * base.period
                                       / cam.theta.size))[0]
        stored = (0.5 * m * v[0] ** 2 + 0.5 * k_c * (b - u[0] + off) ** 2
                  + 0.5 * k_s * (u[0] + f0 / k_s) ** 2)
        ratios.append(abs(work) / np.max(stored))
    # 5.8e-8 at 5 steps per period of the train's mode ... 1.1e-10 at 160, fitted order 1.8
    assert ratios[0] < 1e-4
    assert np.all(np.diff(ratios) < 0)
    order = -np.polyfit(np.log(PER_PERIOD), np.log(ratios), 1)[0]
    assert order > 1.5
