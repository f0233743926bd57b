"""What a designer reads from a periodic response: separations of the cam contact (with their
number and shortest dwell, so chattering cannot hide), seat impacts and their speeds."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camtrain.dynamics.integrators import TrainResponse


@dataclass(frozen=True)
class Separation:
    """The cam contact open from ``loss`` to ``regained`` [rad] during the lift event (``dwell``
    [rad] the angle between), ``speed`` [m/s] the closing speed at re-contact; ``in_flight``:
    the valve was off its seat when the cam lost the follower (a jump, the elastic counterpart
    of the rigid train's bounce), not a rebound of the valve landing on its seat."""

    loss: float
    regained: float
    dwell: float
    speed: float
    in_flight: bool = True


@dataclass(frozen=True)
class Findings:
    """Separations during the lift event, seat impacts (angle [rad], valve speed [m/s]) and the
    number of contact changes on the base circle (a zero-lash follower touching its cam)."""

    separations: tuple[Separation, ...]
    seat_impacts: tuple[tuple[float, float], ...]
    base_circle_changes: int


def _on_lift(response: TrainResponse, angle: float) -> bool:
    lift = response_cam_lift(response, angle)
    return lift > 0.0


def response_cam_lift(response: TrainResponse, angle: float) -> float:
    """Cam input (valve-referred lift) at a cam angle [m], from the response's grid values."""
    theta = response.theta
    i = int(np.argmin(np.abs(np.angle(np.exp(1j * (theta - angle))))))
    neighbours = response.cam[0][[(i - 1) % theta.size, i, (i + 1) % theta.size]]
    return float(np.max(neighbours))


def findings(response: TrainResponse) -> Findings:
    """Pair each contact loss with the next re-contact (periodic), list seat impacts."""
    # the revolution starts at rest in the middle of the dwell; the valve is in flight from its
    # first lift off the seat to its first landing (later lifts are rebounds)
    phase = "seated"
    base = 0
    seps = []
    pending = None
    flight = False
    for e in response.events:
        if e.kind == "seat_lift" and phase == "seated":
            phase = "flight"
        elif e.kind == "seat_impact" and phase == "flight":
            phase = "landed"
        if e.kind in ("seat_lift", "seat_impact"):
            continue
        if not _on_lift(response, e.angle):
            base += 1
            continue
        if e.kind == "contact_loss":
            pending, flight = e, phase == "flight"
        elif pending is not None:
            dwell = (e.angle - pending.angle) % (2.0 * math.pi)
            seps.append(Separation(pending.angle, e.angle, dwell, e.speed, flight))
            pending = None
    if pending is not None:  # regained after the end of the revolution: wrap to the first one
        firsts = [e for e in response.events if e.kind == "contact_regained"
                  and _on_lift(response, e.angle)]
        if firsts:
            e = firsts[0]
            seps.append(Separation(pending.angle, e.angle,
                                   (e.angle - pending.angle) % (2.0 * math.pi), e.speed, flight))
    impacts = tuple((e.angle, abs(e.speed)) for e in response.events if e.kind == "seat_impact")
    return Findings(tuple(seps), impacts, base)
