"""The drive's speed oscillation (Williams 2013 App A6, eq. A6.5) in the coupled march: every
lobe turns with the drive's angle plus its twist (camshaft.flexibility.speed_amplitude,
speed_order), so on a stiff shaft each train is the single train under the same oscillation at
the lobe's phase of it (docs/camshaft_dynamics.md)."""
from __future__ import annotations

import numpy as np
import pytest

from camtrain import api
from camtrain.camshaft import shift_curve
from camtrain.deck.load import validate
from camtrain.errors import InputError
from tests.integration_camshaft.test_camshaft_coupled import DECKS, coupled_raw

AMPLITUDE = 50.0   # rpm, at twice the camshaft speed


@pytest.fixture(scope="module", params=["monolithic", "staggered"])
def oscillating(request):
    raw = coupled_raw(1e3, solver=request.param)
    raw["camshaft"]["flexibility"].update(speed_amplitude=AMPLITUDE, speed_order=2)
    model = validate(raw, "coupled", DECKS)
    single = coupled_raw(1e3, coupling="one_way")
    single.pop("camshaft")
    single["dynamics"].update(speed_oscillation=AMPLITUDE, speed_oscillation_order=2)
    return model, api.run(model), api.run(validate(single, "single", DECKS))["load"]


@pytest.mark.derived
def test_stiff_shaft_lobes_follow_the_single_train_under_the_same_oscillation(oscillating):
    """Stiff shaft (x 1000), speed 1500 +- 50 rpm at order 2: the lobes at 0 and 180 deg see the
    oscillation at the phase the single train does (the phase is tied to the cam angle), and
    match it within 0.5 % of its peak at every angle (the issue's stiff-shaft tolerance;
    measured 0.40-0.43 % at 360 angles, 0.32 % at 1440, against 0.19-0.25 % at constant speed:
    the two marches' steps fall at other cam angles once the speed oscillates, and their
    samples are carried onto the grid angles from other points); the lobes at 90 and 270 deg
    see it in opposite phase and differ by more than 5 % (measured 20.6 %): the oscillation
    reaches every train, at its own phase."""
    model, r, single = oscillating
    assert r.metrics["coupling_change"].value <= 1e-4
    peak = float(np.max(single))
    for j, lobe in enumerate(model.camshaft.lobes):
        gap = np.max(np.abs(r.component(f"lobe_{j + 1}")["load"]
                            - shift_curve(single, lobe.max_lift_angle))) / peak
        in_phase = round(np.degrees(lobe.max_lift_angle)) % 180 == 0
        assert (gap < 5e-3) if in_phase else (gap > 5e-2), (j, gap)


def test_the_single_trains_oscillation_is_tied_to_the_cam_angle():
    """The single train's oscillation keeps its phase against the cam angle wherever its march
    starts (camtrain.dynamics.excitation.TimeBase.starting_at): two starts half a revolution
    apart, order 2, give the same angle law."""
    from camtrain.dynamics.excitation import TimeBase

    base = TimeBase(157.0, 5.0, 2)
    t = np.linspace(0.0, base.period, 50)
    first = -np.pi
    a = base.starting_at(first, first)
    b = base.starting_at(first + 0.5 * np.pi, first)   # a quarter turn later: half an order-2 cycle
    # at the same mean angle theta_m the speeds agree
    speed_a = a.angle(t + 0.5 * np.pi / 157.0)[1]
    speed_b = b.angle(t)[1]
    assert np.allclose(speed_a, speed_b, rtol=0, atol=1e-12)


def test_two_way_coupling_takes_the_oscillation_from_the_drive():
    raw = coupled_raw(1.0, solver="monolithic")
    raw["dynamics"].update(speed_oscillation=AMPLITUDE)
    with pytest.raises(InputError, match="dynamics.speed_oscillation"):
        validate(raw, "coupled", DECKS)
    raw = coupled_raw(1.0, solver="waveform")
    raw["camshaft"]["flexibility"]["speed_amplitude"] = AMPLITUDE
    with pytest.raises(InputError, match="coupling_solver"):
        validate(raw, "coupled", DECKS)
