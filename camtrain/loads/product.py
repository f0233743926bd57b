"""The contact-load product: normal cam/follower load of every pair of a valve train."""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from camtrain.components import CLOSING, MAIN


@dataclass(frozen=True)
class ContactLoad:
    """Normal load [N] per angle of the train's pairs and where the cam drives the valve.

    ``load`` is the main (or opening) pair's load, negative where a rigid train loses contact;
    ``closing`` the closing pair's load of a desmodromic train. ``in_contact`` marks the angles
    where the cam drives the valve (off the base circle, clearance taken up); ``model`` names the
    physics that produced the load (several effects may offer it, the plan picks one);
    ``friction`` and ``mu`` are the friction force [N] and coefficient the load was solved with
    (None: no friction/load iteration), ``iterations`` how many passes that took.
    """

    load: np.ndarray
    in_contact: np.ndarray
    model: str
    closing: np.ndarray | None = None
    friction: np.ndarray | None = None
    mu: np.ndarray | None = None
    iterations: int = 1

    @cached_property
    def carried(self) -> np.ndarray:
        """The main pair's load the contact carries, max(W, 0) [N] (0 where a rigid train
        loses contact): formed once for every effect of a sweep batch that reads it."""
        carried = np.maximum(self.load, 0.0)
        carried.flags.writeable = False
        return carried

    def pairs(self) -> tuple[tuple[str, np.ndarray], ...]:
        """(component, load) of each loaded pair, main first."""
        out = ((MAIN, self.load),)
        return out + (((CLOSING, self.closing),) if self.closing is not None else ())

    def contact_intervals(self, theta: np.ndarray) -> list[tuple[float, float]]:
        """[start, end] cam angles [rad] of each run of angles where the cam drives the valve
        and the load is positive (loss of contact splits a run)."""
        on = np.asarray(self.in_contact, dtype=bool) & (np.asarray(self.load) > 0.0)
        return runs(on, np.asarray(theta))


def runs(mask: np.ndarray, theta: np.ndarray) -> list[tuple[float, float]]:
    """Runs of True on a periodic grid; a run across the end of the grid is one run."""
    if not mask.any():
        return []
    if mask.all():
        return [(float(theta[0]), float(theta[-1]))]
    shift = int(np.argmin(mask))  # start the scan on an angle outside every run
    rolled = np.roll(mask, -shift).astype(int)
    edges = np.diff(np.concatenate(([0], rolled, [0])))
    starts, ends = np.nonzero(edges == 1)[0], np.nonzero(edges == -1)[0] - 1
    n = mask.size
    return [(float(theta[(s + shift) % n]), float(theta[(e + shift) % n]))
            for s, e in zip(starts, ends, strict=True)]
