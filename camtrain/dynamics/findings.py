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
    [rad] the angle between), ``speed`` [m/s] the closing speed at re-contact."""

    loss: float
    regained: float
    dwell: float
    speed: float


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
    cam_events = [e for e in response.events if e.kind in ("contact_loss", "contact_regained")]
    on_lift = [e for e in cam_events if _on_lift(response, e.angle)]
    base = len(cam_events) - len(on_lift)
    seps = []
    pending = None
    for e in on_lift:
        if e.kind == "contact_loss":
            pending = e
        elif pending is not None:
            dwell = (e.angle - pending.angle) % (2.0 * math.pi)
            seps.append(Separation(pending.angle, e.angle, dwell, e.speed))
            pending = None
    if pending is not None:  # regained after the end of the revolution: wrap to the first one
        firsts = [e for e in on_lift if e.kind == "contact_regained"]
        if firsts:
            e = firsts[0]
            seps.append(Separation(pending.angle, e.angle,
                                   (e.angle - pending.angle) % (2.0 * math.pi), e.speed))
    impacts = tuple((e.angle, abs(e.speed)) for e in response.events if e.kind == "seat_impact")
    return Findings(tuple(seps), impacts, base)
